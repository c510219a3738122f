#include "sfm_pruning/report/html_report.hpp"

#include <algorithm>
#include <filesystem>
#include <map>

#include "sfm_pruning/eval/model_evaluation.hpp"
#include "sfm_pruning/report/data_uri.hpp"
#include "sfm_pruning/report/epipolar_check.hpp"
#include "sfm_pruning/report/epipolar_image.hpp"
#include "sfm_pruning/report/html_style.hpp"
#include "sfm_pruning/report/palette.hpp"
#include "sfm_pruning/report/removal_summary.hpp"
#include "sfm_pruning/report/svg_builder.hpp"
#include "sfm_pruning/report/timings_drawing.hpp"
#include "sfm_pruning/report/top_view.hpp"
#include "sfm_pruning/report/view_graph_drawing.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

struct RunPage {
  const RunFolder* run = nullptr;
  std::string label;
  std::optional<EvaluationReport> evaluation;
  std::map<IndexT, int> subgraph_of;  // view id -> accepted subgraph
};

std::string RunLabel(const RunFolder& run) {
  const std::string folder = run.path.filename().empty() ? run.path.parent_path().filename().string()
                                                         : run.path.filename().string();
  return run.engine.empty() ? folder : run.engine;
}

std::string Tag(const std::string& text, const Rgb& color) {
  return "<span class=\"tag\" style=\"background:" + color.Hex() + "\">" + EscapeXml(text) + "</span>";
}

std::string Card(const std::string& key, const std::string& value, const std::string& small = "",
                 const std::string& value_class = "v") {
  return "<div class=\"card\"><div class=\"k\">" + EscapeXml(key) + "</div><div class=\"" + value_class + "\">" + EscapeXml(value) +
         (small.empty() ? "" : " <small>" + EscapeXml(small) + "</small>") + "</div></div>\n";
}

std::string Section(const std::string& id, const std::string& title, const std::string& note,
                    const std::string& body) {
  return "<section id=\"" + id + "\"><h2>" + EscapeXml(title) + "</h2>" + (note.empty() ? "" : "<p class=\"note\">" + note + "</p>") +
         "\n" + body + "</section>\n";
}

// One column per run, each headed by the run's tag.
std::string Columns(const std::vector<RunPage>& pages, const std::vector<std::string>& bodies) {
  std::string html = "<div class=\"cols\">\n";
  for (size_t r = 0; r < pages.size(); ++r) {
    html += "<div class=\"col\">" +
            (pages.size() > 1 ? "<h3>" + Tag(pages[r].label, RunColor(r)) + " " +
                                    EscapeXml(pages[r].run->path.string()) + "</h3>"
                              : std::string()) +
            bodies[r] + "</div>\n";
  }
  return html + "</div>\n";
}

size_t NumRegistered(const SfmData& model) { return model.PosedViewIds().size(); }

double TotalSeconds(const RunFolder& run) {
  double total = 0.0;
  for (const StageSeconds& stage : run.stages) total += stage.seconds;
  return total;
}

std::string SummarySection(const std::vector<RunPage>& pages) {
  std::vector<std::string> bodies;
  for (const RunPage& page : pages) {
    const RunFolder& run = *page.run;
    std::string cards = "<div class=\"cards\">\n";
    cards += Card("engine", run.engine.empty() ? "unknown" : run.engine, "", "v text");
    cards += Card("registered views", std::to_string(NumRegistered(run.model)), "of " + std::to_string(run.model.views.size()));
    cards += Card("3D points", std::to_string(run.model.structure.size()));
    // Accuracy first: the cards of two runs line up where it matters.
    if (page.evaluation) {
      for (const AucAtThreshold& auc : page.evaluation->auc) {
        cards += Card("AUC@" + FormatNumber(auc.threshold_deg, 1) + "\u00b0", FormatNumber(auc.auc_percent, 1), "%");
      }
      if (page.evaluation->alignment) {
        cards += Card("median rotation error", FormatNumber(page.evaluation->alignment->median_rotation_error_deg, 3), "\u00b0");
      }
    }
    if (run.final_rms_px >= 0.0) cards += Card("reprojection RMS", FormatNumber(run.final_rms_px, 3), "px");
    if (!run.stages.empty()) cards += Card("wall time", FormatNumber(TotalSeconds(run), 2), "s");
    if (run.view_graph) {
      cards += Card("view-graph edges", std::to_string(run.view_graph->edges.size() - run.view_graph->NumRemovedEdges()),
                    run.view_graph->NumRemovedEdges() > 0
                        ? "of " + std::to_string(run.view_graph->edges.size()) + ", " +
                              std::to_string(run.view_graph->NumRemovedEdges()) + " pruned"
                        : "");
    }
    if (run.pruning) cards += Card("subgraphs", std::to_string(run.pruning->subgraphs.size()));
    bodies.push_back(cards + "</div>\n");
  }
  const std::string note = pages.front().evaluation
                               ? "AUC of the pairwise relative-pose error over all ground-truth image pairs "
                                 "(docs/evaluation.md); unregistered images count as failures."
                               : "No ground truth given (<code>--ground_truth</code>): no accuracy figures.";
  return Section("summary", "Summary", note, Columns(pages, bodies));
}

