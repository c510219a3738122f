#!/usr/bin/env python3
"""How much GLOBAL_PRUNED's result depends on the seed (Louvain's visiting order, the RANSAC
samples, every engine run's random start). Writes bench/sections/seed_sweep.md, or with
--synthetic bench/sections/seed_sweep_synthetic.md.

Real scenes (--scenes, default books,street): the exhaustive databases and sequential references
bench/ambiguous_bench.py prepared in its --work folder (run it first, --prepare_only is enough),
scored by AUC@5 against the reference (success: ≥ 90, issue 5's target).
Synthetic scenes (--synthetic, e.g. street): `prunesfm synth --scene S --seed SEED` once (--seed), scored
by AUC@10 against the ground truth (success: ≥ 95, issue 5's target).
For every scene and every seed in --seeds, `prunesfm run --engine GLOBAL_PRUNED --seed S
--num_threads --threads` with each --variant's extra arguments (default: the defaults, and the
earlier pruning: the inlier-weighted partition and the triangle vote; with --synthetic: the defaults
and the street configuration of docs/pruning.md). Python 3 standard library only.
"""

import concurrent.futures
import json
import re
import shlex
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_colmap as bc  # noqa: E402
import bench_support as bs  # noqa: E402

DEFAULT_VARIANTS = [
    "defaults=",
    "the earlier defaults (inlier partition, triangle vote)=--prune_edge_weight inliers --prune_link_trust match_coverage "
    "--prune_subgraph_loops_method triangle_vote",
]
SYNTHETIC_VARIANTS = [
    "defaults=",
    "street configuration=--positioning_tracks MATCH_STARS --max_epipolar_error_deg 0.08 --prune_audit_enabled true",
]


def real_scene(args, scene):
    """(database, images, reference) of a real scene prepared by bench/ambiguous_bench.py."""
    prepared = Path(args.ambiguous_work) / scene
    database, reference = prepared / "exhaustive.db", prepared / "reference" / "sparse" / "0"
    if not database.is_file() or not reference.is_dir():
        sys.exit(f"seed_sweep_bench: {database} or {reference} missing (run bench/ambiguous_bench.py first)")
    return database, Path(args.shared) / "datasets" / "ambiguous" / scene / "images", reference


def synthetic_scene(args, prunesfm, scene):
    """(database, images, ground truth) of `prunesfm synth --scene scene`, made once in --work."""
    out = Path(args.work) / "synthetic" / scene / "data"
    gt = out / "ground_truth" / "gt_cameras.txt"
    if not gt.is_file():
        stage = bs.synth_stage(prunesfm, scene, args.seed, out, Path(args.work) / f"{scene}_synth.log", args.timeout,
                               threads=args.threads)
        if stage["rc"] != 0:
            sys.exit(f"seed_sweep_bench: prunesfm synth --scene {scene} failed (see {args.work}/{scene}_synth.log)")
    (out / "images").mkdir(exist_ok=True)  # a scene synthesized by an earlier run may predate the folder
    return out / "database.db", out / "images", gt


