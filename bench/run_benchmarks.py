#!/usr/bin/env python3
"""PruneSfM benchmark runner (issue 3). Python 3 standard library only.

Runs every engine (PruneSfM's GLOBAL and GLOBAL_PRUNED, and Debian's COLMAP 3.8 as a peer) on
the synthetic scenes of `prunesfm synth` and on the datasets of ../shared/datasets that have
ground truth, and writes docs/benchmarks.md and the pages it links (plus a JSON file with the same
numbers): pose AUC @3/5/10 deg, registered images, wall time per stage, peak memory, time relative
to COLMAP.

Every stage is a separate child process started with posix_spawn and reaped with wait4, so its
wall time and its own peak RSS (ru_maxrss of that child and the descendants it waited for) are
measured without /usr/bin/time. See bench/README.md for what each stage contains.
"""

import argparse
import fnmatch
import json
import math
import os
import re
import shlex
import sqlite3
import struct
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_colmap as bc  # noqa: E402
import bench_support as bs  # noqa: E402

SMALL_SYNTHETIC = ["orbit_symmetric", "street", "courtyard", "clean"]
LARGE_SYNTHETIC = "sequential_large"
# Datasets with ground truth: scene name -> folder under <shared>/datasets.
DATASETS = {
    "fountain-P11": "strecha/fountain-P11",
    "Herz-Jesus-P8": "strecha/Herz-Jesus-P8",
    "castle-P19": "strecha/castle-P19",
    "templeSparseRing": "middlebury/templeSparseRing",
}
OUR_ENGINES = ["GLOBAL", "GLOBAL_PRUNED"]
ALL_ENGINES = OUR_ENGINES + ["colmap"]
SMOKE_SYNTH_ARGS = ["--num_views", "8"]


# ----------------------------------------------------------------------------------------------
# prunesfm, evaluation, databases (the rest is in bench_support.py and bench_colmap.py)
# ----------------------------------------------------------------------------------------------

def prunesfm_capabilities(prunesfm):
    """Which of our engines can run: `prunesfm --help` must list the `run` subcommand."""
    help_text = subprocess.run([str(prunesfm), "--help"], capture_output=True, text=True).stdout
    has_run = re.search(r"^\s+run\s", help_text, re.MULTILINE) is not None
    run_help = ""
    if has_run:
        run_help = subprocess.run([str(prunesfm), "run", "--help_all"], capture_output=True, text=True).stdout
    refine = sorted(set(re.findall(r"--(?:refine_[a-z_]+|[a-z_]*focal[a-z_]*)", run_help)))
    return {"run": has_run, "num_threads": "--num_threads" in run_help, "intrinsics_options": refine}


def count_gt_images(gt_path):
    return sum(1 for l in Path(gt_path).read_text().splitlines() if l.strip() and not l.startswith("#"))


def evaluate(prunesfm, model_dir, gt_path, out_dir, seed, timeout_s):
    """Evaluates a model; no model counts as nothing registered (every pair failed: AUC 0)."""
    num_gt = count_gt_images(gt_path)
    result = {"registered": 0, "num_gt": num_gt, "auc": {str(t): 0.0 for t in bs.THRESHOLDS},
              "median_rotation_error_deg": None, "median_position_error": None}
    if model_dir is None:
        return result, None
    report, stage = bs.evaluate_model(prunesfm, model_dir, gt_path, out_dir, seed, timeout_s)
    if report is None:
        # A model sharing no image name with the ground truth is also "nothing registered".
        return result, stage
    result["registered"] = report["num_registered_images"]
    result["num_gt"] = report["num_ground_truth_images"]
    result["auc"].update(bs.report_auc(report))
    if report.get("alignment"):
        result["median_rotation_error_deg"] = round(report["alignment"]["median_rotation_error_deg"], 3)
        result["median_position_error"] = report["alignment"]["median_position_error"]
    return result, stage


def colmap_camera_summary(db_path):
    with sqlite3.connect(str(db_path)) as db:
        rows = list(db.execute("SELECT model, width, height, prior_focal_length FROM cameras"))
    return {"num_cameras": len(rows), "prior_focal_from_exif": any(r[3] for r in rows)}


# ----------------------------------------------------------------------------------------------
# Scenes
# ----------------------------------------------------------------------------------------------

def prepare_synthetic(args, prunesfm, scene, num_views, work):
    """`prunesfm synth`: features + putative matches (database.db) + ground truth."""
    key = scene if num_views is None else f"{scene}@{num_views}"
    out = work / key
    extra = SMOKE_SYNTH_ARGS if args.smoke else []
    if num_views is not None:
        extra = ["--num_views", num_views]
    synth_args = ["--scene", scene, "--seed", str(args.seed), *map(str, extra)]
    previous = args.previous_meta.get("scenes", {}).get(key) if args.reuse else None
    gt = out / "ground_truth" / "gt_cameras.txt"
    if (previous and previous.get("synth_args", synth_args) == synth_args and (out / "database.db").is_file()
            and gt.is_file()):
        # --reuse: the database `synth` wrote in the earlier run (same arguments) is still in --work.
        (out / "images").mkdir(exist_ok=True)
        prep = [dict(s, carried=s.get("carried") or args.previous_date) for s in previous.get("prep", [])]
        print(f"  [synth] reused {out / 'database.db'} (from the run of {args.previous_date})", flush=True)
        return {"key": key, "kind": "synthetic", "database": out / "database.db", "images": out / "images",
                "gt": gt, "prep": prep, "shared_stages": [], "ok": True, "error": None,
                "synth_args": synth_args, "reused": True}
    stage = bs.synth_stage(prunesfm, scene, args.seed, out, work / f"{key}.synth.log", args.timeout, extra, args.threads)
    return {"key": key, "kind": "synthetic", "database": out / "database.db", "images": out / "images",
            "gt": out / "ground_truth" / "gt_cameras.txt", "prep": [stage], "shared_stages": [],
            "ok": stage["rc"] == 0, "error": stage.get("error"), "synth_args": synth_args, "reused": False}


