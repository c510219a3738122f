#!/usr/bin/env python3
"""Which of GLOBAL_PRUNED's decisions keep the twin edges, on the synthetic duplicate scenes.
Writes bench/sections/pruning_decisions.md.

A synthetic scene labels every putative match of a pair true, twin (between two copies of one
texture) or random (ground_truth/synthetic_scene.json); an edge is twin-dominated when its twin
matches outnumber its true ones (the oracle's rule, bench/oracle_pruning_bench.py). Each verified
edge of the run's view graph (view_graph.json) is either inside one accepted subgraph (the
partition and the consistency tests decided it) or between two (the pair's inter-subgraph RANSAC,
its rotation-only fallback when no hypothesis is supported, then the loop check against the trusted
forest: pruning_report.json `subgraph_pairs`). The table counts, per decision, the true and the
twin-dominated edges kept and removed, so a wrong decision shows where it was taken. Python 3
standard library only.
"""

import json
import shlex
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_support as bs  # noqa: E402

DEFAULT_SCENES = ["street", "courtyard", "orbit_symmetric",
                  "sequential_large_250=sequential_large:--num_views 250",
                  "sequential_large_1000=sequential_large:--num_views 1000"]
INSIDE = "inside one subgraph"


def pair_classes(report):
    """(k1, k2) -> the decision that kept or removed the pair's edges, e.g. 'aligned, forest'."""
    classes = {}
    for pair in report.get("subgraph_pairs", []):
        status = pair.get("status", "?")
        forest = pair.get("forest_decision")
        key = tuple(sorted((pair["k1"], pair["k2"])))
        classes[key] = f"{status}, {forest}" if forest else status
    return classes


def count_decisions(run_dir, scene_json):
    """Counter of (decision, 'true'|'twin', 'kept'|'removed') over the verified edges of a run; twin =
    twin-dominated by the oracle's rule (bench_support.twin_dominated_pairs)."""
    twin_pairs, _ = bs.twin_dominated_pairs(scene_json, 1.0)
    graph = json.loads((run_dir / "view_graph.json").read_text())
    report = json.loads((run_dir / "pruning_report.json").read_text())
    index_of = {v["view_id"]: bs.view_index(v["image"]) for v in graph["views"]}
    subgraph_of = {v["view_id"]: v["subgraph"] for v in graph["views"]}
    classes = pair_classes(report)
    counts = Counter()
    for edge in graph["edges"]:
        label = "twin" if tuple(sorted((index_of[edge["i"]], index_of[edge["j"]]))) in twin_pairs else "true"
        ka, kb = subgraph_of[edge["i"]], subgraph_of[edge["j"]]
        decision = INSIDE if ka == kb else classes.get(tuple(sorted((ka, kb))), "between, no pair entry")
        counts[(decision, label, "removed" if edge["removed"] else "kept")] += 1
    return counts


def scene_lines(label, counts, evaluation):
    decisions = sorted({d for d, _, _ in counts}, key=lambda d: (d != INSIDE, d))
    head = (f"**{label}**: AUC@10 {evaluation['auc']['10']:.1f} "
            f"({evaluation['registered']}/{evaluation['num_reference']})")
    twin_kept = sum(n for (d, lab, fate), n in counts.items() if lab == "twin" and fate == "kept")
    true_removed = sum(n for (d, lab, fate), n in counts.items() if lab == "true" and fate == "removed")
    lines = ["", f"{head}; twin-dominated edges kept {twin_kept}, true edges removed {true_removed}.", "",
             "| decision | true kept | true removed | twin kept | twin removed |", "|---|---|---|---|---|"]
    for d in decisions:
        cells = [str(counts.get((d, lab, fate), 0)) for lab in ("true", "twin") for fate in ("kept", "removed")]
        lines.append(f"| {d} | " + " | ".join(cells) + " |")
    return lines


def main():
    parser = bs.argument_parser(__doc__, "/tmp/prunesfm-pruning-decisions")
    parser.add_argument("--scenes", default=",".join(DEFAULT_SCENES),
                        help="comma-separated LABEL[=SCENE[:SYNTH ARGS]] (as bench/oracle_pruning_bench.py)")
    parser.add_argument("--run_args", default="", help="extra `prunesfm run` options, e.g. '--prune_audit_enabled true'")
    parser.add_argument("--reuse", action="store_true", help="keep a scene already generated in the work folder")
    args = parser.parse_args()
    prunesfm = str(bs.find_prunesfm(args.prunesfm))
    work = Path(args.work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    lines = bs.header_lines("Where the pruning keeps twin edges: its decisions against the synthetic labels",
                            sys.argv, prunesfm, None)
    run_args = shlex.split(args.run_args)
    lines += [f"`prunesfm synth --scene S --seed {args.seed}`, then `prunesfm run --engine GLOBAL_PRUNED"
              f"{' ' + args.run_args if run_args else ''}` (seed {args.seed}, {args.threads} threads). An edge is "
              "twin-dominated when its twin matches outnumber its true ones. Decision: inside one accepted "
              "subgraph, or the subgraph pair's `status` (aligned: a RANSAC hypothesis; rotation_only: none "
              "supported, the largest rotation-consistent set) and its trusted-forest decision (docs/pruning.md)."]
    for spec in [s for s in args.scenes.split(",") if s]:
        label, scene_name, extra = bs.parse_scene(spec)
        scene = work / label
        if not (args.reuse and (scene / "database.db").is_file()):
            bs.synth_stage(prunesfm, scene_name, args.seed, scene, work / f"{label}_synth.log", args.timeout, extra)
        out = work / f"{label}_run"
        stage = bs.run_ours_on_database(prunesfm, scene / "database.db", scene / "images", out, "GLOBAL_PRUNED",
                                        work / f"{label}_run.log", args.timeout,
                                        ["--seed", args.seed, "--num_threads", args.threads, *run_args],
                                        output_flag="--output")
        if stage["rc"] != 0:
            lines += ["", f"**{label}**: `prunesfm run` failed (rc {stage['rc']}, log {work / (label + '_run.log')})."]
            continue
        evaluation = bs.evaluate_against(prunesfm, bs.run_model(stage, out), scene / "ground_truth" / "gt_cameras.txt",
                                         out, args.seed, args.timeout)
        counts = count_decisions(out, scene / "ground_truth" / "synthetic_scene.json")
        scene_table = scene_lines(label, counts, evaluation)
        lines += scene_table
        print("\n".join(scene_table), flush=True)
    bs.write_fragment("pruning_decisions", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