def main():
    parser = bs.argument_parser(__doc__, "/tmp/prunesfm-seed-sweep")
    parser.add_argument("--ambiguous_work", default="/tmp/prunesfm-bench-ambiguous",
                        help="bench/ambiguous_bench.py's --work (exhaustive.db and reference/ per scene)")
    parser.add_argument("--scenes", default="books,street", help="real scenes (bench/ambiguous_bench.py)")
    parser.add_argument("--synthetic", default="", help="synthetic scenes instead, e.g. street,courtyard")
    parser.add_argument("--seeds", default="0-9", help="a range A-B or a comma-separated list")
    parser.add_argument("--variant", action="append", default=[], metavar="LABEL=ARGS",
                        help="a row LABEL with these extra `prunesfm run` arguments (repeatable)")
    parser.add_argument("--target", type=float, help="AUC counted as a success (default: 90 real, 95 synthetic)")
    parser.add_argument("--fragment", help="section name to write (default: seed_sweep, or seed_sweep_synthetic "
                                           "with --synthetic); another name keeps those sections and adds one")
    bs.add_options(parser, "jobs",
                   jobs={"help": "seeds run at once (each with --threads threads); the results do not depend on it"})
    parser.add_argument("--title", help="section title (default: by the kind of scenes)")
    args = parser.parse_args()
    prunesfm = str(bs.find_prunesfm(args.prunesfm))
    if "-" in args.seeds:
        first, last = (int(x) for x in args.seeds.split("-"))
        seeds = list(range(first, last + 1))
    else:
        seeds = [int(x) for x in args.seeds.split(",")]
    synthetic = [s for s in args.synthetic.split(",") if s]
    default_variants = SYNTHETIC_VARIANTS if synthetic else DEFAULT_VARIANTS
    variants = [v.split("=", 1) for v in (args.variant or default_variants)]
    auc_key, target = ("10", 95.0) if synthetic else ("5", 90.0)
    target = args.target if args.target is not None else target
    title = args.title or ("Seed sweep on synthetic scenes" if synthetic else "Seed sweep on the real ambiguous scenes")
    lines = bs.header_lines(title, sys.argv, prunesfm)
    scored = (f"`prunesfm synth --scene S --seed {args.seed}`, AUC@{auc_key} against its ground truth" if synthetic
              else f"each scene's exhaustive COLMAP database, AUC@{auc_key} against the sequential reference "
                   "(bench/ambiguous_bench.py)")
    lines += [f"GLOBAL_PRUNED with `--seed S --num_threads {args.threads}` for S in {seeds[0]}..{seeds[-1]} on "
              f"{scored}; success = AUC@{auc_key} ≥ {target:g}.", "",
              f"| scene | pruning | AUC@{auc_key} per seed | successes |", "|---|---|---|---|"]
    base = Path(args.work) / "synthetic" if synthetic else Path(args.work)

    def run_seed(scene, database, images, reference, label, extra, seed):
        """AUC of one GLOBAL_PRUNED run; each run has its own folder, so runs may go in parallel."""
        out = base / scene / f"{re.sub(r'[^A-Za-z0-9]+', '_', label).strip('_')}_{seed}"
        out.mkdir(parents=True, exist_ok=True)
        db = out / "database.db"
        bc.copy_database(database, db)
        stage = bs.run_ours_on_database(prunesfm, db, images, out / "result", "GLOBAL_PRUNED", out / "run.log",
                                        args.timeout,
                                        ["--seed", seed, "--num_threads", args.threads, *shlex.split(extra)])
        evaluation = bs.evaluate_against(prunesfm, bs.run_model(stage, out / "result"), reference, out,
                                         str(args.seed), args.timeout)
        auc = evaluation["auc"][auc_key]
        print(f"{scene} {label} seed {seed}: AUC@{auc_key} {auc:.1f}", flush=True)
        return auc

    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for scene in synthetic or [s for s in args.scenes.split(",") if s]:
            database, images, reference = (synthetic_scene(args, prunesfm, scene) if synthetic
                                           else real_scene(args, scene))
            for label, extra in variants:
                aucs = list(pool.map(lambda seed: run_seed(scene, database, images, reference, label, extra, seed),
                                     seeds))
                successes = sum(a >= target for a in aucs)
                results.setdefault(scene, {})[label] = aucs
                lines.append(f"| {scene} | {label}{(' `' + extra + '`') if extra else ''} | "
                             f"{', '.join(f'{a:.1f}' for a in aucs)} | {successes} of {len(aucs)} |")
    (base / "results.json").write_text(json.dumps(results, indent=2) + "\n")
    bs.write_fragment(args.fragment or ("seed_sweep_synthetic" if synthetic else "seed_sweep"), lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