std::string GraphLegend(const RunViewGraph& graph, const RunFolder& run, bool after) {
  std::string html = "<div class=\"legend\">";
  std::map<int, size_t> sizes;
  for (const RunGraphView& view : graph.views) ++sizes[view.subgraph];
  for (const auto& [subgraph, size] : sizes) {
    if (subgraph < 0 && graph.num_subgraphs == 0) continue;
    std::string name = subgraph < 0 ? "outside the partition" : "subgraph " + std::to_string(subgraph + 1);
    if (run.pruning && subgraph >= 0 && static_cast<size_t>(subgraph) < run.pruning->subgraphs.size()) {
      name += " (" + run.pruning->subgraphs[static_cast<size_t>(subgraph)].status + ")";
    }
    html += "<span><span class=\"swatch\" style=\"background:" + SubgraphColor(subgraph).Hex() + "\"></span>" +
            EscapeXml(name) + ": " + std::to_string(size) + " views</span>";
  }
  if (after) {
    html += "<span><span class=\"line\" style=\"border-color:" + report_colors::kKept.Hex() +
            "\"></span>kept edge between subgraphs</span>";
    html += "<span><span class=\"line dashed\" style=\"border-color:" + report_colors::kRemoved.Hex() +
            "\"></span>removed edge (" + std::to_string(graph.NumRemovedEdges()) + ")</span>";
  }
  return html + "</div>\n";
}

// At most this many subgraph pairs are listed by name; the rest are counted.
constexpr size_t kMaxListedSubgraphPairs = 12;

// The removals in plain words: one line per reason with its count, subgraph pairs and measure,
// then the subgraph pairs that lost the most edges.
std::string RemovalSummaryHtml(const RunViewGraph& graph) {
  const RemovalSummary summary = SummariseRemovals(graph);
  if (summary.removed == 0) return "<p>The pruning removed no edge.</p>\n";
  std::string html = "<p><b>The pruning removed " + std::to_string(summary.removed) + " of " +
                     std::to_string(summary.edges) + " verified edges.</b></p>\n<table class=\"removals\">"
                     "<tr><th>edges</th><th>removed because</th><th>subgraph pairs</th><th>measured</th></tr>\n";
  for (const RemovalGroup& group : summary.groups) {
    html += "<tr><td>" + std::to_string(group.edges) + "</td><td>" + EscapeXml(RemovalReasonInWords(group.reason)) +
            " <small><code>" + EscapeXml(group.reason) + "</code></small></td><td>" +
            std::to_string(group.subgraph_pairs) + "</td><td>" + EscapeXml(GroupMeasureInWords(group)) + "</td></tr>\n";
  }
  html += "</table>\n<table class=\"removals\"><tr><th>subgraph pair</th><th>removed</th><th>kept</th>"
          "<th>most removed because</th></tr>\n";
  for (size_t k = 0; k < summary.pairs.size() && k < kMaxListedSubgraphPairs; ++k) {
    const SubgraphPairRemovals& pair = summary.pairs[k];
    const std::string name = pair.a < 0 ? "outside the partition"
                                        : std::to_string(pair.a + 1) + " - " + std::to_string(pair.b + 1);
    html += "<tr><td>" + name + "</td><td>" + std::to_string(pair.removed) + "</td><td>" + std::to_string(pair.kept) +
            "</td><td>" + EscapeXml(RemovalReasonInWords(pair.main.reason) + " (" + GroupMeasureInWords(pair.main) + ")") +
            "</td></tr>\n";
  }
  html += "</table>\n";
  if (summary.pairs.size() > kMaxListedSubgraphPairs) {
    html += "<p class=\"note\">and " + std::to_string(summary.pairs.size() - kMaxListedSubgraphPairs) +
            " more subgraph pairs with removed edges (view_graph.json lists every edge).</p>\n";
  }
  return html;
}

