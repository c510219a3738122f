#!/usr/bin/env python3
"""The image front end (issue 6) against COLMAP 3.8, from the photos: `prunesfm run IMAGES OUT`
(init + SIFT + matching + verification, then the engine) and `colmap feature_extractor` +
`exhaustive_matcher` (CPU, the flags of bench/run_benchmarks.py) on the same images, then the
accuracy of our models from images against the ground truth.

Speed: our init + features + match stages against COLMAP's feature_extractor + exhaustive_matcher,
with the verified-inlier counts of both (ours: matches.e.bin; COLMAP: two_view_geometries rows
with at least one inlier). COLMAP is re-measured in this run on the scenes of --colmap_scenes; on
the others its times are taken from bench/results.json (the run that built the database in
bench/run_benchmarks.py's --work folder, whose inlier counts are read here) and marked so; the
ratio that makes the claim is the one measured in this run.

Intrinsics: Strecha scenes start from their K.txt (`--k_file`), the temple ring from the K of its
gt_cameras.txt (written to a K file in --work), Sceaux Castle and the ambiguous scenes from EXIF.
Writes bench/sections/frontend.md. Python 3 standard library only.
"""

import json
import re
import sqlite3
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_support as bs  # noqa: E402

# scene -> (images below shared/datasets, ground truth or None, intrinsics: "K.txt", "gt", "exif")
SCENES = {
    "templeSparseRing": ("middlebury/templeSparseRing", "gt"),
    "fountain-P11": ("strecha/fountain-P11", "K.txt"),
    "Herz-Jesus-P8": ("strecha/Herz-Jesus-P8", "K.txt"),
    "castle-P19": ("strecha/castle-P19", "K.txt"),
    "sceaux_castle": ("sceaux_castle", "exif"),
    "books": ("ambiguous/books", "exif"),
    "street": ("ambiguous/street", "exif"),
}
TARGETS = {"fountain-P11": ("3", 95.0), "Herz-Jesus-P8": ("3", 95.0), "castle-P19": ("5", 90.0),
           "templeSparseRing": ("5", 90.0)}


def k_file_from_gt(gt, path):
    """The K of the first camera of a gt_cameras.txt, as a K file."""
    for line in Path(gt).read_text().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        f = line.split()
        fx, fy, cx, cy, skew = f[3], f[4], f[5], f[6], f[7]
        path.write_text(f"{fx} {skew} {cx}\n0 {fy} {cy}\n0 0 1\n")
        return path
    raise SystemExit(f"{gt}: no camera")


def colmap_inliers(db):
    with sqlite3.connect(f"file:{db}?mode=ro", uri=True) as c:
        rows = c.execute("SELECT COUNT(*), COALESCE(SUM(rows), 0) FROM two_view_geometries WHERE rows > 0").fetchone()
    return {"pairs": rows[0], "inliers": rows[1]}


def ours_inliers(log):
    m = re.search(r"(\d+) verified \((\d+) inliers\)", Path(log).read_text(errors="replace"))
    return {"pairs": int(m.group(1)), "inliers": int(m.group(2))} if m else None


def carried_colmap(scene):
    """COLMAP's feature + match seconds of bench/results.json and the database they built."""
    results = json.loads((bs.REPO / "bench" / "results.json").read_text())
    for row in results["results"]:
        if row["scene"] == scene and row["engine"] == "colmap":
            stages = {s["name"]: s for s in row["stages"]}
            if "features" in stages and "match" in stages:
                db = Path(stages["features"]["log"]).parent / "database.db"
                return {"features": stages["features"]["seconds"], "match": stages["match"]["seconds"],
                        "date": stages["features"].get("carried", "earlier run"), "db": db}
    return None


