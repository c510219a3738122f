"""The shared library of bench/. Each script of bench/ is the one entry point of one table
(run_benchmarks.py: the engine-by-scene tables of docs/benchmarks*.md; every other script: one
fragment bench/sections/<name>.md); each imports this module, and bench_colmap.py for COLMAP's
files and camera geometry, and no script imports another. Python 3 standard library only.

  command line  the options several scripts share: add_options, argument_parser
  stages        run_stage (one child process, its wall time and peak memory), fresh_folder
  tools         find_prunesfm, colmap_version, machine_info
  prunesfm      synth_stage, run_ours_on_database, run_model, prune_database, evaluate_model,
                evaluate_against
  COLMAP        colmap_features, colmap_match, verify_synthetic_matches, colmap_mapper, colmap_to_text
  synthetic     the labels of `prunesfm synth` scenes and the oracle's edits of their databases
  report        header_lines, write_fragment
"""

import argparse
import array
import datetime
import json
import os
import platform
import random
import shlex
import shutil
import signal
import sqlite3
import subprocess
import sys
import threading
import time
from pathlib import Path

import bench_colmap as bc

REPO = Path(__file__).resolve().parent.parent
SECTIONS_DIR = REPO / "bench" / "sections"  # the fragments the pages of docs/benchmarks.md append
THRESHOLDS = [3, 5, 10]
COLMAP_CAMERA_MODEL = "SIMPLE_RADIAL"


# ----------------------------------------------------------------------------------------------
# Command line
# ----------------------------------------------------------------------------------------------

# The options several scripts share, as argparse settings. A script adds the ones it has, in the
# order of its --help, and may give one its own default or help (add_options).
COMMON_OPTIONS = {
    "prunesfm": {"help": "prunesfm executable (default: as bench/run_benchmarks.py)"},
    "colmap": {"default": shutil.which("colmap"), "help": "colmap executable"},
    "shared": {"default": str(REPO.parent / "shared"), "help": "shared data folder"},
    "work": {"help": "scratch folder of this script (logs and models stay there)"},
    "seed": {"type": int, "default": 0},
    "threads": {"type": int, "default": min(2, os.cpu_count() or 1), "help": "threads of every tool"},
    "timeout": {"type": int, "default": 3600, "help": "seconds before a stage is killed"},
    "jobs": {"type": int, "default": 1},
    "max_image_size": {"type": int, "default": 3200, "help": "COLMAP SiftExtraction.max_image_size"},
}
# --prunesfm of the scripts that do not say which build they take.
NEWEST_BUILD_HELP = "prunesfm binary (default: the newest build)"


def add_options(parser, *names, **changes):
    """Adds the shared options `names` (keys of COMMON_OPTIONS) to `parser` in that order;
    NAME={setting: value} changes an option's argparse settings for this script."""
    for name in names:
        parser.add_argument(f"--{name}", **{**COMMON_OPTIONS[name], **changes.get(name, {})})


