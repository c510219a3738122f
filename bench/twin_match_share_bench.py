#!/usr/bin/env python3
"""How many twin matches inside true pairs the GLOBAL engine survives, with each kind of
positioning tracks. Writes bench/sections/twin_match_share.md.

The synthetic street's true pairs carry matches between copies of its facade module (twin matches
on the epipolar line, at a wrong depth; docs/pruning.md). Here the oracle deletes every
twin-dominated pair (as bench/oracle_pruning_bench.py), then keeps a random share of the twin
matches of the pairs left (ground_truth/feature_landmarks.txt labels every match; one sample per
seed of --sample_seeds) and runs GLOBAL with `--positioning_tracks CONNECTED`
(union-find tracks, GLOMAP) and `MATCH_STARS` (each feature with its direct matches:
src/sfm_pruning/global/match_star_tracks.hpp). A second table keeps every twin match and tightens
the verification's inlier threshold instead (`--max_epipolar_error_deg`: the twins lie near their
epipolar lines, not on them), on the oracle's graph (GLOBAL) and on the whole scene
(GLOBAL_PRUNED). Python 3 standard library only.
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_colmap as bc  # noqa: E402
import bench_support as bs  # noqa: E402

TRACKS = ("CONNECTED", "MATCH_STARS")


def run_global(args, prunesfm, database, scene, out, tracks, engine="GLOBAL", epipolar_deg=None):
    options = ["--positioning_tracks", tracks, "--seed", args.seed, "--num_threads", args.threads]
    if epipolar_deg is not None:
        options += ["--max_epipolar_error_deg", epipolar_deg]
    stage = bs.run_ours_on_database(prunesfm, database, scene / "images", out / "result", engine, out / "run.log",
                                    args.timeout, options, output_flag="--output")
    return bs.evaluate_against(prunesfm, bs.run_model(stage, out / "result"), scene / "ground_truth" / "gt_cameras.txt",
                               out, args.seed, args.timeout)


def cell(r):
    return f"{r['auc']['3']:.1f} / {r['auc']['5']:.1f} / {r['auc']['10']:.1f} ({r['registered']}/{r['num_reference']})"


def threshold_table(args, prunesfm, scene, oracle_db, work):
    """Every twin match kept; the verification's threshold varies. GLOBAL on the oracle's graph and
    GLOBAL_PRUNED on the whole scene, each with both kinds of tracks."""
    thresholds = [t for t in args.epipolar_thresholds.split(",") if t]
    if not thresholds:
        return []
    lines = ["", "Every twin match kept, the verification's inlier threshold tightened (`--max_epipolar_error_deg`; "
             "default 0.25). AUC@3 / 5 / 10 (registered images).", "",
             "| threshold (deg) | " + " | ".join(f"oracle graph, GLOBAL, `{t}`" for t in TRACKS) + " | "
             + " | ".join(f"whole scene, GLOBAL_PRUNED, `{t}`" for t in TRACKS) + " |",
             "|---|" + "---|" * (2 * len(TRACKS))]
    whole_db = work / "whole_scene.db"
    bc.copy_database(scene / "database.db", whole_db)
    for degrees in thresholds:
        cells = []
        for engine, database in (("GLOBAL", oracle_db), ("GLOBAL_PRUNED", whole_db)):
            for tracks in TRACKS:
                out = work / f"threshold_{degrees}_{engine}_{tracks}"
                cells.append(cell(run_global(args, prunesfm, database, scene, out, tracks, engine, degrees)))
        lines.append(f"| {degrees} | " + " | ".join(cells) + " |")
        print(lines[-1], flush=True)
    return lines


def main():
    parser = bs.argument_parser(__doc__, "/tmp/prunesfm-twin-share")
    parser.add_argument("--scene", default="street", help="prunesfm synth scene")
    parser.add_argument("--shares", default="0,0.2,0.4,0.6,0.8,1", help="shares of the twin matches kept")
    parser.add_argument("--sample_seeds", default="1,2", help="seeds of the random shares (one row each)")
    parser.add_argument("--epipolar_thresholds", default="0.25,0.15,0.12,0.1,0.08",
                        help="--max_epipolar_error_deg values of the second table (empty: no second table)")
    args = parser.parse_args()
    prunesfm = str(bs.find_prunesfm(args.prunesfm))
    work = Path(args.work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    scene = work / "scene"
    bs.synth_stage(prunesfm, args.scene, args.seed, scene, work / "synth.log", args.timeout)
    labels = scene / "ground_truth" / "feature_landmarks.txt"
    if not labels.is_file():
        print(f"twin_match_share_bench: {labels} missing (a prunesfm older than its match labels)")
        return 1
    features = bs.read_feature_landmarks(labels)
    pairs, num_pairs = bs.twin_dominated_pairs(scene / "ground_truth" / "synthetic_scene.json", 1.0)
    oracle_db = work / "oracle.db"
    bc.copy_database(scene / "database.db", oracle_db)
    deleted_pairs = bs.delete_pairs(oracle_db, pairs)
    lines = bs.header_lines("Twin matches inside true pairs: what the positioning survives", sys.argv, prunesfm, None)
    lines += [f"`prunesfm synth --scene {args.scene} --seed {args.seed}`; the oracle deletes {deleted_pairs} of "
              f"{num_pairs} pairs (twin matches outnumber true ones), then a random share of the twin matches "
              f"left in the other pairs is kept (one random sample per seed). GLOBAL, AUC@3 / 5 / 10 "
              "(registered images).", "",
              "| twin matches kept | sample seed | " + " | ".join(f"`--positioning_tracks {t}`" for t in TRACKS) + " |",
              "|---|---|" + "---|" * len(TRACKS)]
    seeds = [int(x) for x in args.sample_seeds.split(",") if x]
    for share in [float(s) for s in args.shares.split(",") if s]:
        # Keeping none or all of them leaves nothing to sample: one row.
        for sample_seed in (seeds[:1] if share in (0.0, 1.0) else seeds):
            name = f"share_{share:g}_seed_{sample_seed}"
            database = work / f"{name}.db"
            bc.copy_database(oracle_db, database)
            deleted, total = bs.delete_twin_matches(database, features, share, sample_seed)
            cells = [cell(run_global(args, prunesfm, database, scene, work / f"{name}_{tracks}", tracks))
                     for tracks in TRACKS]
            kept = f"{share:.0%} (deleted {deleted} of {total} matches)"
            seed_cell = str(sample_seed) if share not in (0.0, 1.0) else "–"
            lines.append(f"| {kept} | {seed_cell} | " + " | ".join(cells) + " |")
            print(lines[-1], flush=True)
    lines += threshold_table(args, prunesfm, scene, oracle_db, work)
    bs.write_fragment("twin_match_share", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
