#include "sfm_pruning/report/view_graph_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "sfm_pruning/report/graph_layout.hpp"
#include "sfm_pruning/report/palette.hpp"
#include "sfm_pruning/report/removal_summary.hpp"
#include "sfm_pruning/report/svg_builder.hpp"

namespace sfm_pruning {
namespace {

// Above this many edges the per-edge tooltips would bloat the page; nodes keep theirs.
constexpr size_t kMaxEdgeTooltips = 4000;
// Spring strength of a kept edge between two subgraphs relative to one inside a subgraph.
constexpr double kBetweenSubgraphPull = 0.05;

std::map<IndexT, size_t> IndexOfView(const RunViewGraph& graph) {
  std::map<IndexT, size_t> index;
  for (size_t k = 0; k < graph.views.size(); ++k) index[graph.views[k].view_id] = k;
  return index;
}

std::string EdgeTooltip(const RunViewGraph& graph, const RunGraphEdge& edge, size_t a, size_t b) {
  std::string text = graph.views[a].image + " - " + graph.views[b].image + ": " + std::to_string(edge.inliers) +
                     " inliers";
  if (edge.removed) {
    text += "; removed because " + RemovalReasonInWords(edge.reason) + " (" +
            MeasureValueInWords(edge.reason, edge.measure, edge.value) + ", bound " +
            MeasureValueInWords(edge.reason, edge.measure, edge.threshold) + ")";
  }
  return text;
}

std::string BundleTooltip(const SubgraphPairRemovals& pair) {
  return "subgraph " + std::to_string(pair.a + 1) + " - subgraph " + std::to_string(pair.b + 1) + ": " +
         std::to_string(pair.removed) + " edges removed, " + std::to_string(pair.kept) + " kept; " +
         (pair.main.edges == pair.removed ? "all" : std::to_string(pair.main.edges)) + " because " +
         RemovalReasonInWords(pair.main.reason) + " (" + GroupMeasureInWords(pair.main) + ")";
}

// Subgraph pair of a removed edge whose ends lie in two different accepted subgraphs, else nullopt.
std::optional<std::pair<int, int>> BundledPair(const RunViewGraph& graph, const std::map<IndexT, size_t>& index,
                                               const RunGraphEdge& edge) {
  const int a = graph.views[index.at(edge.i)].subgraph, b = graph.views[index.at(edge.j)].subgraph;
  if (!edge.removed || a < 0 || b < 0 || a == b) return std::nullopt;
  return std::make_pair(std::min(a, b), std::max(a, b));
}

}  // namespace

std::vector<Eigen::Vector2d> LayoutRunViewGraph(const RunViewGraph& graph, uint64_t seed) {
  const std::map<IndexT, size_t> index = IndexOfView(graph);
  std::vector<LayoutEdge> springs;
  for (const RunGraphEdge& edge : graph.edges) {
    if (edge.removed) continue;
    // Kept edges between subgraphs pull weakly, so each subgraph forms its own cluster.
    const int sa = graph.views[index.at(edge.i)].subgraph, sb = graph.views[index.at(edge.j)].subgraph;
    const double between = graph.num_subgraphs > 0 && sa != sb ? kBetweenSubgraphPull : 1.0;
    springs.push_back({index.at(edge.i), index.at(edge.j), between * std::log1p(static_cast<double>(edge.inliers))});
  }
  GraphLayoutOptions options;
  options.seed = seed;
  return ForceDirectedLayout(graph.views.size(), springs, options);
}

std::string DrawViewGraphSvg(const RunViewGraph& graph, const std::vector<Eigen::Vector2d>& layout,
                             ViewGraphPanel panel, double size) {
  const std::map<IndexT, size_t> index = IndexOfView(graph);
  const double margin = 14.0;
  const auto at = [&](size_t k) -> Eigen::Vector2d {
    return Eigen::Vector2d(margin, margin) + layout[k] * (size - 2.0 * margin);
  };
  size_t max_inliers = 1;
  for (const RunGraphEdge& edge : graph.edges) max_inliers = std::max(max_inliers, edge.inliers);
  const bool tooltips = graph.edges.size() <= kMaxEdgeTooltips;
  // Thinner, fainter edges in dense graphs so the structure stays readable.
  const double density = std::clamp(14.0 / std::sqrt(static_cast<double>(graph.edges.size()) + 1.0), 0.25, 1.0);

  SvgBuilder svg(size, size);
  svg.Rect(0, 0, size, size, "fill=\"#fbfbfc\" stroke=\"#d9dde3\"");
  const auto draw_edge = [&](const RunGraphEdge& edge, const std::string& color, double opacity_scale,
                             const std::string& extra) {
    const size_t a = index.at(edge.i), b = index.at(edge.j);
    const double strength = std::log1p(static_cast<double>(edge.inliers)) / std::log1p(static_cast<double>(max_inliers));
    const double width = (0.5 + 1.5 * strength) * (0.5 + 0.5 * density);
    const double opacity = std::clamp((0.15 + 0.6 * strength) * density * opacity_scale, 0.04, 0.9);
    svg.Line(at(a), at(b),
             "stroke=\"" + color + "\" stroke-width=\"" + FormatNumber(width, 2) + "\" stroke-opacity=\"" +
                 FormatNumber(opacity, 2) + "\"" + extra,
             tooltips ? EdgeTooltip(graph, edge, a, b) : "");
  };

  if (panel == ViewGraphPanel::kBeforePruning) {
    svg.BeginGroup("class=\"edges\"");
    for (const RunGraphEdge& edge : graph.edges) draw_edge(edge, report_colors::kKept.Hex(), 1.0, "");
    svg.EndGroup();
  } else {
    svg.BeginGroup("class=\"edges kept-edges\"");
    for (const RunGraphEdge& edge : graph.edges) {
      if (edge.removed) continue;
      const int sa = graph.views[index.at(edge.i)].subgraph, sb = graph.views[index.at(edge.j)].subgraph;
      const bool inside = sa >= 0 && sa == sb;
      draw_edge(edge, inside ? SubgraphColor(sa).Hex() : report_colors::kKept.Hex(), inside ? 1.3 : 0.6, "");
    }
    svg.EndGroup();
    // Removed edges between two subgraphs: one bundle per subgraph pair, from the mean position of
    // its ends in one subgraph to that in the other, as wide as the log of its count. Others alone.
    svg.BeginGroup("class=\"edges removed-edges\"");
    struct Bundle {
      Eigen::Vector2d end_a = Eigen::Vector2d::Zero(), end_b = Eigen::Vector2d::Zero();
      size_t count = 0;
    };
    std::map<std::pair<int, int>, Bundle> bundles;
    for (const RunGraphEdge& edge : graph.edges) {
      if (!edge.removed) continue;
      const std::optional<std::pair<int, int>> pair = BundledPair(graph, index, edge);
      if (!pair) {
        draw_edge(edge, report_colors::kRemoved.Hex(), 0.9, " stroke-dasharray=\"4 3\"");
        continue;
      }
      size_t a = index.at(edge.i), b = index.at(edge.j);
      if (graph.views[a].subgraph != pair->first) std::swap(a, b);
      Bundle& bundle = bundles[*pair];
      bundle.end_a += at(a);
      bundle.end_b += at(b);
      ++bundle.count;
    }
    std::map<std::pair<int, int>, std::string> tooltip_of;
    for (const SubgraphPairRemovals& pair : SummariseRemovals(graph).pairs) {
      tooltip_of[{pair.a, pair.b}] = BundleTooltip(pair);
    }
    for (const auto& [pair, bundle] : bundles) {
      const double n = static_cast<double>(bundle.count);
      const double width = 1.0 + 1.2 * std::log2(n);
      svg.Line(bundle.end_a / n, bundle.end_b / n,
               "stroke=\"" + report_colors::kRemoved.Hex() + "\" stroke-width=\"" + FormatNumber(width, 2) +
                   "\" stroke-opacity=\"0.55\" stroke-linecap=\"round\" stroke-dasharray=\"6 4\"",
               tooltip_of[pair]);
    }
    svg.EndGroup();
  }

  const double radius = std::clamp(70.0 / std::sqrt(static_cast<double>(graph.views.size()) + 1.0), 2.0, 7.0);
  svg.BeginGroup("class=\"nodes\" stroke=\"#ffffff\" stroke-width=\"1\"");
  for (size_t k = 0; k < graph.views.size(); ++k) {
    const RunGraphView& view = graph.views[k];
    std::string tooltip = view.image + " (view " + std::to_string(view.view_id) + ")";
    if (view.subgraph >= 0) tooltip += ", subgraph " + std::to_string(view.subgraph + 1);
    svg.Circle(at(k), radius, "fill=\"" + SubgraphColor(view.subgraph).Hex() + "\"", tooltip);
  }
  svg.EndGroup();
  const std::string label = panel == ViewGraphPanel::kBeforePruning ? "view graph before pruning"
                                                                    : "view graph after pruning";
  return svg.Finish("graph", label);
}

}  // namespace sfm_pruning