def argument_parser(doc, work):
    """A parser with the options every section script has: --prunesfm, --colmap, --shared, --work,
    --seed, --threads, --timeout."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0],
                                     formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    add_options(parser, "prunesfm", "colmap", "shared", "work", "seed", "threads", "timeout",
                work={"default": work})
    return parser


# ----------------------------------------------------------------------------------------------
# Running one stage
# ----------------------------------------------------------------------------------------------

def run_stage(name, argv, log_path, timeout_s, env=None):
    """Runs argv with stdout+stderr to log_path; returns the stage record (wall s, peak MB, rc)."""
    log_path.parent.mkdir(parents=True, exist_ok=True)
    print(f"  [{name}] {' '.join(shlex.quote(str(a)) for a in argv)}", flush=True)
    argv = [str(a) for a in argv]
    with open(log_path, "wb") as log, open(os.devnull, "rb") as devnull:
        start = time.monotonic()
        try:
            pid = os.posix_spawnp(argv[0], argv, env if env is not None else dict(os.environ),
                                  file_actions=[(os.POSIX_SPAWN_DUP2, devnull.fileno(), 0),
                                                (os.POSIX_SPAWN_DUP2, log.fileno(), 1),
                                                (os.POSIX_SPAWN_DUP2, log.fileno(), 2)])
        except OSError as e:
            return {"name": name, "seconds": 0.0, "peak_mb": 0.0, "rc": 127, "log": str(log_path),
                    "error": f"cannot start {argv[0]}: {e}"}
        timed_out = threading.Event()

        def kill():
            timed_out.set()
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass

        timer = threading.Timer(timeout_s, kill)
        timer.start()
        try:
            _, status, usage = os.wait4(pid, 0)
        finally:
            timer.cancel()
        seconds = time.monotonic() - start
    rc = os.waitstatus_to_exitcode(status)
    record = {"name": name, "seconds": round(seconds, 2), "peak_mb": round(usage.ru_maxrss / 1024.0, 1),
              "cpu_s": round(usage.ru_utime + usage.ru_stime, 2), "rc": rc, "log": str(log_path)}
    if timed_out.is_set():
        record["error"] = f"killed after the {timeout_s} s timeout"
    elif rc != 0:
        record["error"] = f"exit code {rc}: {last_line(log_path)}"
    print(f"  [{name}] {seconds:.1f} s, peak {record['peak_mb']:.0f} MB, rc {rc}", flush=True)
    return record


def last_line(path):
    try:
        lines = [l.strip() for l in Path(path).read_text(errors="replace").splitlines() if l.strip()]
    except OSError:
        return ""
    return lines[-1][:200] if lines else ""


def fresh_folder(path):
    """Makes `path` a new empty folder (what an earlier run left there is removed)."""
    if path.exists():
        shutil.rmtree(path)
    path.mkdir(parents=True)


def colmap_env():
    env = dict(os.environ)
    env["QT_QPA_PLATFORM"] = "offscreen"
    return env


# ----------------------------------------------------------------------------------------------
# Tools and machine
# ----------------------------------------------------------------------------------------------

def find_prunesfm(explicit):
    if explicit:
        return Path(explicit).resolve()
    preferred = REPO / "build" / "release" / "src" / "software" / "prunesfm"
    if preferred.is_file():
        return preferred
    candidates = [p for p in REPO.glob("build*/**/src/software/prunesfm") if p.is_file() and os.access(p, os.X_OK)]
    if not candidates:
        sys.exit("run_benchmarks: no prunesfm executable under build*/; build it or pass --prunesfm PATH")
    return max(candidates, key=lambda p: p.stat().st_mtime)  # the most recently built one


def prunesfm_label(prunesfm):
    p = Path(prunesfm)
    return str(p.relative_to(REPO)) if p.is_relative_to(REPO) else str(p)


def colmap_version(colmap):
    if not colmap:
        return None
    out = subprocess.run([colmap, "-h"], capture_output=True, text=True, env=colmap_env()).stdout
    return out.splitlines()[0].strip() if out else "unknown"


def machine_info():
    cpu = "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    mem_gb = None
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemTotal:"):
                mem_gb = round(int(line.split()[1]) / 1024 / 1024, 1)
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    return {"date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "nproc": os.cpu_count(), "cpu": cpu, "mem_gb": mem_gb, "kernel": platform.release(),
            "python": platform.python_version(), "git_commit": commit,
            "loadavg_start": " ".join(f"{x:.2f}" for x in os.getloadavg())}


# ----------------------------------------------------------------------------------------------
# prunesfm: scenes, runs, pruning, evaluation
# ----------------------------------------------------------------------------------------------

def synth_stage(prunesfm, scene, seed, out, log_path, timeout_s, extra=(), threads=None):
    """`prunesfm synth --scene SCENE --seed SEED --output OUT [--num_threads N] EXTRA...` as a stage.
    On success it also makes OUT/images: synth writes no image files, but `prunesfm run --database`
    and COLMAP's mapper want the folder to exist."""
    argv = [prunesfm, "synth", "--scene", scene, "--seed", seed, "--output", out]
    if threads is not None:
        argv += ["--num_threads", threads]
    stage = run_stage("synth", argv + list(extra), log_path, timeout_s)
    if stage["rc"] == 0:
        (Path(out) / "images").mkdir(parents=True, exist_ok=True)
    return stage