std::string GraphSection(const std::vector<RunPage>& pages, uint64_t seed) {
  // The run that pruned (its graph before pruning is the other runs' graph too).
  const RunPage* page = nullptr;
  for (const RunPage& candidate : pages) {
    if (candidate.run->view_graph && candidate.run->view_graph->num_subgraphs > 0) {
      page = &candidate;
      break;
    }
  }
  if (page == nullptr) {
    for (const RunPage& candidate : pages) {
      if (candidate.run->view_graph) {
        page = &candidate;
        break;
      }
    }
  }
  if (page == nullptr) {
    return Section("graph", "View graph", "Not recorded: the run folders have no view_graph.json (written by "
                                 "<code>prunesfm run</code> since the report exists).", "");
  }
  const RunViewGraph& graph = *page->run->view_graph;
  const std::vector<Eigen::Vector2d> layout = LayoutRunViewGraph(graph, seed);
  const std::string before = DrawViewGraphSvg(graph, layout, ViewGraphPanel::kBeforePruning);
  const std::string title_before = "<h3>Before pruning: " + std::to_string(graph.views.size()) + " views, " +
                                   std::to_string(graph.edges.size()) + " verified edges</h3>";
  if (graph.num_subgraphs == 0) {
    return Section("graph", "View graph",
                   "Verified edges of " + EscapeXml(page->label) +
                       " (no pruning in this engine). Layout: seeded force-directed, edge width and opacity "
                       "grow with the inlier count.",
                   "<div class=\"cols\"><div class=\"col\">" + title_before + before + "</div></div>\n");
  }
  const std::string after = DrawViewGraphSvg(graph, layout, ViewGraphPanel::kAfterPruning);
  const size_t removed = graph.NumRemovedEdges();
  const std::string title_after = "<h3>After pruning: " + std::to_string(graph.edges.size() - removed) +
                                  " edges kept, " + std::to_string(removed) + " removed</h3>";
  const std::string toggle =
      "<label class=\"toggle\"><input type=\"checkbox\" id=\"show-removed\" checked> show removed edges</label>";
  return Section("graph", "View graph before and after pruning",
                 "Nodes are views coloured by the accepted subgraph of the recursive partition (" +
                     EscapeXml(page->label) +
                     "); both panels share one seeded force-directed layout of the pruned graph, so subgraphs "
                     "form clusters. The removed edges between two subgraphs show as one dashed red bundle per "
                     "pair of subgraphs, as wide as the log of its count. Hover for image names, inliers and "
                     "the measured error of each cut. " + toggle,
                 RemovalSummaryHtml(graph) + "<div class=\"cols\"><div class=\"col\">" + title_before + before + GraphLegend(graph, *page->run, false) +
                     "</div><div class=\"col\">" + title_after + after + GraphLegend(graph, *page->run, true) +
                     "</div></div>\n");
}