def run_colmap_front_end(args, images, out):
    """COLMAP's feature_extractor + exhaustive_matcher on the images, measured in this run."""
    db = out / "database.db"
    out.mkdir(parents=True, exist_ok=True)
    db.unlink(missing_ok=True)
    features = bs.colmap_features("colmap features", args.colmap, db, images, out / "features.log", args.threads,
                                  "3200", args.timeout)
    match = bs.colmap_match("colmap match", args.colmap, ["exhaustive_matcher"], db, out / "match.log", args.threads,
                            args.timeout)
    if features["rc"] != 0 or match["rc"] != 0:
        return None
    return {"features": features["seconds"], "match": match["seconds"], "date": None, "db": db,
            "peak_mb": max(features["peak_mb"], match["peak_mb"])}


def run_log(out, engine):
    """Beside the run folder, not in it: prunesfm writes only into an empty folder or its own output."""
    return out.parent / f"{out.name}.run_{engine}.log"


def run_ours_from_images(args, prunesfm, images, intrinsics, out, engine, force):
    """`prunesfm run IMAGES OUT`: our front end and the engine; returns (stage, timings.json or None)."""
    argv = [prunesfm, "run", images, out, "--engine", engine, "--num_threads", args.threads, "--solver_threads", args.threads,
            "--seed", args.seed]
    if intrinsics is not None:
        argv += ["--k_file", intrinsics]
    if force:
        argv.append("--force")
    stage = bs.run_stage(f"prunesfm run {engine}", argv, run_log(out, engine), args.timeout)
    timings = json.loads((out / "timings.json").read_text()) if stage["rc"] == 0 else None
    return stage, timings


