#!/usr/bin/env python3
"""The pruning as a filter for COLMAP (issue 5, item 6): COLMAP 3.8's `mapper` on a scene's
verified database as it is, and on the copy `prunesfm prune` writes (the spurious two-view
geometries removed); AUC of both against the ground truth, and the time of the pruning.

Inputs are the ones bench/run_benchmarks.py prepared in its --work folder (default
/tmp/prunesfm-bench): for the synthetic scenes COLMAP's verified copy `<scene>/colmap_verified.db`
(the synthetic putative matches verified by COLMAP's exhaustive_matcher), for castle-P19 the
shared COLMAP feature + exhaustive matching database `castle-P19/shared/database.db`. They are
copied (SQLite backup) into this script's own --work folder; nothing in the inputs is modified.
Writes bench/sections/prune_filter.md. Python 3 standard library only.
"""

import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_colmap as bc  # noqa: E402
import bench_support as bs  # noqa: E402

SYNTHETIC = ["orbit_symmetric", "street", "courtyard", "clean"]
DATASETS = {"castle-P19": "strecha/castle-P19"}


def scene_inputs(args, scene):
    """(verified database, image folder, gt_cameras.txt, synthetic_scene.json or None)."""
    bench = Path(args.bench_work)
    if scene in SYNTHETIC:
        gt_dir = bench / scene / "ground_truth"
        return (bench / scene / "colmap_verified.db", None, gt_dir / "gt_cameras.txt",
                gt_dir / "synthetic_scene.json")
    folder = Path(args.shared) / "datasets" / DATASETS[scene]
    return bench / scene / "shared" / "database.db", folder / "images", folder / "gt_cameras.txt", None


def spurious_pairs(scene_json):
    """Synthetic truth: a pair whose matches are mostly between twin copies (twin > true) has a
    wrong two-view geometry. View ids = COLMAP image ids in the synthetic databases."""
    pairs = json.loads(Path(scene_json).read_text())["pairs"]
    return {(min(p["i"], p["j"]), max(p["i"], p["j"])) for p in pairs if p["twin"] > p["true"]}


def run_scene(args, prunesfm, colmap, scene):
    db_in, images, gt, scene_json = scene_inputs(args, scene)
    row = {"scene": scene, "status": "ok"}
    if bc.num_verified_pairs(db_in) == 0 or not gt.is_file():
        row["status"] = f"input missing: {db_in} (run bench/run_benchmarks.py --prepare_only and its colmap row)"
        return row
    out = Path(args.work) / scene
    bs.fresh_folder(out)
    if images is None:
        images = out / "images"  # synthetic: the mapper needs the folder, not images
        images.mkdir()
    original, pruned = out / "original.db", out / "pruned.db"
    bc.copy_database(db_in, original)
    t = str(args.threads)
    stage, report = bs.prune_database(prunesfm, original, pruned, out, t, str(args.seed), args.timeout)
    row["prune_s"] = stage["seconds"]
    row["prune_peak_mb"] = stage["peak_mb"]
    if report is None:
        row["status"] = f"prune failed: {stage.get('error')}"
        return row
    row["prune_phases"] = report["filter"]["seconds"]
    before, after = bc.verified_pairs(original), bc.verified_pairs(pruned)
    removed = before - after
    row["pairs_before"], row["pairs_after"] = len(before), len(after)
    if scene_json is not None and scene_json.is_file():
        wrong = spurious_pairs(scene_json) & before
        row["spurious_before"] = len(wrong)
        row["spurious_removed"] = len(removed & wrong)
        row["correct_removed"] = len(removed - wrong)
    for label, db in (("original", original), ("pruned", pruned)):
        map_dir = out / f"map_{label}"
        stage, model = bs.colmap_mapper(colmap, db, images, map_dir, t, args.timeout, scene in SYNTHETIC)
        result = bs.evaluate_against(prunesfm, model, gt, map_dir, str(args.seed), args.timeout)
        result["map_s"] = stage["seconds"]
        if stage["rc"] != 0:
            result["error"] = stage.get("error")
        row[label] = result
    return row