def prepare_dataset(args, scene, colmap, work):
    """Real images: COLMAP's feature extraction and exhaustive matching, shared by every engine
    (PruneSfM has no feature extraction of its own yet)."""
    folder = Path(args.shared) / "datasets" / DATASETS[scene]
    images, gt = folder / "images", folder / "gt_cameras.txt"
    info = {"key": scene, "kind": "dataset", "images": images, "gt": gt, "prep": [], "shared_stages": [],
            "ok": False, "error": None}
    if not images.is_dir() or not gt.is_file():
        info["error"] = f"{folder} has no images/ or gt_cameras.txt"
        return info
    if not colmap:
        info["error"] = "needs colmap for feature extraction and matching (not installed)"
        return info
    out = work / scene / "shared"
    db = out / "database.db"
    previous = args.previous_meta.get("scenes", {}).get(scene) if args.reuse else None
    if previous and previous.get("shared_stages") and bc.num_verified_pairs(db) > 0:
        # --reuse: COLMAP's features and verified matches of the earlier run are still in --work; their
        # stage times are those measured then (marked as carried in the report).
        info["shared_stages"] = [dict(s, carried=s.get("carried") or args.previous_date) for s in previous["shared_stages"]]
        info["camera"] = colmap_camera_summary(db)
        info["database"] = db
        info["ok"] = True
        info["reused"] = True
        print(f"  [features, match] reused {db} (from the run of {args.previous_date})", flush=True)
        return info
    bs.fresh_folder(out)
    extract = bs.colmap_features("features", colmap, db, images, out / "features.log", args.threads,
                                 args.max_image_size, args.timeout)
    info["shared_stages"].append(extract)
    if extract["rc"] != 0:
        info["error"] = "feature_extractor: " + extract.get("error", "")
        return info
    info["camera"] = colmap_camera_summary(db)
    match = bs.colmap_match("match", colmap, ["exhaustive_matcher"], db, out / "match.log", args.threads, args.timeout)
    info["shared_stages"].append(match)
    if match["rc"] != 0:
        info["error"] = "exhaustive_matcher: " + match.get("error", "")
        return info
    info["database"] = db
    info["ok"] = True
    return info


# ----------------------------------------------------------------------------------------------
# Engines
# ----------------------------------------------------------------------------------------------

def run_colmap_on_scene(args, colmap, scene, work):
    """The colmap row of a scene: on its own database copy, COLMAP's verification of the synthetic
    putative matches (`match`; with --reuse the earlier run's verified copy), then its mapper."""
    out = work / scene["key"] / "colmap"
    verified = work / scene["key"] / "colmap_verified.db"  # COLMAP's verified synthetic database, kept for --reuse
    previous_match = None
    if args.reuse and scene["kind"] == "synthetic" and scene.get("reused"):
        previous_row = next((r for r in args.previous_rows if r["scene"] == scene["key"] and r["engine"] == "colmap"
                             and r.get("status") == "ok" and not r.get("carried_from")), None)
        previous_match = next((s for s in (previous_row or {}).get("stages", []) if s["name"] == "match"), None)
        if previous_match and bc.num_verified_pairs(verified) == 0 and bc.num_verified_pairs(out / "database.db") > 0:
            bc.copy_database(out / "database.db", verified)  # the earlier run's copy, verified by its `match`
        if bc.num_verified_pairs(verified) == 0:
            previous_match = None
    bs.fresh_folder(out)
    db = out / "database.db"
    stages = []
    t = str(args.threads)
    if previous_match is not None:
        # --reuse: only the mapper is timed again, on the database COLMAP verified in the earlier run.
        bc.copy_database(verified, db)
        stages.append(dict(previous_match, carried=previous_match.get("carried") or args.previous_date))
        print(f"  [match] reused {verified} (from the run of {args.previous_date})", flush=True)
    else:
        bc.copy_database(scene["database"], db)
    if scene["kind"] == "synthetic" and previous_match is None:
        # The database holds putative matches but no two-view geometries. COLMAP 3.8's matchers keep
        # the matches of a pair that already has them and only verify them geometrically.
        stages.append(bs.verify_synthetic_matches("match", colmap, db, out / "pairs.txt", out / "match.log", t,
                                                  args.timeout))
        if stages[-1]["rc"] != 0:
            return stages, None, stages[-1]["error"]
        bc.copy_database(db, verified)
    stage, model = bs.colmap_mapper(colmap, db, scene["images"], out, t, args.timeout, scene["kind"] == "synthetic")
    stages.append(stage)
    _, num_models = bc.largest_model(out / "sparse")
    note = None if num_models <= 1 else f"{num_models} models, the largest evaluated"
    if stages[-1]["rc"] != 0:
        note = stages[-1]["error"]
    return stages, model, note


def set_known_intrinsics(db_path, gt_path):
    """--known_k: every camera of the database copy becomes PINHOLE with the ground truth's K (fx fy cx
    cy of gt_cameras.txt's first camera: Strecha's K.txt, Middlebury's *_par.txt; one K per dataset),
    no distortion, i.e. "start from K.txt" (../shared/datasets/README.md)."""
    first = next(l.split() for l in Path(gt_path).read_text().splitlines() if l.strip() and not l.startswith("#"))
    fx, fy, cx, cy = map(float, first[3:7])
    with sqlite3.connect(str(db_path)) as db:
        db.execute("UPDATE cameras SET model = 1, params = ?, prior_focal_length = 1",
                   (struct.pack("<4d", fx, fy, cx, cy),))
    db.close()
    return fx, fy, cx, cy


def run_ours_on_scene(args, prunesfm, caps, engine, scene, work):
    """A row of ours (an engine or a --variant) on a scene: `prunesfm run` on its own database copy
    (with the known K for --known_k), the breakdown of its timings.json, the largest model."""
    label, engine, extra = engine, *args.variants.get(engine, (engine, []))
    out = work / scene["key"] / label
    bs.fresh_folder(out)
    db = out / "database.db"
    bc.copy_database(scene["database"], db)
    if label in args.known_k:
        set_known_intrinsics(db, scene["gt"])
    result_dir = out / "result"
    options = (["--num_threads", args.threads] if caps["num_threads"] else []) + extra
    stage = bs.run_ours_on_database(prunesfm, db, scene["images"], result_dir, engine, out / "run.log", args.timeout,
                                    options)
    # Optional: the engine's own breakdown in result/timings.json, "stages" either {"name": seconds, ...}
    # or [{"stage": name, "seconds": s}, ...] (what `prunesfm run` writes).
    timings = result_dir / "timings.json"
    if timings.is_file():
        try:
            listed = json.loads(timings.read_text())["stages"]
            if isinstance(listed, list):
                listed = {e["stage"]: e["seconds"] for e in listed}
            stage["breakdown"] = {k: round(float(v), 2) for k, v in listed.items()}
        except (ValueError, KeyError, TypeError, AttributeError):
            pass
    model, num_models = bc.largest_model(result_dir / "sparse")
    note = stage.get("error") or (None if num_models <= 1 else f"{num_models} models, the largest evaluated")
    return [stage], model, note


