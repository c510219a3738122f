#!/usr/bin/env python3
"""Hostile inputs: every file reader and subcommand of prunesfm fed what a careless or hostile user
gives it, judged by the rules of docs/formats.md ("Values checked on reading") and
docs/frontend.md ("Output folders").

Classes of input (each applied to every subcommand that reads the file or takes the option):
  file       a needed file missing, empty, cut in half, replaced by random bytes, or a folder
  value      NaN, infinite, 0, negative and 1e308 focal lengths, principal points, image sizes,
             rotations, translations, landmarks and keypoints in every model format and the database
  record     truncated, duplicated and dangling records; negative row counts; impossible pair ids;
             a view graph with no edges
  image      empty, undecodable, truncated and 1x1 images; a folder with one or no image
  option     NaN, inf, -1 and 1e308 for every numeric option of every subcommand; malformed seeds
  output     an output path that is a user's folder, a user's file, empty, or the input itself

A case passes when the command (a) neither crashes nor trips a sanitizer, (b) ends within
--timeout seconds, (c) leaves every file that was there before unchanged unless it is the
output the case asked for, and (d) does what the case expects: a rejected input gets a non-zero
exit and exactly one error line that names the file (or the option) at fault; a tolerated input
(an undecodable image among good ones, an extreme but valid option) finishes with exit 0, or is
rejected by the rules of (d).

Usage: python3 bench/hostile_inputs.py [--prunesfm PATH] [--work DIR] [--only SUBSTRING]
                                       [--output bench/sections/hostile_inputs.md]
Needs ../shared/datasets/middlebury/templeSparseRing for the image cases (skipped without it).
Python 3 standard library only.
"""

import argparse
import json
import os
import random
import re
import shlex
import shutil
import signal
import sqlite3
import struct
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_support as bs  # noqa: E402

REPO = bs.REPO

SANITIZER_MARKS = ("AddressSanitizer", "LeakSanitizer", "UndefinedBehaviorSanitizer", "runtime error:",
                   "terminate called", "Segmentation fault", "Aborted")
NUMBERS = {"nan": "nan", "inf": "inf", "zero": "0", "negative": "-1", "huge": "1e308"}


@dataclass
class Case:
    klass: str
    name: str
    argv: list            # prunesfm arguments, paths relative to the case folder
    setup: object         # callable(case_dir) that lays out the inputs
    expect: str = "reject"  # "reject", "accept" (must finish with exit 0) or "either"
    names: tuple = ()     # what the error line must name, one of these (a file, its folder, an option)
    writes: tuple = ()    # paths the command may create or replace
    result: dict = field(default_factory=dict)


# ---------------------------------------------------------------------------------------------
# Base inputs: one small generated scene and its models in every format, plus four photos.

class Base:
    def __init__(self, prunesfm, work, shared):
        self.prunesfm = prunesfm
        self.dir = work / "base"
        self.photos = shared / "datasets" / "middlebury" / "templeSparseRing" / "images"
        self.has_photos = self.photos.is_dir()
        self.jpeg = shared / "datasets" / "ambiguous" / "street" / "images" / "0010.jpg"  # a real camera JPEG

    def run(self, *argv):
        proc = subprocess.run([self.prunesfm, *map(str, argv)], cwd=self.dir, capture_output=True, text=True)
        if proc.returncode != 0:
            sys.exit(f"hostile_inputs: preparing the base inputs failed: prunesfm {shlex.join(map(str, argv))}\n"
                     f"{proc.stderr}")

    def prepare(self):
        if self.dir.exists():
            shutil.rmtree(self.dir)
        self.dir.mkdir(parents=True)
        self.run("synth", "--scene", "clean", "--num_views", "8", "--seed", "0", "-o", "scene")
        self.run("reconstruct", "--database", "scene/database.db", "-o", "run", "--engine", "GLOBAL_PRUNED")
        self.run("convert", "-i", "run/sparse/0", "-o", "model_txt", "--output_type", "TXT")
        self.run("convert", "-i", "run/sfm_data.json", "-o", "model.bin")
        self.run("convert", "-i", "run/sfm_data.json", "-o", "model.ply")
        (self.dir / "pairs.txt").write_text("0 1 2\n1 2 3\n2 3\n")
        (self.dir / "K.txt").write_text("1520.4 0 302.32\n0 1525.9 246.87\n0 0 1\n")
        if self.has_photos:
            (self.dir / "photos").mkdir()
            for image in sorted(self.photos.iterdir())[:4]:
                shutil.copy(image, self.dir / "photos" / image.name)
            self.run("run", "photos", "photo_run", "--num_threads", "2")
            self.run("export", "-i", "photo_run/sfm_data.json", "--images", "photos", "--format", "openmvs",
                     "-o", "mvs")
            self.run("export", "-i", "photo_run/sfm_data.json", "--images", "photos", "--format",
                     "colmap-undistorted", "-o", "undistorted")
        self.view_name = json.loads((self.dir / "run" / "sfm_data.json").read_text())["views"][0]["value"][
            "ptr_wrapper"]["data"]["filename"]

    def copy(self, relative, case_dir, as_name=None):
        source = self.dir / relative
        target = case_dir / (as_name or relative)
        target.parent.mkdir(parents=True, exist_ok=True)
        if source.is_dir():
            shutil.copytree(source, target)
        else:
            shutil.copy(source, target)
        return target


# ---------------------------------------------------------------------------------------------
# Mutations