def fmt_auc(result):
    return " / ".join(f"{result['auc'][str(t)]:.1f}" for t in bs.THRESHOLDS)


def markdown(args, argv, prunesfm, colmap, rows):
    L = bs.header_lines("COLMAP's mapper on the pruned database (`prunesfm prune`)", argv, prunesfm, colmap)
    L += ["`prunesfm prune --database DB --output DB2` runs GLOBAL_PRUNED's view-graph pruning (default "
          "options) on DB's verified two-view geometries and writes a copy of DB without the "
          "two_view_geometries rows of the removed pairs; COLMAP 3.8's `mapper` (default options) then runs "
          "on DB and on DB2. DB is COLMAP's own verified database (synthetic scenes: `colmap_verified.db` of "
          "`bench/run_benchmarks.py`; castle-P19: its `shared/database.db`, SIFT + exhaustive matching). "
          "AUC of the pairwise relative pose errors against the ground truth (`prunesfm evaluate`). "
          "*spurious*: pairs whose synthetic matches are mostly between twin copies (twin > true in "
          "`ground_truth/synthetic_scene.json`).", ""]
    L += ["| scene | pairs | removed (spurious / correct) | spurious pairs | prune s | registered orig → pruned "
          "| AUC@3/5/10 original | AUC@3/5/10 pruned | map s orig / pruned |",
          "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["status"] != "ok":
            L.append(f"| {r['scene']} | {r['status']} |  |  |  |  |  |  |  |")
            continue
        o, p = r["original"], r["pruned"]
        removed = r["pairs_before"] - r["pairs_after"]
        split = f" ({r['spurious_removed']} / {r['correct_removed']})" if "spurious_removed" in r else ""
        spurious = str(r["spurious_before"]) if "spurious_before" in r else "–"
        L.append(f"| {r['scene']} | {r['pairs_before']} | {removed}{split} | {spurious} | {r['prune_s']:.1f} "
                 f"| {o['registered']} → {p['registered']} | {fmt_auc(o)} | {fmt_auc(p)} "
                 f"| {o['map_s']:.1f} / {p['map_s']:.1f} |")
    L.append("")
    gains = [(r["scene"], r["pruned"]["auc"]["10"] - r["original"]["auc"]["10"]) for r in rows if r["status"] == "ok"]
    if gains:
        L.append("AUC@10 change from pruning: " + ", ".join(f"{s} {g:+.1f}" for s, g in gains) + ".")
        L.append("")
    return L


def parse_args(argv):
    p = bs.argument_parser(__doc__, "/tmp/prunesfm-bench-prunefilter")
    p.add_argument("--bench_work", default="/tmp/prunesfm-bench", help="run_benchmarks.py's --work (inputs)")
    p.add_argument("--scenes", default=",".join(SYNTHETIC + list(DATASETS)))
    p.add_argument("--json", default=None, help="also write the rows as JSON here (default: WORK/results.json)")
    return p.parse_args(argv)


def main(argv):
    args = parse_args(argv)
    prunesfm = bs.find_prunesfm(args.prunesfm)
    if not args.colmap:
        sys.exit("prune_filter_bench: needs Debian's colmap on the PATH (or --colmap)")
    scenes = [s for s in args.scenes.split(",") if s]
    for s in scenes:
        if s not in SYNTHETIC and s not in DATASETS:
            sys.exit(f"prune_filter_bench: unknown scene {s} (known: {', '.join(SYNTHETIC + list(DATASETS))})")
    Path(args.work).mkdir(parents=True, exist_ok=True)
    rows = []
    for scene in scenes:
        print(f"== {scene}", flush=True)
        rows.append(run_scene(args, prunesfm, args.colmap, scene))
    json_path = Path(args.json or Path(args.work) / "results.json")
    json_path.write_text(json.dumps(rows, indent=2) + "\n")
    bs.write_fragment("prune_filter", markdown(args, ["bench/prune_filter_bench.py"] + argv, prunesfm,
                                               args.colmap, rows))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
