#!/usr/bin/env python3
"""How much GLOBAL_PRUNED's result on the real ambiguous scenes depends on the seed (Louvain's
visiting order, the RANSAC samples, every engine run). Writes bench/sections/seed_sweep.md.

Input: the exhaustive databases and sequential references bench/ambiguous_bench.py prepared in
its --work folder (run it first, --prepare_only is enough). For every scene and every seed in
--seeds, `prunesfm run --engine GLOBAL_PRUNED --seed S --num_threads --threads` with each
--variant's extra arguments (default: the defaults, and session 14's pruning: the inlier-weighted
partition and the triangle vote), scored by `prunesfm evaluate` against the reference.
Python 3 standard library only.
"""

import json
import shlex
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_support as bs  # noqa: E402
import run_benchmarks as rb  # noqa: E402

DEFAULT_VARIANTS = [
    "defaults=",
    "session 14 (inlier partition, triangle vote)=--prune_partition_weight inliers --prune_link_trust match_coverage "
    "--prune_loop_method triangle_vote",
]


def main():
    parser = bs.argument_parser(__doc__, "/tmp/prunesfm-seed-sweep")
    parser.add_argument("--ambiguous_work", default="/tmp/prunesfm-bench-ambiguous",
                        help="bench/ambiguous_bench.py's --work (exhaustive.db and reference/ per scene)")
    parser.add_argument("--scenes", default="books,street")
    parser.add_argument("--seeds", default="0-9", help="a range A-B or a comma-separated list")
    parser.add_argument("--variant", action="append", default=[], metavar="LABEL=ARGS",
                        help="a row LABEL with these extra `prunesfm run` arguments (repeatable)")
    parser.add_argument("--target", type=float, default=90.0, help="AUC@5 counted as a success")
    args = parser.parse_args()
    prunesfm = str(Path(args.prunesfm).resolve()) if args.prunesfm else str(rb.find_prunesfm(None))
    if "-" in args.seeds:
        first, last = (int(x) for x in args.seeds.split("-"))
        seeds = list(range(first, last + 1))
    else:
        seeds = [int(x) for x in args.seeds.split(",")]
    variants = [v.split("=", 1) for v in (args.variant or DEFAULT_VARIANTS)]
    lines = bs.header_lines("Seed sweep on the real ambiguous scenes", sys.argv, prunesfm)
    lines += [f"GLOBAL_PRUNED with `--seed S --num_threads {args.threads}` for S in {seeds[0]}..{seeds[-1]} on each "
              "scene's exhaustive COLMAP database, AUC@5 against the sequential reference "
              f"(bench/ambiguous_bench.py); success = AUC@5 ≥ {args.target:g}.", "",
              "| scene | pruning | AUC@5 per seed | successes |", "|---|---|---|---|"]
    results = {}
    for scene in [s for s in args.scenes.split(",") if s]:
        prepared = Path(args.ambiguous_work) / scene
        database, reference = prepared / "exhaustive.db", prepared / "reference" / "sparse" / "0"
        images = Path(args.shared) / "datasets" / "ambiguous" / scene / "images"
        if not database.is_file() or not reference.is_dir():
            sys.exit(f"seed_sweep_bench: {database} or {reference} missing (run bench/ambiguous_bench.py first)")
        for label, extra in variants:
            aucs = []
            for seed in seeds:
                out = Path(args.work) / scene / f"{label.split()[0]}_{seed}"
                out.mkdir(parents=True, exist_ok=True)
                db = out / "database.db"
                rb.copy_database(database, db)
                argv = [prunesfm, "run", "--database", db, "--image_path", images, "--output_path", out / "result",
                        "--engine", "GLOBAL_PRUNED", "--seed", seed, "--num_threads", args.threads,
                        *shlex.split(extra)]
                stage = rb.run_stage("run", argv, out / "run.log", args.timeout)
                model = out / "result" / "sparse" / "0" if stage["rc"] == 0 else None
                result = bs.evaluate_against(prunesfm, model, reference, out, str(args.seed), args.timeout)
                aucs.append(result["auc"]["5"])
                print(f"{scene} {label} seed {seed}: AUC@5 {aucs[-1]:.1f}", flush=True)
            successes = sum(a >= args.target for a in aucs)
            results.setdefault(scene, {})[label] = aucs
            lines.append(f"| {scene} | {label}{(' `' + extra + '`') if extra else ''} | "
                         f"{', '.join(f'{a:.1f}' for a in aucs)} | {successes} of {len(aucs)} |")
    (Path(args.work) / "results.json").write_text(json.dumps(results, indent=2) + "\n")
    bs.write_fragment("seed_sweep", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