TopViewScene MakeTopViewScene(const RunPage& page, const SfmData* truth) {
  const SfmData& model = page.run->model;
  // Identity without ground truth (a plain value: GCC 12 mistakes an optional of Eigen members
  // for uninitialised).
  const bool aligned = page.evaluation && page.evaluation->alignment;
  const Similarity3 to_truth = aligned ? page.evaluation->alignment->transform : Similarity3();
  std::map<std::string, Eigen::Vector3d> true_centers;
  if (truth != nullptr && aligned) {
    for (const auto& [id, view] : truth->views) {
      if (truth->IsPosed(view)) true_centers[fs::path(view.filename).filename().string()] = truth->PoseOf(view).center;
    }
  }
  std::vector<std::pair<std::string, IndexT>> ordered;
  for (IndexT id : model.PosedViewIds()) ordered.emplace_back(model.views.at(id).RelativeImagePath(), id);
  std::sort(ordered.begin(), ordered.end());
  TopViewScene scene;
  for (const auto& [name, id] : ordered) {
    TopViewCamera camera;
    camera.label = name;
    const Pose& pose = model.PoseOf(model.views.at(id));
    camera.pose = to_truth.Apply(pose);
    const auto subgraph = page.subgraph_of.find(id);
    camera.color = subgraph == page.subgraph_of.end() ? report_colors::kCamera : SubgraphColor(subgraph->second);
    const auto true_center = true_centers.find(fs::path(name).filename().string());
    if (true_center != true_centers.end()) camera.true_center = true_center->second;
    scene.cameras.push_back(camera);
  }
  for (const auto& [id, landmark] : model.structure) {
    const bool uncoloured = landmark.color[0] == landmark.color[1] && landmark.color[1] == landmark.color[2] &&
                            landmark.color[0] == 128;
    scene.points.push_back({to_truth.Apply(landmark.X),
                            uncoloured ? report_colors::kPoint
                                       : Rgb{landmark.color[0], landmark.color[1], landmark.color[2]}});
  }
  return scene;
}

std::string TopViewSection(const std::vector<RunPage>& pages, const SfmData* truth) {
  std::vector<std::string> bodies;
  for (const RunPage& page : pages) {
    const TopViewScene scene = MakeTopViewScene(page, truth);
    bodies.push_back(DrawTopViewSvg(scene, TopViewFrameOf(scene)));
  }
  const bool aligned = pages.front().evaluation && pages.front().evaluation->alignment;
  std::string legend = "<div class=\"legend\"><span><span class=\"swatch\" style=\"background:" +
                       report_colors::kCamera.Hex() +
                       "\"></span>camera (coloured by subgraph when pruned), pointing along its view</span>";
  if (aligned) {
    legend += "<span><span class=\"swatch\" style=\"border:2px solid " + report_colors::kTruth.Hex() +
              ";background:none\"></span>true camera centre, joined to its estimate</span>";
  }
  legend += "<span><span class=\"line\" style=\"border-color:#333a45\"></span>trajectory in image-name order</span></div>\n";
  const std::string note =
      aligned ? "Seen from above (the plane of the camera centres, else the cameras' mean up vector), after the "
                "evaluation's robust similarity alignment to the ground truth: each camera is joined to its true "
                "centre, so a folded reconstruction shows long chords across the scene."
              : "Seen from above (the plane of the camera centres, else the cameras' mean up vector), in the "
                "reconstruction's own frame; points clipped to the central 96 %.";
  return Section("topview", "Cameras and points (top view)", note, Columns(pages, bodies) + legend);
}

bool IsRegistered(const SfmData& model, const std::string& image) {
  for (const auto& [id, view] : model.views) {
    if (view.RelativeImagePath() == image) return model.IsPosed(view);
  }
  return false;
}

// The images each check draws lines in. Without ground truth: those that see the region most.
// With it, among the 4 x max_other_views that see it most, those where some run's matched
// feature lies farthest from the true epipolar line come first: a fold (the twin of the point
// matched in its place) shows there, not in the neighbours that agree.
std::vector<std::string> ChooseOtherImages(const std::vector<RunPage>& pages, const EpipolarRequest& request,
                                           const EpipolarCheckOptions& options, const SfmData* truth) {
  const SfmData& first = pages.front().run->model;
  if (truth == nullptr) return ImagesSeeingRegion(first, request.image, request.point, options);
  EpipolarCheckOptions wide = options;
  wide.max_other_views = 4 * options.max_other_views;
  std::vector<std::pair<double, std::string>> scored;
  for (const std::string& candidate : ImagesSeeingRegion(first, request.image, request.point, wide)) {
    double miss = 0.0;
    for (const RunPage& page : pages) {
      if (!IsRegistered(page.run->model, request.image) || !IsRegistered(page.run->model, candidate)) continue;
      const EpipolarCheck check =
          ComputeEpipolarCheck(page.run->model, request.image, request.point, {candidate}, truth, options);
      const EpipolarPanel& panel = check.others.front();
      if (panel.matched_feature && !panel.truth.empty()) {
        miss = std::max(miss, std::min(1e6, DistanceToCurve(panel.truth, *panel.matched_feature)));
      }
    }
    scored.emplace_back(miss, candidate);
  }
  // Stable: equal misses keep the region order.
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::string> images;
  for (size_t k = 0; k < std::min(options.max_other_views, scored.size()); ++k) images.push_back(scored[k].second);
  std::sort(images.begin(), images.end());
  return images;
}

