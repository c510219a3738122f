#include "sfm_pruning/report/run_view_graph.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>

#include <Eigen/Geometry>

#include "sfm_pruning/report/json_file.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {

size_t RunViewGraph::NumRemovedEdges() const {
  size_t count = 0;
  for (const RunGraphEdge& edge : edges) count += edge.removed ? 1 : 0;
  return count;
}

RunViewGraph MakeRunViewGraph(const std::string& engine, const ViewGraph& graph, const SfmData& scene,
                              const ViewGraphPruningReport* pruning) {
  RunViewGraph out;
  out.engine = engine;
  std::map<IndexT, int> subgraph_of;
  std::map<ViewPair, const RemovedEdge*> removed;
  if (pruning != nullptr) {
    const RecursivePartitionResult& partition = pruning->partition;
    out.num_subgraphs = static_cast<int>(partition.accepted.size());
    for (size_t k = 0; k < partition.accepted.size(); ++k) {
      for (IndexT view_id : partition.nodes.at(partition.accepted[k].node).view_ids) {
        subgraph_of[view_id] = static_cast<int>(k);
      }
    }
    for (const RemovedEdge& edge : pruning->removed_edges) removed[edge.pair] = &edge;
  }
  for (IndexT view_id : graph.Nodes()) {
    RunGraphView view;
    view.view_id = view_id;
    const auto it = scene.views.find(view_id);
    view.image = it == scene.views.end() ? "" : it->second.RelativeImagePath();
    const auto subgraph = subgraph_of.find(view_id);
    view.subgraph = subgraph == subgraph_of.end() ? -1 : subgraph->second;
    out.views.push_back(view);
  }
  // `graph` is the graph before pruning: its valid edges are the input of the pruning.
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    RunGraphEdge record;
    record.i = pair.first;
    record.j = pair.second;
    record.inliers = edge.matches.size();
    record.relative_pose = edge.relative_pose;
    record.rotation_std_deg = edge.rotation_std_deg;
    const auto cut = removed.find(pair);
    if (cut != removed.end()) {
      record.removed = true;
      record.reason = EdgeInvalidReasonName(cut->second->invalidation.reason);
      record.value = cut->second->invalidation.value;
      record.threshold = cut->second->invalidation.threshold;
      record.measure = EdgeMeasureName(cut->second->invalidation.Measure());
    }
    out.edges.push_back(record);
  });
  return out;
}

void WriteRunViewGraph(const RunViewGraph& graph, const std::filesystem::path& path) {
  nlohmann::ordered_json views = nlohmann::ordered_json::array();
  for (const RunGraphView& view : graph.views) {
    views.push_back({{"view_id", view.view_id}, {"image", view.image}, {"subgraph", view.subgraph}});
  }
  nlohmann::ordered_json edges = nlohmann::ordered_json::array();
  for (const RunGraphEdge& edge : graph.edges) {
    const Eigen::Quaterniond q(edge.relative_pose.rotation);
    const Eigen::Vector3d& t = edge.relative_pose.translation;
    nlohmann::ordered_json record = {{"i", edge.i},
                                     {"j", edge.j},
                                     {"inliers", edge.inliers},
                                     {"removed", edge.removed},
                                     {"rotation", {q.w(), q.x(), q.y(), q.z()}},
                                     {"translation", {t.x(), t.y(), t.z()}}};
    if (std::isfinite(edge.rotation_std_deg)) record["rotation_std_deg"] = edge.rotation_std_deg;
    if (edge.removed) {
      record["reason"] = edge.reason;
      record["value"] = edge.value;
      record["threshold"] = edge.threshold;
      record["measure"] = edge.measure;
    }
    edges.push_back(std::move(record));
  }
  // One view or edge per line: compact, and a diff of two runs reads edge by edge.
  WriteFileAtomically(path, false, [&](std::ostream& out) {
    out << "{\"engine\": " << nlohmann::json(graph.engine).dump() << ", \"num_subgraphs\": " << graph.num_subgraphs
        << ",\n\"views\": [";
    for (size_t k = 0; k < views.size(); ++k) out << (k == 0 ? "\n" : ",\n") << views[k].dump();
    out << "],\n\"edges\": [";
    for (size_t k = 0; k < edges.size(); ++k) out << (k == 0 ? "\n" : ",\n") << edges[k].dump();
    out << "]}\n";
  });
}

RunViewGraph ReadRunViewGraph(const std::filesystem::path& path) {
  const nlohmann::json json = ReadJsonObject(path);
  RunViewGraph graph;
  ReadJsonFields(path, "view graph", [&]() {
    graph.engine = json.at("engine").get<std::string>();
    graph.num_subgraphs = json.at("num_subgraphs").get<int>();
    for (const auto& view : json.at("views")) {
      graph.views.push_back(
          {view.at("view_id").get<IndexT>(), view.at("image").get<std::string>(), view.at("subgraph").get<int>()});
    }
    for (const auto& edge : json.at("edges")) {
      RunGraphEdge record;
      record.i = edge.at("i").get<IndexT>();
      record.j = edge.at("j").get<IndexT>();
      record.inliers = edge.at("inliers").get<size_t>();
      record.removed = edge.at("removed").get<bool>();
      if (edge.contains("rotation")) {  // absent from files written before poses were recorded
        const auto q = edge.at("rotation").get<std::array<double, 4>>();
        const auto t = edge.at("translation").get<std::array<double, 3>>();
        record.relative_pose.rotation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
        record.relative_pose.translation = Eigen::Vector3d(t[0], t[1], t[2]);
      }
      record.rotation_std_deg = edge.value("rotation_std_deg", std::numeric_limits<double>::infinity());
      if (record.removed) {
        record.reason = edge.at("reason").get<std::string>();
        record.value = edge.at("value").get<double>();
        record.threshold = edge.at("threshold").get<double>();
        // Absent from files written before the measure was recorded.
        record.measure = edge.value("measure", std::string());
      }
      graph.edges.push_back(record);
    }
  });
  std::map<IndexT, bool> listed;
  for (const RunGraphView& view : graph.views) {
    if (view.subgraph < -1 || view.subgraph >= graph.num_subgraphs) {
      throw FileError(path.string(), "view " + std::to_string(view.view_id) + " has subgraph " +
                                         std::to_string(view.subgraph) + " outside [-1, " +
                                         std::to_string(graph.num_subgraphs) + ")");
    }
    listed[view.view_id] = true;
  }
  for (const RunGraphEdge& edge : graph.edges) {
    if (!listed.count(edge.i) || !listed.count(edge.j) || edge.i == edge.j) {
      throw FileError(path.string(), "edge " + std::to_string(edge.i) + "-" + std::to_string(edge.j) +
                                         " does not join two listed views");
    }
  }
  return graph;
}

}  // namespace sfm_pruning