def run_ours_on_database(prunesfm, database, images, output, engine, log, timeout, options=(),
                         output_flag="--output_path"):
    """`prunesfm run --database DATABASE --image_path IMAGES --output_path OUTPUT --engine ENGINE
    OPTIONS...` as the stage "run"; returns the stage record. output_flag: the spelling of the
    output option (`--output` is the same option) in the command the script prints."""
    argv = [prunesfm, "run", "--database", database, "--image_path", images, output_flag, output,
            "--engine", engine, *options]
    return run_stage("run", argv, log, timeout)


def stage_totals(entries):
    """Seconds per stage name of a timings.json "stages" list, in order of first appearance; a
    stage that ran several times (the missing-correspondence check's solves) is summed."""
    totals = {}
    for entry in entries:
        totals[entry["stage"]] = totals.get(entry["stage"], 0.0) + entry["seconds"]
    return totals


def run_model(stage, output):
    """OUTPUT/sparse/0, the model a successful `prunesfm run` writes; None when the run failed."""
    return Path(output) / "sparse" / "0" if stage["rc"] == 0 else None


def prune_database(prunesfm, database, output, log_dir, threads, seed, timeout, extra=()):
    """`prunesfm prune` on a COLMAP database; returns (stage, report dict or None)."""
    report_path = Path(output).with_suffix(".pruning_report.json")
    argv = [prunesfm, "prune", "--database", database, "--output", output, "--report", report_path,
            "--num_threads", threads, "--seed", seed, *extra]
    stage = run_stage("prune", argv, Path(log_dir) / "prune.log", timeout)
    report = json.loads(report_path.read_text()) if stage["rc"] == 0 and report_path.is_file() else None
    return stage, report


def evaluate_model(prunesfm, model, reference, out_dir, seed, timeout):
    """`prunesfm evaluate` of `model` against `reference` (gt_cameras.txt or a model folder) at
    THRESHOLDS, its JSON in OUT_DIR/evaluation.json: (that report, None when it failed; the stage)."""
    json_path = Path(out_dir) / "evaluation.json"
    stage = run_stage("evaluate", [prunesfm, "evaluate", "--estimate", model, "--ground_truth", reference,
                                   "--thresholds", ",".join(map(str, THRESHOLDS)), "--seed", seed,
                                   "--json", json_path], Path(out_dir) / "evaluate.log", timeout)
    return (json.loads(json_path.read_text()) if stage["rc"] == 0 else None), stage


def report_auc(report):
    """{"3": AUC %, "5": ..., "10": ...} of an evaluation report, rounded to 0.01."""
    return {f"{entry['threshold_deg']:g}": round(entry["auc_percent"], 2) for entry in report["auc"]}


def evaluate_against(prunesfm, model, reference, out_dir, seed, timeout):
    """`prunesfm evaluate` of `model` against `reference` (gt_cameras.txt or a model folder):
    {registered, num_reference, auc: {"3","5","10"}}; no model = nothing registered, AUC 0."""
    result = {"registered": 0, "num_reference": None, "auc": {str(t): 0.0 for t in THRESHOLDS}}
    if model is None:
        return result
    report, _ = evaluate_model(prunesfm, model, reference, out_dir, seed, timeout)
    if report is None:
        return result
    result["registered"] = report["num_registered_images"]
    result["num_reference"] = report["num_ground_truth_images"]
    result["auc"].update(report_auc(report))
    return result


