// The command-line options of the view-graph pruning (GLOBAL_PRUNED in reconstruct/run, and
// `prunesfm prune`): every threshold, the RANSAC iteration count and sample fraction, recursion
// and each consistency test on/off, with the paper's values as defaults (METHOD.md §3–4).
#pragma once

#include <string>

#include "sfm_pruning/pruning/view_graph_pruning.hpp"

namespace CLI {
class App;
}

namespace prunesfm {

// Adds the pruning options to `cmd` (in an option group "Pruning"), bound to `options`.
// `final_solve`: the subcommand solves the pruned graph to the end (run, reconstruct), so the
// option of how that solve starts from the audit's model applies; `prune` stops after the audit.
void AddPruningOptions(CLI::App* cmd, sfm_pruning::ViewGraphPruningOptions* options, bool final_solve);

// The --prune_audit_model_schedule name of a schedule (for the run's record of its settings).
std::string AuditModelName(sfm_pruning::AuditModelSchedule schedule);

}  // namespace prunesfm