# ----------------------------------------------------------------------------------------------
# Report
# ----------------------------------------------------------------------------------------------

def fmt(value, digits=1):
    return "–" if value is None else f"{value:.{digits}f}"


def peak_cell(row):
    """The row's peak; when shared stages dominate it, also the engine's own stages' peak."""
    own = [s["peak_mb"] for s in row.get("stages", []) if not s.get("shared")]
    if own and any(s.get("shared") for s in row.get("stages", [])):
        return f"{row['peak_mb']:.0f} (own {max(own):.0f})"
    return f"{row['peak_mb']:.0f}"


def engine_order(rows):
    """Our engines, then their variants (`--variant`), then COLMAP."""
    names = []
    for e in OUR_ENGINES + [r["engine"] for r in rows] + ["colmap"]:
        if e not in names and e != "colmap":
            names.append(e)
    return [e for e in names + ["colmap"] if any(r["engine"] == e for r in rows)]


def stage_cell(row):
    parts = []
    for s in row["stages"]:
        text = f"{s['name']}{'*' if s.get('shared') else ''}{'†' if s.get('carried') else ''} {s['seconds']:.1f}"
        if s.get("breakdown"):
            text += " (" + ", ".join(f"{k} {v:.1f}" for k, v in s["breakdown"].items()) + ")"
        parts.append(text)
    return " · ".join(parts) if parts else "–"


NOT_IMPLEMENTED = "not implemented yet"


def row_status(row):
    """A failed run whose error says the engine is not implemented is reported as such."""
    status = row.get("status", "ok")
    if status == "failed" and NOT_IMPLEMENTED in (row.get("note") or ""):
        return NOT_IMPLEMENTED
    return status


def fold_verdict(auc10):
    if auc10 is None:
        return None
    if auc10 >= 90:
        return "high"
    if auc10 < 50:
        return "low"
    return "partial"


REPORT = bs.REPO / "docs" / "benchmarks.md"
LARGE_REPORT = bs.REPO / "docs" / "benchmarks_large.md"
# The pages of the report in docs/ (none over about 400 lines): file, title, the fragments of
# bench/sections it holds (name patterns, in this order; a fragment goes to the first page with a
# pattern for it, so a new script's fragment lands on the last page). The first page is
# docs/benchmarks.md: the run's header, the index and the summary tables before its fragments;
# the tables of each scene of the run open the last page.
REPORT_PAGES = [
    ("benchmarks.md", "Benchmarks", ["families", "ambiguous", "seed_sweep"]),
    ("benchmarks_ablation.md", "Benchmarks: ablations of the pruning",
     ["pruning_ablation*", "families_leave_one_out", "families_reverify"]),
    ("benchmarks_pipeline.md",
     "Benchmarks: each fixed scene, the front end, export, the prune filter, hostile inputs, cost and scaling",
     ["frontend", "export", "prune_filter", "hostile_inputs", "pruning_cost", "scaling", "*"]),
]


def section_fragments():
    """The sections other benchmark scripts generate (bench/sections/*.md, one per script, each
    saying its own command and date), by page of REPORT_PAGES: {file: [(title, lines)]}, so that
    the pages in docs/ hold every number."""
    pages = {name: [] for name, _, _ in REPORT_PAGES}
    for fragment in sorted(bs.SECTIONS_DIR.glob("*.md")):
        text = fragment.read_text().rstrip("\n").split("\n")
        lines = [f"<!-- from bench/sections/{fragment.name} (regenerated by its own script) -->"] + text + [""]
        title = next((t[3:] for t in text if t.startswith("## ")), fragment.stem)
        for name, _, patterns in REPORT_PAGES:
            rank = next((i for i, p in enumerate(patterns) if fnmatch.fnmatchcase(fragment.stem, p)), None)
            if rank is not None:
                pages[name].append((rank, title, lines))
                break
    return {name: [(title, lines) for _, title, lines in sorted(found, key=lambda f: f[0])]
            for name, found in pages.items()}


def page_lines(header, summary, per_scene):
    """docs/benchmarks.md and the pages it links: {file: lines}."""
    fragments = section_fragments()
    main, *others = REPORT_PAGES
    pages = {}
    for name, title, _ in others:
        lines = [f"# {title}", "",
                 "Part of the benchmark report: [benchmarks.md](benchmarks.md) has the index of its pages and how "
                 "they are regenerated (do not edit by hand). Each section from `bench/sections/` states the command "
                 "that measured it."]
        if name == others[-1][0]:
            lines[-1] += (" The tables of each scene come from the run described at the top of "
                          "[benchmarks.md](benchmarks.md) (command, machine, the columns, **†** = carried over "
                          "from an earlier run).")
            lines += [""] + per_scene
        else:
            lines.append("")
        for _, fragment in fragments[name]:
            lines += fragment
        pages[name] = lines
    index = ["## Pages", "",
             "The report is this page and the pages below, all rewritten from `bench/results.json`, "
             "`bench/results_large.json` and the fragments `bench/sections/*.md` by "
             "`python3 bench/run_benchmarks.py --rewrite_report` (which runs nothing); `bench/README.md` says which "
             "script measures what.", "",
             "- this page: the run's summary tables, then"]
    index += [f"  - {t}" for t, _ in fragments[main[0]]]
    for name, _, _ in others:
        index.append(f"- [{name}]({name}):")
        if name == others[-1][0]:
            index.append("  - the tables of each scene of the run: " + ", ".join(
                line[3:] for line in per_scene if line.startswith("## ")))
        index += [f"  - {t}" for t, _ in fragments[name]]
    index.append(f"- [{LARGE_REPORT.name}]({LARGE_REPORT.name}): the report of the `--large` run "
                 "(`bench/results_large.json`), each view count's table")
    index.append("")
    pages[main[0]] = header + index + summary + [line for _, lines in fragments[main[0]] for line in lines]
    return pages