std::string EpipolarSection(const std::vector<RunPage>& pages, const HtmlReportInput& input) {
  const SfmData& first = pages.front().run->model;
  std::vector<EpipolarRequest> requests = input.checks;
  if (requests.empty()) {
    for (const std::string& image : ChooseCheckImages(first, input.num_auto_checks)) {
      requests.push_back({image, ChooseCheckPoint(first, image)});
    }
  }
  EpipolarCheckOptions options;
  options.max_other_views = input.max_other_views;
  const SfmData* truth = input.ground_truth ? &*input.ground_truth : nullptr;
  EpipolarImageOptions image_options;
  image_options.images_dir = input.images_dir;
  image_options.panel_height = 300;
  std::string body;
  for (const EpipolarRequest& request : requests) {
    const std::vector<std::string> others = ChooseOtherImages(pages, request, options, truth);
    body += "<div class=\"check\"><h3>" + EscapeXml(request.image) + " at (" + FormatNumber(request.point.x(), 1) +
            ", " + FormatNumber(request.point.y(), 1) + ")</h3>\n";
    std::vector<std::string> bodies;
    for (const RunPage& page : pages) {
      if (!IsRegistered(page.run->model, request.image)) {
        bodies.push_back("<p class=\"note\">" + EscapeXml(request.image) + " is not registered in this run.</p>");
        continue;
      }
      const EpipolarCheck check =
          ComputeEpipolarCheck(page.run->model, request.image, request.point, others, truth, options);
      const std::vector<uint8_t> jpeg = RenderEpipolarCheck(check, page.run->model, image_options, ".jpg");
      bodies.push_back("<img alt=\"epipolar check of " + EscapeXml(request.image) + "\" src=\"" +
                       DataUri("image/jpeg", jpeg) + "\">");
    }
    // Checks are wide (four images): runs go under each other, not side by side.
    for (size_t r = 0; r < pages.size(); ++r) {
      if (pages.size() > 1) body += "<div>" + Tag(pages[r].label, RunColor(r)) + "</div>";
      body += bodies[r] + "\n";
    }
    body += "</div>\n";
  }
  std::string legend = "<div class=\"legend\"><span><span class=\"swatch\" style=\"background:" +
                       report_colors::kRemoved.Hex() + "\"></span>the point in the reference image</span>"
                       "<span><span class=\"line\" style=\"border-color:" + report_colors::kRemoved.Hex() +
                       "\"></span>its epipolar line under the estimated poses</span>";
  if (truth != nullptr) {
    legend += "<span><span class=\"line dashed\" style=\"border-color:" + report_colors::kTruth.Hex() +
              "\"></span>under the true poses</span>";
  }
  legend += "<span><span class=\"swatch\" style=\"background:#fff;border:2px solid #000\"></span>the feature matched "
            "to the point (its track)</span></div>\n";
  const std::string note =
      "The paper's check: a point in one image and its epipolar lines in the images that see the same region. In a "
      "consistent reconstruction each line passes through the point's true correspondence" +
      std::string(truth != nullptr ? " and coincides with the dashed true line" : "") +
      "." + (input.images_dir ? "" : " Without <code>--images</code> each image is drawn as its observed features.");
  return Section("epipolar", "Epipolar checks", note, legend + body);
}

std::string TimingsSection(const std::vector<RunPage>& pages) {
  std::vector<TimedRun> runs;
  for (const RunPage& page : pages) {
    if (!page.run->stages.empty()) runs.push_back({page.label, page.run->stages});
  }
  if (runs.empty()) return Section("timings", "Timings", "No timings.json in the run folders.", "");
  std::string legend;
  if (runs.size() > 1) {
    legend = "<div class=\"legend\">";
    for (size_t r = 0; r < runs.size(); ++r) {
      legend += "<span><span class=\"swatch\" style=\"background:" + RunColor(r).Hex() + "\"></span>" +
                EscapeXml(runs[r].label) + "</span>";
    }
    legend += "</div>\n";
  }
  return Section("timings", "Timings", "Wall time per stage from timings.json (single run, shared machine).",
                 DrawTimingsSvg(runs) + legend);
}