# ----------------------------------------------------------------------------------------------
# COLMAP 3.8 (CPU SIFT, QT offscreen)
# ----------------------------------------------------------------------------------------------

def colmap_features(name, colmap, database, images, log, threads, max_image_size, timeout, camera_params=None):
    """`feature_extractor`: one COLMAP_CAMERA_MODEL camera for every image (`camera_params` as a
    known prior when given), SIFT on the CPU."""
    argv = [colmap, "feature_extractor", "--database_path", database, "--image_path", images,
            "--ImageReader.single_camera", "1", "--ImageReader.camera_model", COLMAP_CAMERA_MODEL]
    if camera_params is not None:
        argv += ["--ImageReader.camera_params", camera_params]
    argv += ["--SiftExtraction.use_gpu", "0", "--SiftExtraction.num_threads", str(threads),
             "--SiftExtraction.max_image_size", max_image_size]
    return run_stage(name, argv, log, timeout, colmap_env())


def colmap_match(name, colmap, matcher, database, log, threads, timeout, options=()):
    """COLMAP's matcher = [command, its options...] (exhaustive_matcher, sequential_matcher ...) on
    `database`, then `options`, SIFT matching on the CPU."""
    argv = [colmap, *matcher, "--database_path", database, *options,
            "--SiftMatching.use_gpu", "0", "--SiftMatching.num_threads", str(threads)]
    return run_stage(name, argv, log, timeout, colmap_env())


def verify_synthetic_matches(name, colmap, database, pair_list, log, threads, timeout):
    """COLMAP 3.8's verification of the putative matches a synthetic database holds (its matchers
    keep a pair's existing matches and only verify them): exhaustive_matcher when every pair is
    there, else matches_importer with the pairs written to `pair_list` (exhaustive would match all
    N^2 pairs of a sequential scene)."""
    names, pairs = bc.matched_pairs(database)
    n = len(names)
    if len(pairs) == n * (n - 1) // 2:
        return colmap_match(name, colmap, ["exhaustive_matcher"], database, log, threads, timeout)
    Path(pair_list).write_text("".join(f"{names[a]} {names[b]}\n" for a, b in pairs))
    return colmap_match(name, colmap, ["matches_importer"], database, log, threads, timeout,
                        ["--match_list_path", pair_list, "--match_type", "pairs"])


def colmap_mapper(colmap, database, images, out_dir, threads, timeout, synthetic):
    """COLMAP 3.8's incremental mapper on `database` into out_dir/sparse; returns (stage, model)."""
    sparse = Path(out_dir) / "sparse"
    sparse.mkdir(parents=True, exist_ok=True)
    argv = [colmap, "mapper", "--database_path", database, "--image_path", images, "--output_path", sparse,
            "--Mapper.num_threads", threads]
    if synthetic:
        argv += ["--Mapper.extract_colors", "0"]  # no image files to take colours from
    stage = run_stage("map", argv, Path(out_dir) / "map.log", timeout, colmap_env())
    model, _ = bc.largest_model(sparse)
    return stage, model


def colmap_to_text(colmap, model, txt, log, timeout):
    """`model_converter` of a binary model into the text model `txt`."""
    return run_stage("convert", [colmap, "model_converter", "--input_path", model, "--output_path", txt,
                                 "--output_type", "TXT"], log, timeout, colmap_env())


# ----------------------------------------------------------------------------------------------
# Synthetic scenes: their labels (ground_truth/ of `prunesfm synth`) and the oracle's edits
# ----------------------------------------------------------------------------------------------

def view_index(name):
    """view_00012.jpg -> 12: the index of a synthetic view, as synthetic_scene.json and the labels use it."""
    return int(Path(name).stem.split("_")[-1])


def twin_dominated_pairs(scene_json, ratio):
    stats = json.loads(Path(scene_json).read_text())["pairs"]
    return {(p["i"], p["j"]) for p in stats if p["twin"] > ratio * p["true"]}, len(stats)