def file_mutations(seed):
    """Whole-file classes: (label, function(path))."""
    def missing(path):
        shutil.rmtree(path) if path.is_dir() else path.unlink()

    def empty(path):
        path.write_bytes(b"")

    def truncated(path):
        data = path.read_bytes()
        path.write_bytes(data[:len(data) // 2])

    def garbage(path):
        size = max(64, min(path.stat().st_size, 1 << 16))
        path.write_bytes(random.Random(seed).randbytes(size))

    def folder(path):
        path.unlink()
        path.mkdir()
        (path / "inside.txt").write_text("a folder where a file belongs\n")

    return [("missing", missing), ("empty", empty), ("truncated", truncated), ("garbage", garbage),
            ("folder", folder)]


def edit_json(path, edit):
    data = json.loads(path.read_text())
    edit(data)
    path.write_text(json.dumps(data, indent=1, allow_nan=True).replace("1e+308", "1e308"))


def number(label):
    return {"nan": float("nan"), "inf": float("inf"), "zero": 0.0, "negative": -1.0, "huge": 1e308}[label]


def sfm_data_value_edits():
    """Edits of an OpenMVG sfm_data.json: (field label, function(data, value))."""
    def intrinsic(data):
        return data["intrinsics"][0]["value"]["ptr_wrapper"]["data"]

    def focal(data, v):
        intrinsic(data)["focal_length"] = v

    def principal(data, v):
        intrinsic(data)["principal_point"][0] = v

    def width(data, v):
        intrinsic(data)["width"] = v if v != v or abs(v) == float("inf") else int(max(min(v, 2**62), -2**62))

    def rotation(data, v):
        data["extrinsics"][0]["value"]["rotation"][0][0] = v

    def center(data, v):
        data["extrinsics"][0]["value"]["center"][1] = v

    def landmark(data, v):
        data["structure"][0]["value"]["X"][2] = v

    def observation(data, v):
        data["structure"][0]["value"]["observations"][0]["value"]["x"][0] = v

    return [("focal", focal), ("principal point", principal), ("image width", width), ("rotation", rotation),
            ("camera centre", center), ("landmark", landmark), ("observation", observation)]


def text_edit(path, line_pattern, column, value):
    """Replaces whitespace-separated `column` of the first line matching line_pattern (not a comment)."""
    lines = path.read_text().split("\n")
    for i, line in enumerate(lines):
        if line.startswith("#") or not re.match(line_pattern, line):
            continue
        parts = line.split()
        parts[column] = value
        lines[i] = " ".join(parts)
        path.write_text("\n".join(lines))
        return
    raise RuntimeError(f"{path}: no line matches {line_pattern}")


# ---------------------------------------------------------------------------------------------
# The cases

class Cases:
    def __init__(self, base, seed):
        self.base = base
        self.seed = seed
        self.list = []

    def add(self, klass, name, argv, setup, expect="reject", names="", writes=()):
        names = (names,) if isinstance(names, str) else tuple(names)
        self.list.append(Case(klass, name, [str(a) for a in argv], setup, expect, names, tuple(writes)))

    # A command that reads one file, and how to lay out its other inputs.
    def readers(self):
        b = self.base
        view = b.view_name
        gt = "scene/ground_truth/gt_cameras.txt"
        r = []
        # (file under test, files to copy, argv, writes)
        r.append(("run/sfm_data.json", ["run/sfm_data.json", gt],
                  ["convert", "-i", "run/sfm_data.json", "-o", "out.ply"], ["out.ply"]))
        r.append(("run/sfm_data.json", ["run/sfm_data.json", gt],
                  ["evaluate", "-e", "run/sfm_data.json", "-g", gt], []))
        r.append(("run/sfm_data.json", ["run/sfm_data.json"],
                  ["export", "-i", "run/sfm_data.json", "--format", "colmap", "-o", "out"], ["out"]))
        r.append(("run/sfm_data.json", ["run/sfm_data.json"],
                  ["epipolar", "--model", "run/sfm_data.json", "--image", view, "--output", "e.png"], ["e.png"]))
        r.append(("run/sfm_data.json", ["run"], ["report", "--run", "run", "--output", "r.html"], ["r.html"]))
        r.append(("scene/ground_truth/sfm_data.json", ["scene/ground_truth/sfm_data.json", "scene/matches"],
                  ["reconstruct", "--sfm_data", "scene/ground_truth/sfm_data.json", "--matches_dir",
                   "scene/matches", "-o", "out"], ["out"]))
        r.append(("scene/ground_truth/sfm_data.json", ["scene/ground_truth/sfm_data.json", "scene/matches"],
                  ["prune", "--sfm_data", "scene/ground_truth/sfm_data.json", "--matches_dir", "scene/matches",
                   "-o", "pruned.bin"], ["pruned.bin", "pruned.pruning_report.json"]))
        r.append(("model.bin", ["model.bin", gt], ["evaluate", "-e", "model.bin", "-g", gt], []))
        r.append(("model.bin", ["model.bin"], ["convert", "-i", "model.bin", "-o", "out.json"], ["out.json"]))
        for name in ("cameras.bin", "images.bin", "points3D.bin"):
            f = f"run/sparse/0/{name}"
            r.append((f, ["run/sparse/0"], ["convert", "-i", "run/sparse/0", "-o", "out.json"], ["out.json"]))
            r.append((f, ["run/sparse/0", gt], ["evaluate", "-e", "run/sparse/0", "-g", gt], []))
            r.append((f, ["run/sparse/0"], ["export", "-i", "run/sparse/0", "--format", "json", "-o", "out.json"],
                      ["out.json"]))
        for name in ("cameras.txt", "images.txt", "points3D.txt"):
            f = f"model_txt/{name}"
            r.append((f, ["model_txt"], ["convert", "-i", "model_txt", "-o", "out.json"], ["out.json"]))
            r.append((f, ["model_txt"], ["epipolar", "--model", "model_txt", "--image", view, "--output", "e.png"],
                      ["e.png"]))
        r.append((gt, [gt, "run/sfm_data.json"], ["evaluate", "-e", "run/sfm_data.json", "-g", gt], []))
        r.append((gt, [gt], ["convert", "-i", gt, "-o", "out.json"], ["out.json"]))
        r.append((gt, [gt, "run"], ["report", "--run", "run", "--ground_truth", gt, "--output", "r.html"],
                  ["r.html"]))
        r.append(("model.ply", ["model.ply"], ["convert", "-i", "model.ply", "-o", "out.json"], ["out.json"]))
        r.append(("scene/database.db", ["scene/database.db"],
                  ["reconstruct", "--database", "scene/database.db", "-o", "out"], ["out"]))
        r.append(("scene/database.db", ["scene/database.db"],
                  ["prune", "--database", "scene/database.db", "-o", "pruned.db"],
                  ["pruned.db", "pruned.pruning_report.json"]))
        r.append(("scene/database.db", ["scene/database.db"],
                  ["run", "--database", "scene/database.db", "--image_path", "scene", "--output_path", "out"],
                  ["out"]))
        for f in ("scene/matches/view_00003.feat", "scene/matches/view_00003.desc",
                  "scene/matches/matches.putative.bin"):
            r.append((f, ["scene/ground_truth/sfm_data.json", "scene/matches"],
                      ["reconstruct", "--sfm_data", "scene/ground_truth/sfm_data.json", "--matches_dir",
                       "scene/matches", "-o", "out"], ["out"]))
        r.append(("scene/matches/view_00003.desc", ["scene/ground_truth/sfm_data.json", "scene/matches"],
                  ["match", "-s", "scene/ground_truth/sfm_data.json", "-m", "scene/matches", "--pairs",
                   "sequential", "--window", "2"], ["scene/matches"]))
        r.append(("run/view_graph.json", ["run"], ["report", "--run", "run", "--output", "r.html"], ["r.html"]))
        r.append(("run/timings.json", ["run"], ["report", "--run", "run", "--output", "r.html"], ["r.html"]))
        r.append(("run/pruning_report.json", ["run"], ["report", "--run", "run", "--output", "r.html"],
                  ["r.html"]))
        r.append(("pairs.txt", ["pairs.txt", "scene/ground_truth/sfm_data.json", "scene/matches"],
                  ["match", "-s", "scene/ground_truth/sfm_data.json", "-m", "scene/matches", "--pairs", "list",
                   "--pair_list", "pairs.txt"], ["scene/matches"]))
        if b.has_photos:
            r.append(("K.txt", ["K.txt", "photos"], ["init", "-i", "photos", "-o", "out/sfm_data.json",
                                                     "--k_file", "K.txt"], ["out"]))
            r.append(("photo_run/matches/sfm_data.json", ["photo_run/matches/sfm_data.json", "photos"],
                      ["features", "-s", "photo_run/matches/sfm_data.json", "-o", "feats"], ["feats"]))
            r.append(("photo_run/matches/camera_priors.json", ["photo_run/matches"],
                      ["reconstruct", "--sfm_data", "photo_run/matches/sfm_data.json", "--matches_dir",
                       "photo_run/matches", "-o", "out"], ["out"]))
            r.append(("photo_run/matches/image_describer.json", ["photo_run/matches"],
                      ["match", "-s", "photo_run/matches/sfm_data.json", "-m", "photo_run/matches"],
                      ["photo_run/matches"]))
            r.append(("photo_run/run_manifest.json", ["photo_run", "photos"], ["run", "photos", "photo_run"],
                      ["photo_run"]))
            r.append(("mvs/scene.mvs", ["mvs"], ["export", "-i", "mvs/scene.mvs", "--format", "colmap", "-o", "out"],
                      ["out"]))
        return r

    def setup_copy(self, files, mutate=None, target=None):
        base = self.base

        def setup(d):
            for f in files:
                base.copy(f, d)
            if mutate:
                mutate(d / target)
        return setup

    def build(self):
        b = self.base
        readers = self.readers()
        # file: every reader, every whole-file class
        for target, files, argv, writes in readers:
            for label, mutate in file_mutations(self.seed):
                expect = "reject"
                if target.endswith(("run_manifest.json", "pruning_report.json")) and label != "folder":
                    expect = "either"  # a run redoes what its manifest cannot vouch for; report omits a section
                if target.endswith("camera_priors.json") and label == "missing":
                    expect = "accept"  # the priors are optional
                if target.endswith(("pruning_report.json", "view_graph.json")) and label == "missing":
                    expect = "accept"  # a GLOBAL run has no pruning report
                if argv[0] == "report" and target == "run/sfm_data.json" and label in ("missing", "folder"):
                    expect = "either"  # the run's sparse/0 holds the same model
                if target.endswith(".desc") and argv[0] == "reconstruct":
                    expect = "either"  # reconstruct reads keypoints and matches, never descriptors
                if target.endswith("image_describer.json") and label == "missing":
                    expect = "either"  # the describer's settings are informative only
                # A file of a model folder or of a matches folder may be named through its folder:
                # an empty cameras.txt shows as images.txt naming a missing camera, a cut .feat as
                # match indices past its end.
                names = (Path(target).name, str(Path(target).parent))
                self.add("file", f"{argv[0]}: {target} {label}", argv, self.setup_copy(files, mutate, target),
                         expect, names, writes)
        self.value_cases()
        self.record_cases()
        self.image_cases()
        self.output_cases()
        self.option_cases()
        return self.list

    def value_cases(self):
        b = self.base
        gt = "scene/ground_truth/gt_cameras.txt"
        json_readers = [
            (["run/sfm_data.json"], ["convert", "-i", "run/sfm_data.json", "-o", "out.ply"], ["out.ply"]),
            (["run/sfm_data.json", gt], ["evaluate", "-e", "run/sfm_data.json", "-g", gt], []),
            (["run/sfm_data.json"], ["export", "-i", "run/sfm_data.json", "--format", "colmap", "-o", "out"],
             ["out"]),
            (["scene/ground_truth/sfm_data.json", "scene/matches"],
             ["reconstruct", "--sfm_data", "scene/ground_truth/sfm_data.json", "--matches_dir", "scene/matches",
              "-o", "out"], ["out"]),
        ]
        for files, argv, writes in json_readers:
            target = files[0]
            for field_label, edit in sfm_data_value_edits():
                if argv[0] == "reconstruct" and field_label in ("rotation", "camera centre", "landmark",
                                                                 "observation"):
                    continue  # reconstruct reads only the views and intrinsics
                for label in NUMBERS:
                    if label == "zero" and field_label in ("camera centre", "landmark", "observation",
                                                           "principal point"):
                        continue  # zero is a valid coordinate
                    if label == "negative" and field_label in ("camera centre", "landmark", "observation",
                                                               "principal point", "rotation"):
                        continue
                    value = number(label)

                    def mutate(path, edit=edit, value=value):
                        edit_json(path, lambda data: edit(data, value))
                    self.add("value", f"{argv[0]}: sfm_data.json {field_label} {label}", argv,
                             self.setup_copy(files, mutate, target), "reject", "sfm_data.json", writes)
        # COLMAP text model: camera line "ID MODEL W H f cx cy ...", image line "ID QW QX QY QZ TX TY TZ CAM NAME"
        text_fields = [("cameras.txt", r"^\d+ ", 4, "focal"), ("cameras.txt", r"^\d+ ", 5, "principal point"),
                       ("cameras.txt", r"^\d+ ", 2, "image width"), ("images.txt", r"^\d+ .*\.\w+$", 1, "qvec"),
                       ("images.txt", r"^\d+ .*\.\w+$", 5, "translation"),
                       ("points3D.txt", r"^\d+ ", 1, "landmark")]
        for name, pattern, column, field_label in text_fields:
            for label, value in NUMBERS.items():
                if label in ("zero", "negative") and field_label in ("principal point", "translation", "landmark",
                                                                     "qvec"):
                    continue
                if field_label == "image width" and label in ("nan", "inf", "huge"):
                    value = {"nan": "nan", "inf": "inf", "huge": "99999999999999999999"}[label]

                def mutate(path, pattern=pattern, column=column, value=value):
                    text_edit(path, pattern, column, value)
                # A quaternion is normalised on reading: 1e308 in one component is a valid rotation.
                expect = "either" if field_label == "qvec" and label == "huge" else "reject"
                self.add("value", f"convert: {name} {field_label} {label}", ["convert", "-i", "model_txt", "-o",
                                                                             "out.json"],
                         self.setup_copy(["model_txt"], mutate, f"model_txt/{name}"), expect, (name, "model_txt"),
                         ["out.json"])
        # gt_cameras.txt: "name fx fy cx cy r11..r33 tx ty tz" (Strecha-style lines)
        for column, field_label in ((1, "focal"), (5, "rotation"), (14, "translation")):
            for label, value in NUMBERS.items():
                if label in ("zero", "negative") and field_label != "focal":
                    continue

                def mutate(path, column=column, value=value):
                    text_edit(path, r"^\S+\s+[-\d.e+]+", column, value)
                self.add("value", f"evaluate: gt_cameras.txt {field_label} {label}",
                         ["evaluate", "-e", "run/sfm_data.json", "-g", gt],
                         self.setup_copy([gt, "run/sfm_data.json"], mutate, gt), "reject", "gt_cameras.txt")
        # COLMAP database: camera parameters, image sizes, keypoints, two-view geometries
        for label in NUMBERS:
            for field_label, sql_edit in database_value_edits(number(label)):
                def mutate(path, sql_edit=sql_edit):
                    with sqlite3.connect(path) as db:
                        sql_edit(db)
                for argv, writes in ((["reconstruct", "--database", "scene/database.db", "-o", "out"], ["out"]),
                                     (["prune", "--database", "scene/database.db", "-o", "pruned.db"],
                                      ["pruned.db", "pruned.pruning_report.json"])):
                    if field_label.startswith("keypoint") and label in ("zero", "negative", "huge"):
                        continue  # a keypoint at (0, y), (-1, y) or far away is a bad match, not a bad file
                    # A principal point on the image's edge or just off it is a cropped frame.
                    expect = "either" if field_label.endswith("principal point") and label in (
                        "zero", "negative") else "reject"
                    self.add("value", f"{argv[0]}: database {field_label} {label}", argv,
                             self.setup_copy(["scene/database.db"], mutate, "scene/database.db"), expect,
                             "database.db", writes)

    def record_cases(self):
        gt = "scene/ground_truth/gt_cameras.txt"

        def drop_half_points(path):
            lines = path.read_text().split("\n")
            body = [l for l in lines if l and not l.startswith("#")]
            head = [l for l in lines if l.startswith("#")]
            path.write_text("\n".join(head + body[:len(body) // 2]) + "\n")

        def duplicate_camera(path):
            lines = path.read_text().rstrip("\n").split("\n")
            path.write_text("\n".join(lines + [l for l in lines if not l.startswith("#")][:1]) + "\n")

        def trailing_number(path):
            text_edit(path, r"^\d+ .*\.\w+$", -1, "x.png 7")

        def dangling_point(path):
            lines = path.read_text().split("\n")
            for i, line in enumerate(lines):
                if re.match(r"^\d+ .*\.\w+$", line) and i + 1 < len(lines):
                    parts = lines[i + 1].split()
                    for k in range(2, len(parts), 3):
                        if parts[k] != "-1":
                            parts[k] = "999999"
                            break
                    lines[i + 1] = " ".join(parts)
                    break
            path.write_text("\n".join(lines))

        # The NAME of images.txt is the rest of its line (names may hold spaces), so a trailing field
        # is part of the name: accepted, and the image is then looked up under that name.
        for name, label, mutate, expect in (("points3D.txt", "half the points", drop_half_points, "reject"),
                                            ("cameras.txt", "duplicate camera", duplicate_camera, "reject"),
                                            ("images.txt", "trailing field", trailing_number, "either"),
                                            ("images.txt", "point2D of a missing point", dangling_point, "reject")):
            for argv, writes in ((["convert", "-i", "model_txt", "-o", "out.json"], ["out.json"]),
                                 (["evaluate", "-e", "model_txt", "-g", gt], [])):
                self.add("record", f"{argv[0]}: {name} {label}", argv,
                         self.setup_copy(["model_txt", gt], mutate, f"model_txt/{name}"), expect, name, writes)
        for label, sql_edit in database_record_edits():
            def mutate(path, sql_edit=sql_edit):
                with sqlite3.connect(path) as db:
                    sql_edit(db)
            for argv, writes in ((["reconstruct", "--database", "scene/database.db", "-o", "out"], ["out"]),
                                 (["prune", "--database", "scene/database.db", "-o", "pruned.db"],
                                  ["pruned.db", "pruned.pruning_report.json"]),
                                 (["run", "--database", "scene/database.db", "--image_path", "scene",
                                   "--output_path", "out"], ["out"])):
                self.add("record", f"{argv[0]}: database {label}", argv,
                         self.setup_copy(["scene/database.db"], mutate, "scene/database.db"), "reject",
                         "database.db", writes)

        def no_matches(path):
            path.write_bytes(b"")
        # A match file with no pairs: the view graph has no edges.
        for argv, writes in ((["reconstruct", "--sfm_data", "scene/ground_truth/sfm_data.json", "--matches_dir",
                               "scene/matches", "-o", "out"], ["out"]),
                             (["prune", "--sfm_data", "scene/ground_truth/sfm_data.json", "--matches_dir",
                               "scene/matches", "-o", "pruned.bin"], ["pruned.bin", "pruned.pruning_report.json"])):
            def setup(d):
                self.base.copy("scene/ground_truth/sfm_data.json", d)
                self.base.copy("scene/matches", d)
                (d / "scene/matches/matches.putative.bin").unlink()
                (d / "scene/matches/matches.putative.txt").write_text("")
            self.add("record", f"{argv[0]}: match file with no pairs", argv, setup, "reject", "matches.putative.txt",
                     writes)
        # Pair lists without a pair, or naming a view the scene does not have.
        for label, text in (("without pairs", "0\n"), ("naming a missing view", "0 1\n1 4000\n")):
            def write_list(path, text=text):
                path.write_text(text)
            self.add("record", f"match: pair list {label}",
                     ["match", "-s", "scene/ground_truth/sfm_data.json", "-m", "scene/matches", "--pairs", "list",
                      "--pair_list", "pairs.txt"],
                     self.setup_copy(["pairs.txt", "scene/ground_truth/sfm_data.json", "scene/matches"], write_list,
                                     "pairs.txt"), "reject", "pairs.txt", ["scene/matches"])

    def image_cases(self):
        b = self.base
        if not b.has_photos:
            return

        def first_jpeg():
            return b.jpeg if b.jpeg.is_file() else sorted(b.photos.iterdir())[0]

        def first_png():
            return sorted(b.photos.iterdir())[0]

        def photos_with(extra):
            def setup(d):
                b.copy("photos", d)
                extra(d / "photos")
            return setup

        def truncated_jpeg(folder):
            data = first_jpeg().read_bytes()
            (folder / "cut.jpg").write_bytes(data[:len(data) // 2])

        def truncated_png(folder):
            data = first_png().read_bytes()
            (folder / "cut.png").write_bytes(data[:len(data) // 2])

        def empty_image(folder):
            (folder / "empty.jpg").write_bytes(b"")

        def text_image(folder):
            (folder / "notes.png").write_text("not an image\n")

        def tiny_png(folder):
            (folder / "tiny.png").write_bytes(tiny_png_bytes())

        tolerated = (("a truncated JPEG", truncated_jpeg, "cut.jpg"), ("a truncated PNG", truncated_png, "cut.png"),
                     ("an empty image", empty_image, "empty.jpg"),
                     ("a text file named .png", text_image, "notes.png"), ("a 1x1 PNG", tiny_png, "tiny.png"))
        for label, extra, name in tolerated:
            self.add("image", f"init: photos plus {label}", ["init", "-i", "photos", "-o", "out/sfm_data.json"],
                     photos_with(extra), "accept", name, ["out"])
        for label, extra, name in tolerated[:3]:
            self.add("image", f"run: photos plus {label}", ["run", "photos", "out", "--num_threads", "2"],
                     photos_with(extra), "accept", name, ["out"])

        def only(files):
            def setup(d):
                (d / "photos").mkdir()
                for make in files:
                    make(d / "photos")
            return setup

        def one_photo(folder):
            shutil.copy(sorted(b.photos.iterdir())[0], folder)

        def two_cut(folder):
            data = first_jpeg().read_bytes()
            (folder / "a.jpg").write_bytes(data[:len(data) // 3])
            data = first_png().read_bytes()
            (folder / "b.png").write_bytes(data[:len(data) // 2])

        def two_tiny(folder):
            (folder / "a.png").write_bytes(tiny_png_bytes())
            (folder / "b.png").write_bytes(tiny_png_bytes())

        for label, files in (("no image", []), ("one image", [one_photo]), ("a truncated JPEG and PNG", [two_cut]),
                             ("two 1x1 images", [two_tiny])):
            self.add("image", f"run: a folder with {label}", ["run", "photos", "out"], only(files), "reject",
                     "photos", ["out"])
            # init lists what decodes; a 1x1 image decodes (run then finds no features in it).
            self.add("image", f"init: a folder with {label}", ["init", "-i", "photos", "-o", "out/sfm_data.json"],
                     only(files), "either" if label in ("one image", "two 1x1 images") else "reject", "photos",
                     ["out"])

        def undecodable_view(d):
            b.copy("photo_run/sfm_data.json", d)
            b.copy("photos", d)
            first = sorted((d / "photos").iterdir())[0]
            first.write_bytes(first.read_bytes()[:100])
        self.add("image", "export openmvs: an image of the model cut short",
                 ["export", "-i", "photo_run/sfm_data.json", "--images", "photos", "--format", "openmvs", "-o", "out"],
                 undecodable_view, "reject", sorted(b.photos.iterdir())[0].name, ["out"])
        self.add("image", "export colmap-undistorted: an image of the model cut short",
                 ["export", "-i", "photo_run/sfm_data.json", "--images", "photos", "--format", "colmap-undistorted",
                  "-o", "out"], undecodable_view, "reject", sorted(b.photos.iterdir())[0].name, ["out"])

        def missing_view(d):
            b.copy("photo_run/sfm_data.json", d)
            b.copy("photos", d)
            sorted((d / "photos").iterdir())[0].unlink()
        self.add("image", "export openmvs: an image of the model missing",
                 ["export", "-i", "photo_run/sfm_data.json", "--images", "photos", "--format", "openmvs", "-o", "out"],
                 missing_view, "reject", sorted(b.photos.iterdir())[0].name, ["out"])
        for label, value in (("nan", "nan"), ("inf", "inf"), ("zero", "0")):
            def mutate(path, value=value):
                edit_json(path, lambda data: data["intrinsics"][0]["value"]["ptr_wrapper"]["data"].__setitem__(
                    "focal_length", float(value)))
            self.add("value", f"export colmap-undistorted: sfm_data.json focal {label}",
                     ["export", "-i", "photo_run/sfm_data.json", "--images", "photos", "--format",
                      "colmap-undistorted", "-o", "out"],
                     self.setup_copy(["photo_run/sfm_data.json", "photos"], mutate, "photo_run/sfm_data.json"),
                     "reject", "sfm_data.json", ["out"])

    def output_cases(self):
        b = self.base
        writers = [
            (["synth", "--scene", "clean", "--num_views", "6", "-o", "OUT"], []),
            (["convert", "-i", "run/sparse/0", "-o", "OUT"], ["run/sparse/0"]),
            (["export", "-i", "run/sfm_data.json", "--format", "colmap", "-o", "OUT"], ["run/sfm_data.json"]),
            (["reconstruct", "--database", "scene/database.db", "-o", "OUT"], ["scene/database.db"]),
            (["run", "--database", "scene/database.db", "--image_path", "scene", "--output_path", "OUT"],
             ["scene/database.db"]),
        ]
        if b.has_photos:
            writers.append((["run", "photos", "OUT"], ["photos"]))
            writers.append((["export", "-i", "photo_run/sfm_data.json", "--images", "photos", "--format", "openmvs",
                             "-o", "OUT"], ["photo_run/sfm_data.json", "photos"]))
        for argv, files in writers:
            label = " ".join(argv[:1] + ([argv[3]] if argv[0] == "export" else []))

            def user_folder(d, files=files):
                for f in files:
                    b.copy(f, d)
                (d / "OUT").mkdir()
                (d / "OUT" / "precious.txt").write_text("the user's own file\n")

            def user_file(d, files=files):
                for f in files:
                    b.copy(f, d)
                (d / "OUT").write_text("the user's own file\n")
            self.add("output", f"{label}: output is a user's folder", argv, user_folder, "reject", "OUT")
            self.add("output", f"{label}: output is a user's file", argv, user_file, "reject", "OUT")
            self.add("output", f"{label}: empty output path", [a if a != "OUT" else "" for a in argv],
                     self.setup_copy(files), "reject", ("output", "OUT_DIR"))
        # The output is the input itself
        self.add("output", "prune: output is the input database",
                 ["prune", "--database", "scene/database.db", "-o", "scene/database.db"],
                 self.setup_copy(["scene/database.db"]), "reject", "database.db")
        self.add("output", "convert: output is the input model",
                 ["convert", "-i", "run/sparse/0", "-o", "run/sparse/0"], self.setup_copy(["run/sparse/0"]), "reject",
                 "0")
        self.add("output", "convert: output file is the input file",
                 ["convert", "-i", "model.bin", "-o", "model.bin"], self.setup_copy(["model.bin"]), "reject",
                 "model.bin")
        self.add("output", "prune: report is the input database",
                 ["prune", "--database", "scene/database.db", "-o", "pruned.db", "--report", "scene/database.db"],
                 self.setup_copy(["scene/database.db"]), "reject", "database.db", ["pruned.db"])

    def option_cases(self):
        """Every numeric option of every subcommand, from its --help."""
        b = self.base
        gt = "scene/ground_truth/gt_cameras.txt"
        view = b.view_name
        commands = [
            (["synth", "--scene", "clean", "--num_views", "6", "-o", "out"], [], ["out"]),
            (["reconstruct", "--database", "scene/database.db", "-o", "out"], ["scene/database.db"], ["out"]),
            (["prune", "--sfm_data", "scene/ground_truth/sfm_data.json", "--matches_dir", "scene/matches", "-o",
              "pruned.bin"], ["scene/ground_truth/sfm_data.json", "scene/matches"],
             ["pruned.bin", "pruned.pruning_report.json"]),
            (["run", "--database", "scene/database.db", "--image_path", "scene", "--output_path", "out"],
             ["scene/database.db"], ["out"]),
            (["evaluate", "-e", "run/sfm_data.json", "-g", gt], ["run/sfm_data.json", gt], []),
            (["export", "-i", "run/sfm_data.json", "--format", "colmap", "-o", "out"], ["run/sfm_data.json"], ["out"]),
            (["report", "--run", "run", "--output", "r.html"], ["run"], ["r.html"]),
            (["epipolar", "--model", "run/sfm_data.json", "--image", view, "--output", "e.png"],
             ["run/sfm_data.json"], ["e.png"]),
            (["match", "-s", "scene/ground_truth/sfm_data.json", "-m", "scene/matches", "--pairs", "sequential",
              "--window", "2"], ["scene/ground_truth/sfm_data.json", "scene/matches"], ["scene/matches"]),
        ]
        if b.has_photos:
            commands.append((["init", "-i", "photos", "-o", "out/sfm_data.json"], ["photos"], ["out"]))
            commands.append((["features", "-s", "photo_run/matches/sfm_data.json", "-o", "feats"],
                             ["photo_run/matches/sfm_data.json", "photos"], ["feats"]))
        for argv, files, writes in commands:
            for option, kind in numeric_options(b.prunesfm, argv[0]):
                if option in argv:
                    continue
                values = [("nan", "nan", "reject"), ("inf", "inf", "reject"), ("-1", "-1", "either"),
                          ("1e308", "1e308", "either"), ("1e400", "1e400", "reject")]
                if kind in ("INT", "UINT"):
                    values += [("2^64", "18446744073709551616", "reject"), ("1.5", "1.5", "reject")]
                for label, value, expect in values:
                    self.add("option", f"{argv[0]} {option} {label}", argv + [option, value],
                             self.setup_copy(files), expect, option, writes)


def numeric_options(prunesfm, command):
    """(--option, FLOAT|INT|UINT) of every numeric option in `prunesfm COMMAND --help_all`."""
    text = subprocess.run([prunesfm, command, "--help_all"], capture_output=True, text=True).stdout
    found = []
    for match in re.finditer(r"^\s+(?:-\w,)?(--[\w,-]+)\s+(FLOAT|INT|UINT)\b", text, re.M):
        option = match.group(1).split(",")[0]
        if option not in [o for o, _ in found]:
            found.append((option, match.group(2)))
    return found


def tiny_png_bytes():
    """A valid 1x1 grey PNG, written from its chunks."""
    import zlib

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    header = struct.pack(">IIBBBBB", 1, 1, 8, 0, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(b"\x00\x80")) + \
        chunk(b"IEND", b"")


def database_value_edits(value):
    """(label, function(sqlite connection)) that put `value` into one field of the database."""
    def camera_param(index):
        def edit(db):
            camera_id, params = db.execute("SELECT camera_id, params FROM cameras LIMIT 1").fetchone()
            values = list(struct.unpack(f"<{len(params) // 8}d", params))
            values[index] = value
            db.execute("UPDATE cameras SET params=? WHERE camera_id=?", (struct.pack(f"<{len(values)}d", *values),
                                                                         camera_id))
        return edit

    def width(db):
        db.execute("UPDATE cameras SET width=? WHERE camera_id=(SELECT MIN(camera_id) FROM cameras)",
                   (int(value) if value == value and abs(value) < 1e18 else -(2**62),))

    def keypoint(db):
        image_id, rows, cols, data = db.execute("SELECT image_id, rows, cols, data FROM keypoints LIMIT 1").fetchone()
        values = list(struct.unpack(f"<{len(data) // 4}f", data))
        values[0] = value if abs(value) < 3e38 or value != value else float("inf")
        db.execute("UPDATE keypoints SET data=? WHERE image_id=?", (struct.pack(f"<{len(values)}f", *values), image_id))

    edits = [("camera focal", camera_param(0)), ("camera principal point", camera_param(1)), ("keypoint x", keypoint)]
    return edits + [("camera width", width)]


def database_record_edits():
    def negative_rows(db):
        db.execute("UPDATE matches SET rows=-5 WHERE pair_id=(SELECT MIN(pair_id) FROM matches)")

    def negative_keypoint_rows(db):
        db.execute("UPDATE keypoints SET rows=-1 WHERE image_id=(SELECT MIN(image_id) FROM keypoints)")

    def huge_pair_id(db):
        db.execute("UPDATE matches SET pair_id=? WHERE pair_id=(SELECT MIN(pair_id) FROM matches)", (2**63 - 1,))

    def match_index_out_of_range(db):
        pair_id, data = db.execute("SELECT pair_id, data FROM matches LIMIT 1").fetchone()
        values = list(struct.unpack(f"<{len(data) // 4}I", data))
        values[0] = 4000000000
        db.execute("UPDATE matches SET data=? WHERE pair_id=?", (struct.pack(f"<{len(values)}I", *values), pair_id))

    def short_blob(db):
        db.execute("UPDATE keypoints SET data=substr(data, 1, 10) WHERE image_id=(SELECT MIN(image_id) FROM keypoints)")

    def no_pairs(db):
        db.execute("DELETE FROM matches")
        db.execute("DELETE FROM two_view_geometries")

    def no_cameras(db):
        db.execute("DELETE FROM cameras")

    def no_images(db):
        db.execute("DELETE FROM images")

    def unknown_camera_model(db):
        db.execute("UPDATE cameras SET model=99")

    def dropped_table(db):
        db.execute("DROP TABLE keypoints")

    return [("match rows -5", negative_rows), ("keypoint rows -1", negative_keypoint_rows),
            ("pair_id 2^63-1", huge_pair_id), ("match index past the keypoints", match_index_out_of_range),
            ("keypoint blob cut short", short_blob), ("no pairs", no_pairs), ("no cameras", no_cameras),
            ("no images", no_images), ("unknown camera model", unknown_camera_model),
            ("keypoints table missing", dropped_table)]


# ---------------------------------------------------------------------------------------------
# Running and judging

def snapshot(folder):
    files = {}
    for path in folder.rglob("*"):
        if path.is_file() and not path.is_symlink():
            files[path.relative_to(folder).as_posix()] = path.read_bytes()
    return files


def under(relative, writes):
    return any(relative == w or relative.startswith(w.rstrip("/") + "/") or relative.startswith(w + ".")
               for w in writes)


def run_case(prunesfm, case, case_dir, timeout):
    if case_dir.exists():
        shutil.rmtree(case_dir)
    case_dir.mkdir(parents=True)
    case.setup(case_dir)
    before = snapshot(case_dir)
    start = time.monotonic()
    proc = subprocess.Popen([prunesfm, *case.argv], cwd=case_dir, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, errors="replace", process_group=0)
    try:
        stdout, stderr = proc.communicate(timeout=timeout)
        hung = False
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        stdout, stderr = proc.communicate()
        hung = True
    seconds = time.monotonic() - start
    after = snapshot(case_dir)
    damaged = sorted(p for p, data in before.items() if not under(p, case.writes) and after.get(p) != data)
    errors = [line for line in stderr.split("\n") if "error" in line.lower() and line.strip()]
    problems = []
    if hung:
        problems.append(f"still running after {timeout:.0f} s")
    crashed = proc.returncode < 0 or proc.returncode >= 128 and proc.returncode not in (105, 106, 107, 108, 109,
                                                                                       110, 111, 112, 113, 114)
    if crashed or any(mark in stderr for mark in SANITIZER_MARKS):
        problems.append(f"crashed (exit {proc.returncode})")
    if damaged:
        problems.append("changed or deleted: " + ", ".join(damaged[:3]))
    rejected = proc.returncode != 0 and not hung
    if not problems:
        if rejected:
            if case.expect == "accept":
                problems.append("rejected a tolerable input")
            elif len(errors) != 1:
                problems.append(f"{len(errors)} error lines")
            elif case.names and not any(n.lower() in errors[0].lower() for n in case.names):
                problems.append(f"the error does not name {' or '.join(case.names)}")
        elif case.expect == "reject":
            problems.append("accepted (exit 0)")
    case.result = {"rc": proc.returncode, "seconds": round(seconds, 2), "hung": hung, "rejected": rejected,
                   "error": errors[0] if errors else (stderr.strip().split("\n")[-1] if stderr.strip() else ""),
                   "problems": problems}
    if not problems:
        shutil.rmtree(case_dir, ignore_errors=True)
    return case


def write_report(path, argv, prunesfm, cases, timeout):
    lines = bs.header_lines("Hostile inputs: malformed files, impossible numbers, bad options, occupied outputs "
                            "(`bench/hostile_inputs.py`)", argv, prunesfm)
    lines += ["Every case runs one `prunesfm` subcommand on a small generated scene (or four photos of "
              "templeSparseRing) with one input spoiled. It passes when the command does not crash, ends within "
              f"{timeout:.0f} s, leaves every file that was there before unchanged (outputs it was asked to "
              "write excepted), and either rejects the input with a non-zero exit and one error line naming the "
              "file or option, or (inputs a user may legitimately give: an undecodable image among good ones, an "
              "extreme but valid option value) finishes normally.", "",
              "| class | cases | rejected, one line naming the culprit | tolerated (exit 0) | failed | slowest (s) |",
              "|---|---:|---:|---:|---:|---:|"]
    classes = []
    for case in cases:
        if case.klass not in classes:
            classes.append(case.klass)
    for klass in classes + ["all"]:
        chosen = [c for c in cases if klass in ("all", c.klass)]
        failed = [c for c in chosen if c.result["problems"]]
        rejected = [c for c in chosen if c.result["rejected"] and not c.result["problems"]]
        tolerated = [c for c in chosen if not c.result["rejected"] and not c.result["problems"]]
        slowest = max(c.result["seconds"] for c in chosen)
        label = f"**{klass}**" if klass == "all" else klass
        lines.append(f"| {label} | {len(chosen)} | {len(rejected)} | {len(tolerated)} | {len(failed)} | "
                     f"{slowest:.1f} |")
    failed = [c for c in cases if c.result["problems"]]
    lines.append("")
    if failed:
        lines += ["Failed cases:", "", "| case | problem | last message |", "|---|---|---|"]
        for c in failed:
            message = c.result["error"].replace("|", "\\|")[:160]
            lines.append(f"| {c.name} | {'; '.join(c.result['problems'])} | {message} |")
    else:
        lines.append("No case failed.")
    lines.append("")
    Path(path).write_text("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    bs.add_options(parser, "prunesfm", "shared", "work", "timeout", "seed",
                   prunesfm={"help": bs.NEWEST_BUILD_HELP}, shared={"help": None},
                   work={"default": "/tmp/prunesfm-hostile", "help": "scratch folder (failed cases stay here)"},
                   timeout={"type": float, "default": 60.0, "help": "seconds a case may run"},
                   seed={"help": "seed of the random bytes"})
    parser.add_argument("--only", default="", help="run only the cases whose name contains this")
    parser.add_argument("--classes", default="file,value,record,image,output,option",
                        help="comma-separated classes of cases to run")
    parser.add_argument("--output", default=None,
                        help="markdown report (default: bench/sections/hostile_inputs.md for the whole list, "
                             "WORK/report.md when --only or --classes runs a part of it)")
    parser.add_argument("--list", action="store_true", help="list the cases and exit")
    args = parser.parse_args()
    prunesfm = str(bs.find_prunesfm(args.prunesfm))
    work = Path(args.work)
    base = Base(prunesfm, work, Path(args.shared))
    if not base.has_photos:
        print(f"hostile_inputs: {base.photos} not found; the image cases are skipped", file=sys.stderr)
    if not args.list:
        base.prepare()
    else:
        base.view_name = "view_00000.png"
    classes = args.classes.split(",")
    if args.output is None:
        whole = not args.only and set(classes) == {"file", "value", "record", "image", "output", "option"}
        args.output = str(REPO / "bench" / "sections" / "hostile_inputs.md") if whole else str(work / "report.md")
    cases = [c for c in Cases(base, args.seed).build() if args.only in c.name and c.klass in classes]
    if not cases:
        print(f"no case matches --only {args.only!r} in the classes {args.classes}", file=sys.stderr)
        return 2
    if args.list:
        for c in cases:
            print(f"{c.klass:7} {c.expect:7} {c.name}")
        print(f"{len(cases)} cases")
        return 0
    for i, case in enumerate(cases):
        run_case(prunesfm, case, work / "cases" / f"{i:04d}", args.timeout)
        mark = "FAIL " + "; ".join(case.result["problems"]) if case.result["problems"] else "ok"
        print(f"[{i + 1}/{len(cases)}] {case.name}: {mark} ({case.result['seconds']:.1f} s)", flush=True)
    write_report(args.output, sys.argv, prunesfm, cases, args.timeout)
    failed = sum(1 for c in cases if c.result["problems"])
    print(f"{len(cases)} cases, {failed} failed; report in {args.output}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