def write_text(path, lines):
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text("\n".join(lines) + "\n")
    tmp.replace(path)


def write_markdown(path, meta, rows, scenes):
    by_scene = {}
    for row in rows:
        by_scene.setdefault(row["scene"], []).append(row)
    engines = engine_order(rows)
    L = []
    L.append("# Benchmarks")
    L.append("")
    L.append("Generated by `bench/run_benchmarks.py` (do not edit by hand; how to rerun and what every stage "
             "contains: `bench/README.md`). Every number below comes from the run described here"
             + (", or, where marked †, from the earlier run(s) it merged (`--merge`, `--reuse`; dates below)."
                if meta.get("merged_from") or any(r.get("carried_from") for r in rows) else "."))
    L.append("")
    m = meta["machine"]
    L.append(f"- Command: `{meta['command']}`")
    L.append(f"- Date: {m['date']}; git commit `{m['git_commit']}`")
    L.append(f"- Machine: {m['nproc']} cores ({m['cpu']}), {m['mem_gb']} GB RAM, Linux {m['kernel']}; "
             f"load average at start {m['loadavg_start']} (the machine is shared: absolute seconds are noisy, "
             f"compare the ratio column)")
    L.append(f"- prunesfm: `{meta['prunesfm']}` (`run` subcommand: {'yes' if meta['prunesfm_run'] else 'no'})")
    L.append(f"- Peer: {meta['colmap_version'] or 'colmap not installed'}; CPU SIFT, "
             f"{meta['settings']['threads']} threads for every tool; real images: one shared "
             f"`{bs.COLMAP_CAMERA_MODEL}` camera per dataset (`--ImageReader.single_camera 1`), "
             f"`--SiftExtraction.max_image_size {meta['settings']['max_image_size']}`, principal point not refined "
             f"(COLMAP's default), K not given (focal from EXIF when present, else COLMAP's 1.2·max(w, h) prior)")
    L.append(f"- Seed {meta['settings']['seed']} (synthetic scenes and the evaluation's alignment RANSAC)")
    L.append("")
    L.append("Columns: **registered** = images of the evaluated model (the largest one) / ground-truth images; "
             "**AUC@t** = area under the recall curve of pairwise relative pose errors up to t degrees, unregistered "
             "images count as failed pairs (`prunesfm evaluate`, docs/evaluation.md); **rot err** = median "
             "rotation error in degrees after similarity alignment; **stages** = wall seconds per stage (`*` = "
             "stage shared by all engines of the scene and counted in each total); **total** = sum of the "
             "stages; **peak MB** = largest peak RSS of any stage (own = of the engine's own stages, without the shared ones); **× colmap** = total / COLMAP's total on the "
             "same scene (the COLMAP row of the table); **rec × map** = our reconstruction time / COLMAP's "
             "`map` stage on the same scene, the issue's speed target (≤ 0.5) — our reconstruction time is the "
             "`run` stage, minus its `verification` breakdown on synthetic scenes, where `run` verifies the "
             "putative matches itself while COLMAP does that in its `match` stage. Synthetic-scene generation "
             "(`synth`) is input preparation, not counted.")
    L.append("")
    L.append("Real images: every engine reads COLMAP's database of the shared `features*` + `match*` stages "
             "(PruneSfM has no feature extraction yet; their time is counted in every total). Our engines "
             "use its verified two-view geometries (`two_view_geometries`; COLMAP 3.8 stores no relative "
             "pose, so the engine re-estimates each pair's pose from the stored inliers: `verification` in "
             "the breakdown) and COLMAP's `SIMPLE_RADIAL` camera as the initial intrinsics.")
    if meta.get("prunesfm_run") and "prunesfm_run_intrinsics_options" in meta:
        options = meta["prunesfm_run_intrinsics_options"]
        if options:
            L.append(f"`prunesfm run` intrinsics options in this build: {', '.join(f'`{o}`' for o in options)}. "
                     "By default (`--refine_intrinsics AUTO`) a camera whose focal COLMAP only guessed "
                     "(`prior_focal_length` = 0: these images have no EXIF, so every dataset's camera) gets its "
                     "focal calibrated from the fundamental matrices of the verified pairs (kept only when the "
                     "pairs determine it), then focal, k1 and principal point refined in bundle adjustment under "
                     "weak priors (principal point near the centre, k1 near 0; docs/global.md); when "
                     "that moves the focal by more than 5 % the pairs are verified and solved again with the refined "
                     "intrinsics (`first pass` in the breakdown); a camera whose focal the pairs do not determine gets "
                     "a quick solve that finds it first (`focal search`). So the GLOBAL rows **refine the principal point**; "
                     "a `GLOBAL-PP` row, where present, is the same with `--refine_principal_point 0`, a `+K` row "
                     "the engine started from the dataset's known K (`--known_k`: \"start from K.txt\", "
                     "`../shared/datasets/README.md`); COLMAP never gets K and does not refine the principal point.")
        else:
            L.append("`prunesfm run --help` offers no option to refine the focal length or the principal point in "
                     "this build: our engines hold COLMAP's prior camera as given (focal 1.2·max(w, h) when no EXIF, "
                     "principal point at the image centre, ~16 px from the truth on the Strecha sets). A `+K` row, "
                     "where present, is the same engine started from the dataset's known K instead "
                     "(`--known_k`: \"start from K.txt\", `../shared/datasets/README.md`); COLMAP never gets K.")
    L.append("")
    merged = meta.get("merged_from")
    carried_dates = sorted({r["carried_from"] for r in rows if r.get("carried_from")} |
                           {s["carried"] for r in rows for s in r.get("stages", []) if s.get("carried")})
    if carried_dates:
        L.append("**†** = carried over from an earlier run (" + ", ".join(carried_dates) + "), not measured in this "
                 "one: a row marked † in the engine column was not run this time (`--merge`); a stage marked † "
                 "is input preparation whose result this run reused from the work folder (`--reuse`)"
                 + (f"; earlier run: `{merged['command']}`, commit `{merged['git_commit']}`" if merged else "")
                 + ". A ratio comes from one run when both rows carry the same date (both unmarked, or both † "
                 "with the same date); the totals of rows with † stages add the earlier run's seconds.")
        L.append("")
    # Summary
    summary_start = len(L)
    L.append("## Summary: AUC@10 (registered / total)")
    L.append("")
    L.append("| scene | " + " | ".join(engines) + " |")
    L.append("|---|" + "---|" * len(engines))
    for key in scenes:
        cells = []
        for e in engines:
            r = next((r for r in by_scene.get(key, []) if r["engine"] == e), None)
            if r is None:
                cells.append("–")
            elif row_status(r) != "ok":
                cells.append(row_status(r) + (" †" if r.get("carried_from") else ""))
            else:
                cells.append(f"{r['auc']['10']:.1f} ({r['registered']}/{r['num_gt']})"
                             + (" †" if r.get("carried_from") else ""))
        L.append(f"| {key} | " + " | ".join(cells) + " |")
    L.append("")
    # Speed target: our reconstruction time against COLMAP's mapper on the same scene.
    ours = [e for e in engines if e != "colmap"]
    speed = []
    for key in scenes:
        srows = by_scene.get(key, [])
        base = next((r for r in srows if r["engine"] == "colmap" and row_status(r) == "ok"), None)
        base_map = next((s for s in (base or {}).get("stages", []) if s["name"] == "map"), None)
        cells = []
        for e in ours:
            r = next((r for r in srows if r["engine"] == e), None)
            if r is None or row_status(r) != "ok" or r.get("reconstruction_s") is None or not base_map:
                cells.append("–" if r is None or row_status(r) == "ok" else row_status(r))
                continue
            same_run = r.get("carried_from") == base.get("carried_from")
            cells.append(f"{r['reconstruction_s']:.1f} / {base_map['seconds']:.1f} = "
                         f"**{r['reconstruction_s'] / base_map['seconds']:.2f}**" + ("" if same_run else " (two runs)"))
        speed.append(f"| {key} | " + " | ".join(cells) + " |")
    if ours and any("**" in line for line in speed):
        L.append("## Speed: our reconstruction seconds / COLMAP mapper seconds (rec × map, target ≤ 0.5)")
        L.append("")
        L.append("| scene | " + " | ".join(ours) + " |")
        L.append("|---|" + "---|" * len(ours))
        L.extend(speed)
        L.append("")
    # Observations on the duplicate-structure scenes, from the numbers above.
    obs = []
    for key in scenes:
        r = next((r for r in by_scene.get(key, []) if r["engine"] == "colmap" and row_status(r) == "ok"), None)
        if r is None or not any(key.startswith(s) for s in SMALL_SYNTHETIC + [LARGE_SYNTHETIC]):
            continue
        verdict = fold_verdict(r["auc"]["10"])
        if key.startswith("clean"):
            obs.append(f"- `{key}` (control, no twins): COLMAP AUC@10 {r['auc']['10']:.1f} — "
                       + ("as expected, near perfect." if verdict == "high" else "NOT near perfect: check the scene."))
        elif verdict == "high":
            obs.append(f"- `{key}`: COLMAP does **not** fold this scene (AUC@10 {r['auc']['10']:.1f} ≥ 90, "
                       f"{r['registered']}/{r['num_gt']} registered): the duplicate structure is not hard enough "
                       "to mislead an incremental mapper.")
        elif verdict == "low":
            obs.append(f"- `{key}`: COLMAP is misled (AUC@10 {r['auc']['10']:.1f} < 50, "
                       f"{r['registered']}/{r['num_gt']} registered).")
        else:
            obs.append(f"- `{key}`: COLMAP partly misled (50 ≤ AUC@10 {r['auc']['10']:.1f} < 90, "
                       f"{r['registered']}/{r['num_gt']} registered).")
    if obs:
        L.append("Synthetic scenes, COLMAP (thresholds: ≥ 90 not folded, < 50 misled):")
        L.append("")
        L.extend(obs)
        L.append("")
    # Per scene
    per_scene_start = len(L)
    for key in scenes:
        srows = by_scene.get(key, [])
        if not srows:
            continue
        L.append(f"## {key}")
        L.append("")
        info = meta["scenes"].get(key, {})
        if info.get("description"):
            L.append(info["description"])
            L.append("")
        L.append("| engine | registered | AUC@3 | AUC@5 | AUC@10 | rot err (°) | stages (s) | total (s) | peak MB "
                 "| × colmap | rec × map |")
        L.append("|---|---|---|---|---|---|---|---|---|---|---|")
        base = next((r for r in srows if r["engine"] == "colmap" and row_status(r) == "ok"), None)
        engines_here = engine_order(srows)
        for r in sorted(srows, key=lambda r: engines_here.index(r["engine"])):
            name = r["engine"] + (f" † ({r['carried_from']})" if r.get("carried_from") else "")
            if row_status(r) != "ok":
                note = f" ({r['note']})" if r.get("note") else ""
                timing = (f" {stage_cell(r)} | {r['total_s']:.1f} | {r['peak_mb']:.0f} |"
                          if r.get("stages") and row_status(r) != NOT_IMPLEMENTED else " | | |")
                L.append(f"| {name} | {row_status(r)}{note} | | | | |{timing} | |")
                continue
            ratio = "–"
            if base is not None and base["total_s"] > 0:
                ratio = f"{r['total_s'] / base['total_s']:.2f}"
            map_ratio = "–"
            base_map = next((s for s in (base or {}).get("stages", []) if s["name"] == "map"), None)
            if r["engine"] != "colmap" and r.get("reconstruction_s") is not None and base_map and base_map["seconds"] > 0:
                map_ratio = f"{r['reconstruction_s'] / base_map['seconds']:.2f}"
            L.append(f"| {name} | {r['registered']}/{r['num_gt']} | {r['auc']['3']:.1f} | "
                     f"{r['auc']['5']:.1f} | {r['auc']['10']:.1f} | {fmt(r['median_rotation_error_deg'], 2)} | "
                     f"{stage_cell(r)} | {r['total_s']:.1f} | {peak_cell(r)} | {ratio} | {map_ratio} |")
            if r.get("note"):
                L.append(f"|  | note: {r['note']} | | | | | | | | | |")
        L.append("")
    if path.resolve() == REPORT.resolve():
        pages = page_lines(L[:summary_start], L[summary_start:per_scene_start], L[per_scene_start:])
        for name, lines in pages.items():
            write_text(path.parent / name, lines)
        return
    if path.resolve() == LARGE_REPORT.resolve():
        L[2:2] = ["One of the benchmark pages: [benchmarks.md](benchmarks.md) has their index.", ""]
    write_text(path, L)