def delete_pairs(database, pairs, tables=("matches",)):
    """Deletes the rows of `pairs` (view indices = the number in view_NNNNN.jpg) from `tables`; returns
    how many pairs had rows in the first of them."""
    db = sqlite3.connect(database)
    view_of = {image_id: view_index(name) for image_id, name in db.execute(
        "SELECT image_id, name FROM images")}
    deleted = 0
    for (pair_id,) in list(db.execute(f"SELECT pair_id FROM {tables[0]}")):
        a, b = bc.image_pair(pair_id)
        views = tuple(sorted((view_of[a], view_of[b])))
        if views in pairs:
            for table in tables:
                db.execute(f"DELETE FROM {table} WHERE pair_id = ?", (pair_id,))
            deleted += 1
    db.commit()
    db.close()
    return deleted


def read_feature_landmarks(path):
    """ground_truth/feature_landmarks.txt of `prunesfm synth`: view -> [(landmark, appearance)] per feature."""
    result = {}
    for line in Path(path).read_text().splitlines():
        if not line or line.startswith("#"):
            continue
        fields = [int(x) for x in line.split()]
        view, count = fields[0], fields[1]
        result[view] = list(zip(fields[2:2 + 2 * count:2], fields[3:3 + 2 * count:2]))
    return result


def delete_twin_matches(database, features, keep_fraction=0.0, seed=0):
    """Removes from every pair's putative matches those between two copies of one texture (different
    landmarks, one appearance), each but a random `keep_fraction` of them (random.Random(seed));
    returns (twin matches deleted, matches before)."""
    rng = random.Random(seed)
    db = sqlite3.connect(database)
    view_of = {image_id: view_index(name) for image_id, name in db.execute(
        "SELECT image_id, name FROM images")}
    deleted = total = 0
    for pair_id, rows, cols, blob in list(db.execute("SELECT pair_id, rows, cols, data FROM matches")):
        a, b = bc.image_pair(pair_id)
        pairs = array.array("I", blob)  # uint32 feature index pairs (COLMAP's matches blob)
        labels_a, labels_b = features[view_of[a]], features[view_of[b]]
        kept = array.array("I")
        for k in range(rows):
            (la, aa), (lb, ab) = labels_a[pairs[cols * k]], labels_b[pairs[cols * k + 1]]
            if la >= 0 and lb >= 0 and la != lb and aa == ab and rng.random() >= keep_fraction:
                continue
            kept.extend(pairs[cols * k:cols * k + cols])
        total += rows
        deleted += rows - len(kept) // cols
        db.execute("UPDATE matches SET rows = ?, data = ? WHERE pair_id = ?", (len(kept) // cols, kept.tobytes(), pair_id))
    db.commit()
    db.close()
    return deleted, total


# ----------------------------------------------------------------------------------------------
# Report fragments
# ----------------------------------------------------------------------------------------------

def header_lines(title, argv, prunesfm, colmap=None):
    """The fragment's heading and how it was made: command, date, commit, machine load."""
    m = machine_info()
    command = " ".join(shlex.quote(a) for a in argv)
    lines = [f"## {title}", "",
             f"Generated by `{command}` on {m['date']} at commit `{m['git_commit']}` "
             f"(`{prunesfm_label(prunesfm)}`, {colmap_version(colmap) or 'no colmap'}); "
             f"machine: {m['nproc']} cores ({m['cpu']}), load average at start {m['loadavg_start']} "
             "(the machine is shared: compare ratios measured in the same run, not absolute seconds).", ""]
    return lines


def write_fragment(name, lines):
    path = SECTIONS_DIR / f"{name}.md"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines).rstrip("\n") + "\n")
    print(f"wrote {path} (refresh docs/benchmarks*.md: python3 bench/run_benchmarks.py --rewrite_report)")
    return path
