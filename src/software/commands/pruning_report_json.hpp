// The pruning report (OUT/pruning_report.json of GLOBAL_PRUNED, and `prunesfm prune`'s report):
// the subgraph tree, the accepted subgraphs, the connected pairs, the removed edges with their
// reasons and measured errors, and the phase times. docs/pruning.md describes the fields.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "sfm_pruning/pruning/view_graph_pruning.hpp"

namespace prunesfm {

nlohmann::json PruningReportJson(const sfm_pruning::ViewGraphPruningReport& pruning);

// Writes `report` (pretty-printed) atomically.
void WriteJsonAtomically(const nlohmann::json& report, const std::filesystem::path& path);

// One line for the console: "N subgraphs (T tree nodes, E engine runs), removed R of I edges in
// P subgraph pairs, S s".
std::string PruningSummary(const sfm_pruning::ViewGraphPruningReport& pruning);

}  // namespace prunesfm