# ----------------------------------------------------------------------------------------------
# Main
# ----------------------------------------------------------------------------------------------

def merge_previous(args, meta, rows, keys):
    """--merge: the previous file's rows for (scene, engine) pairs this run did not produce."""
    done = {(r["scene"], r["engine"]) for r in rows}
    merged = list(rows)
    for r in args.previous_rows:
        if (r["scene"], r["engine"]) in done:
            continue
        merged.append(dict(r, carried_from=r.get("carried_from") or args.previous_date))
        if r["scene"] not in meta["scenes"]:
            meta["scenes"][r["scene"]] = args.previous_meta.get("scenes", {}).get(r["scene"], {})
    all_keys = sorted(dict.fromkeys(keys + [r["scene"] for r in merged]), key=scene_order)
    return merged, all_keys


def scene_order(key):
    """The report's order of scenes: the canonical ones as listed, then the others by name and view count."""
    canonical = SMALL_SYNTHETIC + list(DATASETS)
    name, _, views = key.partition("@")
    return (canonical.index(key) if key in canonical else len(canonical), name,
            int(views) if views.isdigit() else 0, key)


SCALING_TARGET_VIEWS, SCALING_TARGET_S, SCALING_TARGET_MB = 2000, 300.0, 4096.0


def scaling_section(meta, rows):
    """bench/sections/scaling.md (--large): time and peak memory of each engine against the view
    count, our time per stage, and how each grows (exponent between consecutive sizes)."""
    m = meta["machine"]
    L = ["## Scaling with the number of views (`bench/run_benchmarks.py --large`)", "",
         f"Generated by `{meta['command']}` on {m['date']} at commit `{m['git_commit']}` (`{meta['prunesfm']}`, "
         f"{meta['colmap_version'] or 'no colmap'}); machine: {m['nproc']} cores ({m['cpu']}), {m['mem_gb']} GB RAM, "
         f"load average at start {m['loadavg_start']}, at the end {m.get('loadavg_end', '(run not finished)')} (the "
         "machine is shared by several engineers: a load above the 2 cores stretches every wall time; ratios within "
         f"one run are comparable). Scene `{LARGE_SYNTHETIC}` (`prunesfm synth --scene {LARGE_SYNTHETIC} --num_views "
         "N`: a loop street driven twice, sliding-window + retrieval pairs, 25 % repeated facades), "
         f"{meta['settings']['threads']} threads. **s** = wall seconds of the engine's stages (ours: `prunesfm run`, "
         "which includes verifying the putative matches; COLMAP: matches_importer verification + mapper), **MB** = "
         "peak RSS, **CPU s** = user + system seconds of the process (what the load does not stretch; at most 2 × s "
         "with 2 threads), **exp.** = log(s₂/s₁) / log(N₂/N₁) against the previous size of the same engine (1 = linear); "
         "the last columns are our stages (`timings.json`).", ""]
    ours = [r for r in rows if r.get("status") == "ok" and r["engine"] != "colmap"]
    stage_names = []
    for r in ours:
        for stage in r.get("stages", []):
            for name in stage.get("breakdown", {}):
                if name not in stage_names:
                    stage_names.append(name)
    L.append("| views | engine | registered | AUC@10 | s | CPU s | exp. | MB | " + " | ".join(stage_names) + " |")
    L.append("|---|---|---|---|---|---|---|---|" + "---|" * len(stage_names))
    previous = {}
    for r in sorted(rows, key=lambda r: (int(r["scene"].split("@")[1]), r["engine"])):
        n = int(r["scene"].split("@")[1])
        if r.get("status") != "ok" or not r.get("stages"):
            L.append(f"| {n} | {r['engine']} | {r.get('status')}: {r.get('note') or ''} | | | | | |"
                     + " |" * len(stage_names))
            continue
        seconds = sum(s["seconds"] for s in r["stages"] if not s.get("carried"))
        growth = "–"
        if r["engine"] in previous and previous[r["engine"]][1] > 0 and seconds > 0:
            n0, s0 = previous[r["engine"]]
            growth = f"{math.log(seconds / s0) / math.log(n / n0):.2f}"
        previous[r["engine"]] = (n, seconds)
        breakdown = {}
        for stage in r["stages"]:
            breakdown.update(stage.get("breakdown", {}))
        cells = [fmt(breakdown[name], 1) if name in breakdown else "–" for name in stage_names]
        cpu = sum(s.get("cpu_s", 0.0) for s in r["stages"] if not s.get("carried"))
        L.append(f"| {n} | {r['engine']} | {r.get('registered')}/{r.get('num_gt')} | "
                 f"{fmt(r.get('auc', {}).get('10'))} | {seconds:.1f} | {cpu:.1f} | {growth} | {r['peak_mb']:.0f} | "
                 + " | ".join(cells) + " |")
    target = [r for r in ours if r["engine"] == "GLOBAL" and r["scene"] == f"{LARGE_SYNTHETIC}@{SCALING_TARGET_VIEWS}"]
    L.append("")
    if target:
        r = target[0]
        seconds = sum(s["seconds"] for s in r["stages"] if not s.get("carried"))
        holds = seconds < SCALING_TARGET_S and r["peak_mb"] < SCALING_TARGET_MB
        L.append(f"Target (issue 4): {SCALING_TARGET_VIEWS} views on 2 cores in under "
                 f"{SCALING_TARGET_S / 60:.0f} minutes with under {SCALING_TARGET_MB / 1024:.0f} GB: GLOBAL took "
                 f"{seconds:.0f} s and {r['peak_mb']:.0f} MB at the load above: "
                 f"**{'holds' if holds else 'does not hold'}** in this run.")
    else:
        L.append(f"Target (issue 4): {SCALING_TARGET_VIEWS} views in under {SCALING_TARGET_S / 60:.0f} minutes "
                 f"and {SCALING_TARGET_MB / 1024:.0f} GB: not measured in this run.")
    return L


