#!/usr/bin/env python3
"""What perfect pair pruning could reach on the synthetic duplicate scenes: the ceiling of any
view-graph pruning method, GLOBAL_PRUNED's included. Writes bench/sections/oracle_pruning.md.

For each scene, the synthetic ground truth says how many of a pair's putative matches are true,
twin (different copies of one texture: false but consistent with one wrong motion) or random
(synthetic_scene.json). The oracle deletes from a copy of the scene's database every pair whose
twin matches outnumber its true ones (or, with --twin_ratio R, exceed R times them), then runs
GLOBAL (`prunesfm run`) and COLMAP 3.8's mapper on the rest (COLMAP's `exhaustive_matcher`
verifies the full database first, since it would match a missing pair again, and the pairs are
deleted from its matches and two-view geometries after). A scene the oracle cannot recover is out
of reach of pruning edges: its true pairs carry twin matches too, or deleting the twin pairs
disconnects it. A last column also deletes the twin matches inside the pairs the oracle keeps
(ground_truth/feature_landmarks.txt labels every match) and runs GLOBAL: what the solve reaches
once no wrong correspondence of a copy is left. GLOBAL and GLOBAL_PRUNED on the full database are
the comparison columns.

Scenes are generated here (`prunesfm synth --seed S --scene NAME` plus any extra arguments given
as NAME:ARGS, e.g. 'street_12m=street:--street_module_width 12'), so nothing depends on another
script's work folder. Python 3 standard library only.
"""

import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_colmap as bc  # noqa: E402
import bench_support as bs  # noqa: E402

DEFAULT_SCENES = ["orbit_symmetric", "street", "street_12m=street:--street_module_width 12", "courtyard"]


def evaluate_ours_on_database(args, prunesfm, database, gt, out, engine):
    """`prunesfm run --database` with `engine`, its model evaluated against `gt`."""
    stage = bs.run_ours_on_database(prunesfm, database, out / "images", out / "result", engine, out / "run.log",
                                    args.timeout, ["--seed", args.seed, "--num_threads", args.threads],
                                    output_flag="--output")
    return bs.evaluate_against(prunesfm, bs.run_model(stage, out / "result"), gt, out, args.seed, args.timeout)


def evaluate_colmap_without_pairs(args, prunesfm, database, pairs, gt, out):
    """COLMAP's exhaustive_matcher verifies the full database (it would match again any pair whose
    matches are missing, undoing the oracle), then the oracle's pairs are deleted from its matches and
    two-view geometries, then the mapper; its model evaluated against `gt`."""
    t = str(args.threads)
    bs.colmap_match("match", args.colmap, ["exhaustive_matcher"], database, out / "match.log", t, args.timeout)
    bs.delete_pairs(database, pairs, ("two_view_geometries", "matches"))
    (out / "images").mkdir(parents=True, exist_ok=True)
    _, model = bs.colmap_mapper(args.colmap, database, out / "images", out, t, args.timeout, True)
    return bs.evaluate_against(prunesfm, model, gt, out, args.seed, args.timeout)