def main():
    parser = bs.argument_parser(__doc__, "/tmp/prunesfm-frontend-bench")
    parser.add_argument("--scenes", default=",".join(SCENES), help="scenes to run")
    parser.add_argument("--colmap_scenes", default="templeSparseRing",
                        help="scenes on which COLMAP's extraction and matching are re-measured in this run")
    args = parser.parse_args()
    prunesfm = str(Path(bs.find_prunesfm(args.prunesfm)).resolve())
    shared = Path(args.shared) / "datasets"
    work = Path(args.work)
    lines = bs.header_lines("Image front end: from photos (bench/frontend_bench.py)", sys.argv, prunesfm, args.colmap)
    speed_rows, accuracy_rows = [], []
    for scene in args.scenes.split(","):
        folder, intrinsics_kind = SCENES[scene]
        images = shared / folder / "images"
        gt = shared / folder / "gt_cameras.txt"
        out = work / scene / "ours"
        out.mkdir(parents=True, exist_ok=True)
        print(f"{scene}:", flush=True)
        k_file = {"K.txt": shared / folder / "K.txt", "gt": None, "exif": None}[intrinsics_kind]
        if intrinsics_kind == "gt":
            k_file = k_file_from_gt(gt, work / scene / "K_from_gt.txt")
        engines = ["GLOBAL", "GLOBAL_PRUNED"] if scene in ("castle-P19", "books", "street") else ["GLOBAL"]
        for n, engine in enumerate(engines):
            stage, timings = run_ours_from_images(args, prunesfm, images, k_file, out, engine, force=(n == 0))
            row = {"scene": scene, "engine": engine, "intrinsics": intrinsics_kind, "rc": stage["rc"],
                   "seconds": stage["seconds"], "peak_mb": stage["peak_mb"]}
            if timings:
                row["stages"] = {s["stage"]: s["seconds"] for s in timings["stages"]}
                row["registered"] = timings["counts"]["registered_views"]
                row["views"] = timings["counts"]["views"]
            if gt.is_file() and stage["rc"] == 0:
                row["eval"] = bs.evaluate_against(prunesfm, out / "sparse" / "0", gt, out / f"eval_{engine}",
                                                  args.seed, args.timeout)
            accuracy_rows.append(row)
            if n == 0 and timings and (scene in args.colmap_scenes.split(",") or carried_colmap(scene)):
                front = sum(row["stages"].get(s, 0.0) for s in ("init", "features", "match"))
                speed = {"scene": scene, "ours": row["stages"], "ours_front": front,
                         "ours_inliers": ours_inliers(run_log(out, engine)), "ours_peak_mb": stage["peak_mb"]}
                colmap = run_colmap_front_end(args, images, work / scene / "colmap") \
                    if scene in args.colmap_scenes.split(",") else carried_colmap(scene)
                if colmap:
                    speed["colmap"] = colmap
                    speed["colmap_inliers"] = colmap_inliers(colmap["db"]) if Path(colmap["db"]).is_file() else None
                speed_rows.append(speed)

    lines += ["Speed: our `init` + `features` + `match` stages (timings.json of `prunesfm run IMAGES OUT "
              f"--num_threads {args.threads}` with its defaults: listing, OpenCV SIFT with at most 12288 descriptors on "
              "images downscaled to at most 1600 px, AUTO matching of every pair (brute force through BLAS up to ~10000 "
              "features per image, FLANN above), ratio 0.8, mutual check, OpenGV 5-point verification) against "
              f"`colmap feature_extractor` + `exhaustive_matcher` (CPU, {args.threads} threads, one SIMPLE_RADIAL "
              "camera, max image size 3200, COLMAP's own geometric verification inside the matcher). Inliers: "
              "sum over verified pairs (ours: matches.e.bin; COLMAP: two_view_geometries with rows > 0).", "",
              "| scene | ours: init + features + match (s) | ours: verified pairs / inliers | COLMAP: features + match (s) "
              "| COLMAP: verified pairs / inliers | speed-up |", "|---|---|---|---|---|---|"]
    for s in speed_rows:
        o = s["ours"]
        c = s.get("colmap")
        oi, ci = s.get("ours_inliers") or {}, s.get("colmap_inliers") or {}
        if c:
            when = "this run" if c["date"] is None else f"carried from {c['date']}, not re-measured"
            colmap_cell = f"{c['features']:.1f} + {c['match']:.1f} = {c['features'] + c['match']:.1f} ({when})"
            ratio = f"**{(c['features'] + c['match']) / s['ours_front']:.1f}×**"
        else:
            colmap_cell, ratio = "–", "–"
        lines.append(f"| {s['scene']} | {o.get('init', 0):.1f} + {o.get('features', 0):.1f} + {o.get('match', 0):.1f} = "
                     f"{s['ours_front']:.1f} | {oi.get('pairs', '?')} / {oi.get('inliers', '?')} | {colmap_cell} | "
                     f"{ci.get('pairs', '?')} / {ci.get('inliers', '?')} | {ratio} |")
    lines += ["", "Accuracy from the photos (`prunesfm evaluate` against gt_cameras.txt; intrinsics: K.txt = "
              "`--k_file` with the dataset's K, gt = the K of gt_cameras.txt as a K file, exif = focal from EXIF; "
              "the principal point is never refined):", "",
              "| scene | engine | intrinsics | registered | AUC@3 | AUC@5 | AUC@10 | target | run (s) |",
              "|---|---|---|---|---|---|---|---|---|"]
    for r in accuracy_rows:
        e = r.get("eval")
        target = TARGETS.get(r["scene"])
        verdict = "–"
        if target and e and (r["engine"] == "GLOBAL_PRUNED" or r["scene"] != "castle-P19"):
            value = e["auc"][target[0]]
            verdict = f"AUC@{target[0]} ≥ {target[1]:g}: {'holds' if value >= target[1] else 'not met'}"
        elif not target and r["rc"] == 0:
            verdict = f"one model: {'yes' if r.get('registered') == r.get('views') else 'no'}"
        registered = f"{r.get('registered', 0)}/{r.get('views', '?')}"
        aucs = [f"{e['auc'][t]:.1f}" for t in ("3", "5", "10")] if e else ["–"] * 3
        lines.append(f"| {r['scene']} | {r['engine']} | {r['intrinsics']} | {registered} | {' | '.join(aucs)} | "
                     f"{verdict} | {r['seconds']:.1f} |")
    lines += ["", "Registered = views in the model / views listed (images that decode); the engine keeps the "
              "largest connected component of the verified view graph, so a model with every view is one model."]
    (work / "frontend_bench.json").write_text(json.dumps({"speed": speed_rows, "accuracy": accuracy_rows},
                                                         indent=2, default=str))
    bs.write_fragment("frontend", lines)


if __name__ == "__main__":
    main()