def write_reports(args, meta, rows, keys):
    if args.large:
        bs.SECTIONS_DIR.mkdir(parents=True, exist_ok=True)
        tmp = bs.SECTIONS_DIR / "scaling.md.tmp"
        tmp.write_text("\n".join(scaling_section(meta, rows)) + "\n")
        tmp.replace(bs.SECTIONS_DIR / "scaling.md")
    if args.merge:
        meta = json.loads(json.dumps(meta, default=str))  # merge_previous adds the carried scenes
        rows, keys = merge_previous(args, meta, rows, keys)
    write_markdown(Path(args.output), meta, rows, keys)
    Path(args.json).parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(args.json + ".tmp")
    tmp.write_text(json.dumps({"meta": meta, "results": rows}, indent=1, default=str) + "\n")
    tmp.replace(args.json)


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    bs.add_options(p, "prunesfm", "colmap", "shared", "work",
                   prunesfm={"help": "prunesfm executable (default: build/release/src/software/prunesfm, "
                                     "else the newest build*/.../src/software/prunesfm)"},
                   colmap={"help": "colmap executable (peer; skipped if absent)"},
                   work={"default": "/tmp/prunesfm-bench", "help": "scratch folder (kept: logs and models)"})
    p.add_argument("--scenes", default=",".join(SMALL_SYNTHETIC + list(DATASETS)),
                   help="comma-separated synthetic scenes and datasets with ground truth")
    p.add_argument("--large", metavar="SIZES",
                   help=f"separate target: only {LARGE_SYNTHETIC} at these view counts, e.g. 1000,2000,5000")
    p.add_argument("--engines", default=",".join(ALL_ENGINES), help="comma-separated engines")
    bs.add_options(p, "seed", "threads", "max_image_size", "timeout",
                   threads={"default": os.cpu_count(), "help": "threads given to every tool"},
                   timeout={"default": 7200})
    p.add_argument("--smoke", action="store_true",
                   help="quick check (< 1 min): clean scene with 8 views; writes into --work unless "
                        "--output/--json are given")
    p.add_argument("--output", help="markdown report (default docs/benchmarks.md, with the pages it links; "
                                    "docs/benchmarks_large.md with --large)")
    p.add_argument("--json", help="machine-readable results (default bench/results.json; "
                                  "bench/results_large.json with --large)")
    p.add_argument("--merge", metavar="PREVIOUS.json",
                   help="carry over the rows of PREVIOUS.json (an earlier --json) whose (scene, engine) this run "
                        "does not produce; they are marked with their run's date")
    p.add_argument("--reuse", action="store_true",
                   help="reuse the inputs an earlier run left in --work instead of preparing them again: the "
                        "synthetic databases (no `synth`), the datasets' COLMAP feature/matching database (no "
                        "`features`/`match`) and COLMAP's verified synthetic databases (COLMAP's `match` not "
                        "rerun, only `map`); their stage times come from the --merge file (default: the --json "
                        "file as it is before this run) and are marked as carried. Inputs no longer in --work are "
                        "prepared again.")
    p.add_argument("--rewrite_report", action="store_true",
                   help="run nothing: regenerate --output from the --json file as it is (after a change to the "
                        "report's layout or to a fragment of bench/sections); the default --output also rewrites "
                        "docs/benchmarks_large.md from bench/results_large.json")
    p.add_argument("--prepare_only", action="store_true",
                   help="only prepare the inputs (synthetic databases; COLMAP feature extraction + matching on "
                        "the datasets, no mapper) into --work, run no engine and write no report")
    p.add_argument("--variant", action="append", default=[], metavar="LABEL=ENGINE:ARGS",
                   help="an extra row LABEL: `prunesfm run --engine ENGINE` with the extra arguments ARGS "
                        "(split like a shell), e.g. 'GLOBAL+pp=GLOBAL:--refine_principal_point'; repeatable, "
                        "LABEL is then usable in --engines")
    p.add_argument("--known_k", default="", metavar="LABELS",
                   help="comma-separated --variant labels whose database copy gets the dataset's known K "
                        "(PINHOLE fx fy cx cy from gt_cameras.txt, i.e. Strecha's K.txt) instead of COLMAP's "
                        "prior camera; datasets only (no row on synthetic scenes)")
    args = p.parse_args(argv)
    args.variants = {}
    for v in args.variant:
        label, sep, rest = v.partition("=")
        engine, _, extra = rest.partition(":")
        if not sep or not label or engine not in OUR_ENGINES or label in ALL_ENGINES:
            p.error(f"--variant {v}: expected LABEL=ENGINE:ARGS with ENGINE in {', '.join(OUR_ENGINES)}")
        args.variants[label] = (engine, shlex.split(extra))
    args.known_k = [k for k in args.known_k.split(",") if k]
    for k in args.known_k:
        if k not in args.variants:
            p.error(f"--known_k {k}: not a --variant label")
    work = Path(args.work)
    if args.smoke:
        args.scenes = "clean"
        args.output = args.output or str(work / "smoke.md")
        args.json = args.json or str(work / "smoke.json")
    elif args.large:
        args.output = args.output or str(bs.REPO / "docs" / "benchmarks_large.md")
        args.json = args.json or str(bs.REPO / "bench" / "results_large.json")
    else:
        args.output = args.output or str(bs.REPO / "docs" / "benchmarks.md")
        args.json = args.json or str(bs.REPO / "bench" / "results.json")
    return args