def main():
    parser = bs.argument_parser(__doc__, "/tmp/prunesfm-oracle")
    parser.add_argument("--scenes", default=",".join(DEFAULT_SCENES),
                        help="comma-separated LABEL or LABEL=SCENE:EXTRA_SYNTH_ARGS")
    parser.add_argument("--twin_ratio", type=float, default=1.0,
                        help="a pair is deleted when its twin matches exceed this times its true ones")
    args = parser.parse_args()
    prunesfm = str(bs.find_prunesfm(args.prunesfm))
    lines = bs.header_lines("Oracle pruning: the ceiling of pruning view-graph edges", sys.argv, prunesfm, args.colmap)
    lines += [f"Pairs whose twin matches exceed {args.twin_ratio:g}× their true matches (synthetic ground truth) "
              "are deleted from the database before GLOBAL and COLMAP's mapper run; GLOBAL and GLOBAL_PRUNED on "
              f"the full database for comparison. `prunesfm synth --seed {args.seed}`, AUC@3 / 5 / 10, "
              "registered images.", "",
              "| scene | pairs deleted / all | GLOBAL | GLOBAL_PRUNED | oracle + GLOBAL | oracle + COLMAP | "
              "oracle + GLOBAL on COLMAP's two-view geometries | twin matches left in the oracle's pairs | "
              "oracle without them + GLOBAL |",
              "|---|---|---|---|---|---|---|---|---|"]
    results = {}
    for spec in [s for s in args.scenes.split(",") if s]:
        label, scene, extra = bs.parse_scene(spec)
        work = Path(args.work).resolve() / label
        bs.fresh_folder(work)
        synth = work / "scene"
        bs.synth_stage(prunesfm, scene, args.seed, synth, work / "synth.log", args.timeout, extra)
        gt = synth / "ground_truth" / "gt_cameras.txt"
        row = {}
        for engine in ("GLOBAL", "GLOBAL_PRUNED"):
            db = work / f"{engine}.db"
            bc.copy_database(synth / "database.db", db)
            row[engine] = evaluate_ours_on_database(args, prunesfm, db, gt, work / engine, engine)
        pairs, num_pairs = bs.twin_dominated_pairs(synth / "ground_truth" / "synthetic_scene.json", args.twin_ratio)
        oracle_db = work / "oracle.db"
        bc.copy_database(synth / "database.db", oracle_db)
        row["deleted"] = bs.delete_pairs(oracle_db, pairs)
        row["pairs"] = num_pairs
        row["oracle GLOBAL"] = evaluate_ours_on_database(args, prunesfm, oracle_db, gt, work / "oracle_global",
                                                         "GLOBAL")
        # Twin matches also sit inside the pairs the oracle keeps (a view sees part of a copy its
        # neighbour sees of the next one); this row deletes those too: the ceiling of pruning edges
        # and matches, i.e. what the solve does once every wrong correspondence of a copy is gone.
        labels = synth / "ground_truth" / "feature_landmarks.txt"
        if labels.is_file():
            clean_db = work / "oracle_without_twin_matches.db"
            bc.copy_database(oracle_db, clean_db)
            row["twin matches deleted"], row["matches kept by the oracle"] = bs.delete_twin_matches(
                clean_db, bs.read_feature_landmarks(labels))
            row["oracle without twin matches GLOBAL"] = evaluate_ours_on_database(
                args, prunesfm, clean_db, gt, work / "oracle_without_twin_matches", "GLOBAL")
        else:
            print(f"oracle_pruning_bench: {labels} missing (a prunesfm older than its match labels): "
                  "no column without the twin matches", flush=True)
        if args.colmap:
            colmap_db = work / "oracle_colmap.db"
            bc.copy_database(synth / "database.db", colmap_db)
            row["oracle colmap"] = evaluate_colmap_without_pairs(args, prunesfm, colmap_db, pairs, gt,
                                                                 work / "oracle_colmap")
            # The same verified pairs through our engine (`run --database` uses a database's two-view
            # geometries as they are): tells our verification's share of a failure from the solve's.
            ours_on_colmap_db = work / "oracle_colmap_geometries.db"
            bc.copy_database(colmap_db, ours_on_colmap_db)
            row["oracle GLOBAL on colmap geometries"] = evaluate_ours_on_database(
                args, prunesfm, ours_on_colmap_db, gt, work / "oracle_global_colmap_geometries", "GLOBAL")
        results[label] = row

        def cell(r):
            if r is None:
                return "–"
            return (f"{r['auc']['3']:.1f} / {r['auc']['5']:.1f} / {r['auc']['10']:.1f} "
                    f"({r['registered']}/{r['num_reference']})")
        lines.append(f"| {label} (`{scene}{(' ' + ' '.join(extra)) if extra else ''}`) | {row['deleted']} / {num_pairs} | "
                     f"{cell(row['GLOBAL'])} | {cell(row['GLOBAL_PRUNED'])} | {cell(row['oracle GLOBAL'])} | "
                     f"{cell(row.get('oracle colmap'))} | {cell(row.get('oracle GLOBAL on colmap geometries'))} | "
                     + (f"{row['twin matches deleted']} of {row['matches kept by the oracle']}"
                        if "twin matches deleted" in row else "–")
                     + f" | {cell(row.get('oracle without twin matches GLOBAL'))} |")
        print(f"{label}: {lines[-1]}", flush=True)
    (Path(args.work) / "results.json").write_text(json.dumps(results, indent=2) + "\n")
    lines += ["", "Reading: where the oracle folds too, the scene is beyond pruning edges."]
    bs.write_fragment("oracle_pruning", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