std::string SubgraphSection(const std::vector<RunPage>& pages) {
  for (const RunPage& page : pages) {
    if (!page.run->pruning) continue;
    const PruningSummary& pruning = *page.run->pruning;
    std::string table = "<table><tr><th>subgraph</th><th class=\"num\">views</th><th class=\"num\">edges</th>"
                        "<th>status</th><th class=\"num\">depth</th></tr>\n";
    for (size_t k = 0; k < pruning.subgraphs.size(); ++k) {
      const AcceptedSubgraphSummary& s = pruning.subgraphs[k];
      table += "<tr><td><span class=\"swatch\" style=\"background:" + SubgraphColor(static_cast<int>(k)).Hex() +
               "\"></span>" + std::to_string(k + 1) + "</td><td class=\"num\">" + std::to_string(s.num_views) +
               "</td><td class=\"num\">" + std::to_string(s.num_edges) + "</td><td>" + EscapeXml(s.status) +
               "</td><td class=\"num\">" + std::to_string(s.depth) + "</td></tr>\n";
    }
    table += "</table>\n";
    const std::string note = "From pruning_report.json of " + EscapeXml(page.label) + ": " +
                             std::to_string(pruning.edges_in) + " edges in, " + std::to_string(pruning.edges_out) +
                             " out, " + std::to_string(pruning.engine_runs) + " subgraph solves, " +
                             FormatNumber(pruning.total_seconds, 2) + " s.";
    return Section("subgraphs", "Accepted subgraphs", note, table);
  }
  return "";
}

}  // namespace

std::string BuildHtmlReport(const HtmlReportInput& input) {
  std::vector<RunPage> pages;
  const SfmData* truth = input.ground_truth ? &*input.ground_truth : nullptr;
  for (const RunFolder& run : input.runs) {
    RunPage page;
    page.run = &run;
    page.label = RunLabel(run);
    if (truth != nullptr) {
      EvaluationOptions options;
      options.alignment.seed = input.seed;
      page.evaluation = EvaluateModel(run.model, *truth, options, run.model_path.string(), input.ground_truth_source);
    }
    if (run.view_graph) {
      for (const RunGraphView& view : run.view_graph->views) {
        if (view.subgraph >= 0) page.subgraph_of[view.view_id] = view.subgraph;
      }
    }
    pages.push_back(std::move(page));
  }
  // Two runs of one engine need their folders to tell them apart.
  if (pages.size() > 1 && pages[0].label == pages[1].label) {
    for (RunPage& page : pages) page.label += " (" + page.run->path.filename().string() + ")";
  }
  const std::string title = input.title.empty() ? pages.front().run->path.filename().string() : input.title;
  std::string subtitle = "PruneSfM report \u00b7 " + pages.front().label + " \u00b7 " + pages.front().run->path.string();
  if (pages.size() > 1) subtitle += " \u00b7 compared with " + pages[1].label + " \u00b7 " + pages[1].run->path.string();

  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                     "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
                     "<title>" + EscapeXml(title) + " \u2014 PruneSfM report</title>\n<style>" + kReportCss +
                     "</style>\n</head>\n<body>\n<header><h1>" + EscapeXml(title) + "</h1><div class=\"sub\">" +
                     EscapeXml(subtitle) + "</div><nav><a href=\"#summary\">summary</a><a href=\"#graph\">view graph</a>"
                     "<a href=\"#topview\">top view</a><a href=\"#epipolar\">epipolar checks</a>"
                     "<a href=\"#timings\">timings</a></nav></header>\n<main>\n";
  html += SummarySection(pages);
  html += GraphSection(pages, input.seed);
  html += TopViewSection(pages, truth);
  html += EpipolarSection(pages, input);
  html += TimingsSection(pages);
  html += SubgraphSection(pages);
  html += "</main>\n<footer>Generated by <code>prunesfm report</code>";
  if (truth != nullptr) html += " \u00b7 ground truth " + EscapeXml(input.ground_truth_source);
  html += " \u00b7 seed " + std::to_string(input.seed) + "</footer>\n<script>" + kReportScript +
          "</script>\n</body>\n</html>\n";
  return html;
}

}  // namespace sfm_pruning