def main(argv):
    args = parse_args(argv)
    if args.rewrite_report:
        reports = [(Path(args.output), Path(args.json))]
        if Path(args.output).resolve() == REPORT.resolve():  # the --large run's report is one of its pages
            reports.append((LARGE_REPORT, bs.REPO / "bench" / "results_large.json"))
        for output, json_path in reports:
            data = json.loads(json_path.read_text())
            keys = sorted(dict.fromkeys(r["scene"] for r in data["results"]), key=scene_order)
            write_markdown(output, data["meta"], data["results"], keys)
            pages = " and the pages it links" if output.resolve() == REPORT.resolve() else ""
            print(f"wrote {output}{pages} from {json_path}")
        return 0
    work = Path(args.work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    prunesfm = bs.find_prunesfm(args.prunesfm)
    caps = prunesfm_capabilities(prunesfm)
    colmap = args.colmap if args.colmap and Path(args.colmap).exists() else None
    engines = [e.strip() for e in args.engines.split(",") if e.strip()]
    for e in engines:
        if e not in ALL_ENGINES and e not in args.variants:
            sys.exit(f"run_benchmarks: unknown engine {e} (known: {', '.join(ALL_ENGINES + list(args.variants))})")
    previous_path = args.merge or (args.json if args.reuse else None)
    args.previous_meta, args.previous_rows, args.previous_date = {}, [], None
    if previous_path:
        if not Path(previous_path).is_file():
            sys.exit(f"run_benchmarks: {previous_path} does not exist (--merge / --reuse)")
        previous = json.loads(Path(previous_path).read_text())
        args.previous_meta, args.previous_rows = previous["meta"], previous["results"]
        args.previous_date = previous["meta"]["machine"]["date"]
    if args.large:
        scene_list = [(LARGE_SYNTHETIC, int(n)) for n in args.large.split(",") if n.strip()]
    else:
        scene_list = [(s.strip(), None) for s in args.scenes.split(",") if s.strip()]
        for s, _ in scene_list:
            if s not in SMALL_SYNTHETIC and s not in DATASETS and s != LARGE_SYNTHETIC:
                sys.exit(f"run_benchmarks: unknown scene {s} (synthetic: {', '.join(SMALL_SYNTHETIC)}, "
                         f"{LARGE_SYNTHETIC}; datasets: {', '.join(DATASETS)})")
    shown_argv = ["bench/run_benchmarks.py"] + argv
    meta = {"command": " ".join(shlex.quote(a) for a in shown_argv), "machine": bs.machine_info(),
            "prunesfm": bs.prunesfm_label(prunesfm),
            "prunesfm_run": caps["run"], "prunesfm_run_intrinsics_options": caps["intrinsics_options"],
            "colmap_version": bs.colmap_version(colmap),
            "settings": {"seed": args.seed, "threads": args.threads, "max_image_size": args.max_image_size,
                         "colmap_camera_model": bs.COLMAP_CAMERA_MODEL, "thresholds_deg": bs.THRESHOLDS},
            "scenes": {}}
    if args.merge:
        pm = args.previous_meta
        meta["merged_from"] = {"file": args.merge, "date": args.previous_date, "command": pm.get("command"),
                               "git_commit": pm.get("machine", {}).get("git_commit")}
    if args.variants:
        meta["variants"] = {k: {"engine": e, "extra_args": x} for k, (e, x) in args.variants.items()}
    rows, keys = [], []
    for name, num_views in scene_list:
        print(f"== {name}{'' if num_views is None else '@' + str(num_views)}", flush=True)
        if name in DATASETS:
            scene = prepare_dataset(args, name, colmap, work)
            desc = f"Real images: `{DATASETS[name]}` of the shared datasets, ground truth `gt_cameras.txt`."
            if scene.get("camera"):
                desc += (" Focal prior from EXIF: " + ("yes." if scene["camera"]["prior_focal_from_exif"]
                                                        else "no (COLMAP's default prior)."))
        else:
            scene = prepare_synthetic(args, prunesfm, name, num_views, work)
            prep = scene["prep"][0]
            desc = (f"Synthetic: `prunesfm synth {' '.join(scene['synth_args'])}` "
                    f"({prep['seconds']:.1f} s, not counted).")
        if args.prepare_only:
            print(f"  prepared: {'ok' if scene['ok'] else scene['error']}", flush=True)
            continue
        keys.append(scene["key"])
        meta["scenes"][scene["key"]] = {"description": desc, "kind": scene["kind"],
                                        "prep": scene["prep"], "shared_stages": scene["shared_stages"]}
        if scene.get("synth_args"):
            meta["scenes"][scene["key"]]["synth_args"] = scene["synth_args"]
        for engine in engines:
            if engine in args.known_k and scene["kind"] != "dataset":
                continue  # known K only means something on real images
            row = {"scene": scene["key"], "engine": engine, "status": "ok", "note": None}
            rows.append(row)
            if engine == "colmap" and not colmap:
                row["status"] = "not installed"
                continue
            if engine in args.variants:
                e, extra = args.variants[engine]
                row["variant"] = {"engine": e, "extra_args": extra}
            if engine != "colmap" and not caps["run"]:
                row["status"] = "not built yet"
                row["note"] = "`prunesfm run` does not exist in this build"
                continue
            if not scene["ok"]:
                row["status"] = "input failed"
                row["note"] = scene["error"]
                continue
            print(f"-- {scene['key']} / {engine}", flush=True)
            if engine == "colmap":
                stages, model, note = run_colmap_on_scene(args, colmap, scene, work)
            else:
                stages, model, note = run_ours_on_scene(args, prunesfm, caps, engine, scene, work)
            shared = [dict(s, shared=True) for s in scene["shared_stages"]]
            row["stages"] = shared + stages
            row["total_s"] = round(sum(s["seconds"] for s in row["stages"]), 2)
            row["peak_mb"] = max(s["peak_mb"] for s in row["stages"])
            if engine in args.variants:
                e, extra = args.variants[engine]
                variant_note = f"`--engine {' '.join([e] + extra)}`"
                if engine in args.known_k:
                    variant_note += (" on a database copy whose camera is the known K (PINHOLE fx fy cx cy of "
                                     "gt_cameras.txt = K.txt), not COLMAP's prior")
                note = variant_note + ("; " + note if note else "")
            row["note"] = note
            run = next((s for s in stages if s["name"] == "run"), None)
            if run is not None:
                verification = run.get("breakdown", {}).get("verification", 0.0) if scene["kind"] == "synthetic" else 0.0
                row["reconstruction_s"] = round(run["seconds"] - verification, 2)
            if any(s["rc"] != 0 for s in stages):
                row["status"] = NOT_IMPLEMENTED if NOT_IMPLEMENTED in (note or "") else "failed"
                continue
            ev, ev_stage = evaluate(prunesfm, model, scene["gt"], work / scene["key"] / engine, args.seed,
                                    args.timeout)
            row.update(ev)
            if model is None:
                row["note"] = "no model written: nothing registered"
            elif ev_stage is not None and ev_stage["rc"] != 0:
                row["note"] = "evaluate failed, counted as nothing registered: " + ev_stage.get("error", "")
            row["model"] = str(model) if model else None
            write_reports(args, meta, rows, keys)  # partial results survive an interruption
    if args.prepare_only:
        print("inputs prepared in", work)
        return 0
    meta["machine"]["loadavg_end"] = " ".join(f"{x:.2f}" for x in os.getloadavg())
    write_reports(args, meta, rows, keys)
    print(f"wrote {args.output} and {args.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
