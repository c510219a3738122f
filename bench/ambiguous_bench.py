#!/usr/bin/env python3
"""Real ambiguous scenes without ground truth (issue 5): books and street of
<shared>/datasets/ambiguous (Yan et al. 2017). Writes bench/sections/ambiguous.md.

Reference. The images are in capture order, so a reconstruction from neighbour-only pairs never
sees the doppelgangers (the alike copies are far apart in the sequence): COLMAP 3.8
`feature_extractor` (one SIMPLE_RADIAL camera, focal from exif_focal.txt as a known prior) +
`sequential_matcher` (pairs i, i+1 .. i+overlap; no quadratic overlap, no loop detection) +
`mapper`. The reference is checked, not trusted:
  - every image registered in one model;
  - epipolar consistency: the reference's poses and intrinsics give, for every pair COLMAP
    verified in the *exhaustive* database, the Sampson error of its inlier matches; sequential
    pairs must fit (median below --max_sampson_px), and so must every far pair that sees the same
    physical surface;
  - point transfer: each inlier match with a keypoint on a reference track has that 3D point
    projected into the other image; a pair whose matches land more often on something else
    (> 5 · --max_transfer_px away) than on the keypoint (≤ --max_transfer_px) does not fit either.
    Sampson's test cannot see a twin that is shifted along the epipolar line, which is what a
    street's twin is (a facade one period further, in the direction the camera walks);
  - pairs that do not fit are the doppelganger pairs (listed: their gap in the sequence and
    inlier count);
  - trajectory: the step between consecutive camera centres (largest / median) and no two
    far-apart images at the same place looking the same way (what folding looks like).
Then the exhaustive database (same features, `exhaustive_matcher`) is reconstructed by
GLOBAL, GLOBAL_PRUNED (`prunesfm run`), COLMAP's mapper, and COLMAP's mapper on the database
`prunesfm prune` cleaned; each model is scored by `prunesfm evaluate` against the reference
(AUC of pairwise relative pose errors, as for ground truth).
Python 3 standard library only.
"""

import json
import math
import shutil
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_colmap as bc  # noqa: E402
import bench_support as bs  # noqa: E402

SCENES = {"books": "ambiguous/books", "street": "ambiguous/street"}
ENGINES = ["GLOBAL", "GLOBAL_PRUNED", "colmap", "colmap+prune"]


# ----------------------------------------------------------------------------------------------
# Inputs: exif focal (the COLMAP database and text models: bench_colmap.py)
# ----------------------------------------------------------------------------------------------

def exif_camera(path):
    """(width, height, f_px) shared by every image of exif_focal.txt (one camera per scene)."""
    cams = set()
    for line in Path(path).read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            name, w, h, _, _, f_px = line.split()[:6]
            cams.add((int(w), int(h), float(f_px)))
    if len(cams) != 1:
        sys.exit(f"ambiguous_bench: {path}: expected one camera, found {sorted(cams)}")
    return cams.pop()


# ----------------------------------------------------------------------------------------------
# Preparation (COLMAP)
# ----------------------------------------------------------------------------------------------

def prepare(args, scene, work):
    """base.db (features), sequential.db and exhaustive.db (verified pairs). Returns stage records."""
    folder = Path(args.shared) / "datasets" / SCENES[scene]
    images = folder / "images"
    w, h, f_px = exif_camera(folder / "exif_focal.txt")
    base, seq, exh = work / "base.db", work / "sequential.db", work / "exhaustive.db"
    t = str(args.threads)
    stages = []
    if not (args.reuse and bc.has_keypoints(base)):
        for p in (base, Path(str(base) + "-wal"), Path(str(base) + "-shm")):
            p.unlink(missing_ok=True)
        # A known focal (prior_focal_length = 1) from EXIF; principal point at the centre, k = 0 to start.
        params = f"{f_px},{w / 2},{h / 2},0"
        stages.append(bs.colmap_features("features", args.colmap, base, images, work / "features.log", t,
                                         args.max_image_size, args.timeout, camera_params=params))
        if stages[-1]["rc"] != 0:
            sys.exit(f"ambiguous_bench: {scene}: feature_extractor failed: {stages[-1].get('error')}")
        bc.fold_wal(base)
    matchers = [
        ("sequential", seq, ["sequential_matcher", "--SequentialMatching.overlap", str(args.overlap),
                             "--SequentialMatching.quadratic_overlap", "0",
                             "--SequentialMatching.loop_detection", "0"]),
        ("exhaustive", exh, ["exhaustive_matcher"]),
    ]
    for name, db, matcher in matchers:
        if args.reuse and bc.num_verified_pairs(db) > 0:
            continue
        bc.copy_database(base, db)
        stages.append(bs.colmap_match(name, args.colmap, matcher, db, work / f"{name}.log", t, args.timeout))
        if stages[-1]["rc"] != 0:
            sys.exit(f"ambiguous_bench: {scene}: {matcher[0]} failed: {stages[-1].get('error')}")
        bc.fold_wal(db)
    return images, (w, h, f_px), stages


def build_reference(args, work, images):
    """COLMAP's mapper on the sequential database; the largest model, also as text."""
    ref = work / "reference"
    txt = ref / "text"
    stages = []
    model, num_models = bc.largest_model(ref / "sparse")
    if not (args.reuse and model is not None and (txt / "images.txt").is_file()):
        if ref.exists():
            shutil.rmtree(ref)
        db = work / "reference.db"
        bc.copy_database(work / "sequential.db", db)
        stage, model = bs.colmap_mapper(args.colmap, db, images, ref, str(args.threads), args.timeout, False)
        stages.append(stage)
        if model is None:
            sys.exit(f"ambiguous_bench: the reference mapper made no model (see {ref / 'map.log'})")
        txt.mkdir(parents=True)
        bs.colmap_to_text(args.colmap, model, txt, ref / "convert.log", args.timeout)
        _, num_models = bc.largest_model(ref / "sparse")
    return model, num_models, txt, stages


# ----------------------------------------------------------------------------------------------
# Checking the reference
# ----------------------------------------------------------------------------------------------

def pair_sampson_px(cameras, images, names, keypoints, pair, matches):
    """Median Sampson error (pixels, focal-scaled) of a pair's inliers under the reference poses."""
    n1, n2 = names[pair[0]], names[pair[1]]
    if n1 not in images or n2 not in images:
        return None
    R1, t1, c1 = images[n1]
    R2, t2, c2 = images[n2]
    R = bc.matmul(R2, bc.transpose(R1))
    t = bc.sub(t2, bc.matvec(R, t1))
    E = bc.matmul(bc.skew(t), R)
    Et = bc.transpose(E)
    focal = 0.5 * (cameras[c1][3][0] + cameras[c2][3][0])
    errors = []
    for i, j in matches:
        u1, v1 = bc.normalized(cameras[c1], keypoints[pair[0]][i])
        u2, v2 = bc.normalized(cameras[c2], keypoints[pair[1]][j])
        x1, x2 = [u1, v1, 1.0], [u2, v2, 1.0]
        Ex1, Etx2 = bc.matvec(E, x1), bc.matvec(Et, x2)
        num = sum(x2[k] * Ex1[k] for k in range(3))
        den = Ex1[0] ** 2 + Ex1[1] ** 2 + Etx2[0] ** 2 + Etx2[1] ** 2
        errors.append(math.sqrt(num * num / den) * focal if den > 0 else float("inf"))
    return statistics.median(errors)


def pair_transfer(cameras, images, tracks, names, keypoints, pair, matches, max_px):
    """(true, twin) matches of a pair under the reference's 3D points: a match (f1, f2) whose f1
    (else f2) lies on a reference track has that point projected into the other image; within
    max_px of the other keypoint it is true, beyond 5 · max_px it is a twin (the other keypoint
    sees something else). Sampson's test is blind along the epipolar line, and a street's twin is
    exactly there: a copy one facade further along the direction the camera moves."""
    point_ids, points = tracks
    n = [names[pair[0]], names[pair[1]]]
    if n[0] not in images or n[1] not in images:
        return 0, 0
    true = twin = 0
    for f in matches:
        for a in (0, 1):
            ids = point_ids.get(n[a], [])
            point = ids[f[a]] if f[a] < len(ids) else -1
            if point < 0 or point not in points:
                continue
            R, t, cam = images[n[1 - a]]
            pixel = bc.project(cameras[cam], R, t, points[point])
            seen = keypoints[pair[1 - a]][f[1 - a]]
            error = math.inf if pixel is None else math.hypot(pixel[0] - seen[0], pixel[1] - seen[1])
            true += error <= max_px
            twin += error > 5 * max_px
            break
    return true, twin


def check_reference(args, work, txt, num_models):
    cameras, images = bc.read_text_model(txt)
    tracks = bc.read_text_tracks(txt)
    names, keypoints, inliers = bc.read_database(work / "exhaustive.db")
    order = {name: k for k, name in enumerate(sorted(names.values()))}
    check = {"images": len(names), "registered": len(images), "models": num_models}
    pairs = []
    for pair, matches in sorted(inliers.items()):
        gap = abs(order[names[pair[0]]] - order[names[pair[1]]])
        err = pair_sampson_px(cameras, images, names, keypoints, pair, matches)
        true, twin = pair_transfer(cameras, images, tracks, names, keypoints, pair, matches, args.max_transfer_px)
        pairs.append({"pair": list(pair), "names": [names[pair[0]], names[pair[1]]], "gap": gap,
                      "inliers": len(matches), "sampson_px": None if err is None else round(err, 3),
                      "transfer_true": true, "transfer_twin": twin})
    # A pair fits when its inliers satisfy the reference's epipolar geometry and, where they can be
    # transferred through the reference's points, more of them land on the same point than on a copy.
    sampson_fits = lambda p: p["sampson_px"] is not None and p["sampson_px"] <= args.max_sampson_px  # noqa: E731
    fits = lambda p: sampson_fits(p) and p["transfer_twin"] <= p["transfer_true"]  # noqa: E731
    near = [p for p in pairs if p["gap"] <= args.overlap]
    far = [p for p in pairs if p["gap"] > args.overlap]
    check["sequential_pairs"] = len(near)
    check["sequential_pairs_fitting"] = sum(fits(p) for p in near)
    check["sequential_median_sampson_px"] = round(statistics.median(
        [p["sampson_px"] for p in near if p["sampson_px"] is not None] or [float("nan")]), 3)
    check["far_pairs"] = len(far)
    check["far_pairs_fitting"] = sum(fits(p) for p in far)
    check["far_pairs_fitting_sampson_only"] = sum(sampson_fits(p) for p in far)
    # Sequential pairs can hold twins too (street: three pairs three frames apart, more twin than
    # true matches; the reference's mapper rejected those matches as outliers of its tracks).
    check["doppelganger_pairs"] = [p for p in pairs if not fits(p)]
    check["sequential_pairs_not_fitting"] = [p for p in near if not fits(p)]
    # Trajectory: centres in capture order.
    seq = sorted(images, key=lambda n: order.get(n, 0))
    centres = {n: bc.camera_centre(images[n][0], images[n][1]) for n in seq}
    axis = {n: images[n][0][2] for n in seq}  # viewing direction = third row of R
    steps = [bc.norm(bc.sub(centres[b], centres[a])) for a, b in zip(seq, seq[1:])]
    median_step = statistics.median(steps) if steps else float("nan")
    check["median_step"] = median_step
    check["max_step_ratio"] = round(max(steps) / median_step, 2) if steps and median_step > 0 else None
    merged = []
    for a in range(len(seq)):
        for b in range(a + args.overlap + 1, len(seq)):
            dist = bc.norm(bc.sub(centres[seq[a]], centres[seq[b]]))
            cosang = sum(axis[seq[a]][k] * axis[seq[b]][k] for k in range(3))
            if dist < 0.3 * median_step and cosang > math.cos(math.radians(15)):
                merged.append([seq[a], seq[b]])
    check["merged_far_images"] = merged
    check["pairs"] = pairs
    return check


# ----------------------------------------------------------------------------------------------
# Engines
# ----------------------------------------------------------------------------------------------

def removed_pairs_of(report):
    return {tuple(sorted(e["pair"])) for e in report.get("removed_edges", [])}


def run_engine(args, prunesfm, engine, work, images):
    out = work / engine
    bs.fresh_folder(out)
    db = out / "database.db"
    bc.copy_database(work / "exhaustive.db", db)
    t = str(args.threads)
    row = {"engine": engine, "stages": []}
    if engine in ("GLOBAL", "GLOBAL_PRUNED"):
        result = out / "result"
        stage = bs.run_ours_on_database(prunesfm, db, images, result, engine, out / "run.log", args.timeout,
                                        ["--num_threads", t, "--seed", str(args.seed)])
        row["stages"].append(stage)
        model, _ = bc.largest_model(result / "sparse")
        report = result / "pruning_report.json"
        if report.is_file():
            row["removed"] = sorted(removed_pairs_of(json.loads(report.read_text())))
        return row, model
    if engine == "colmap+prune":
        pruned = out / "pruned.db"
        stage, report = bs.prune_database(prunesfm, db, pruned, out, t, str(args.seed), args.timeout)
        row["stages"].append(stage)
        if report is None:
            return row, None
        row["removed"] = sorted(removed_pairs_of(report))
        db = pruned
    stage, model = bs.colmap_mapper(args.colmap, db, images, out, t, args.timeout, False)
    row["stages"].append(stage)
    return row, model


# ----------------------------------------------------------------------------------------------
# Trajectory pictures (to judge by eye: a folded model doubles back onto itself)
# ----------------------------------------------------------------------------------------------

def symmetric_eigenvectors(m):
    """Eigenvectors (columns, by decreasing eigenvalue) of a symmetric 3x3 matrix (Jacobi)."""
    a = [row[:] for row in m]
    v = [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]
    for _ in range(50):
        p, q = max(((0, 1), (0, 2), (1, 2)), key=lambda ij: abs(a[ij[0]][ij[1]]))
        if abs(a[p][q]) < 1e-15:
            break
        theta = 0.5 * math.atan2(2 * a[p][q], a[q][q] - a[p][p])
        c, s = math.cos(theta), math.sin(theta)
        for k in range(3):  # a <- J^T a J, v <- v J
            akp, akq = a[k][p], a[k][q]
            a[k][p], a[k][q] = c * akp - s * akq, s * akp + c * akq
        for k in range(3):
            apk, aqk = a[p][k], a[q][k]
            a[p][k], a[q][k] = c * apk - s * aqk, s * apk + c * aqk
        for k in range(3):
            vkp, vkq = v[k][p], v[k][q]
            v[k][p], v[k][q] = c * vkp - s * vkq, s * vkp + c * vkq
    order = sorted(range(3), key=lambda i: -a[i][i])
    return [[v[k][i] for k in range(3)] for i in order]


def model_centres(args, model, out_dir):
    """Camera centres of a model in capture (name) order, via COLMAP's text export."""
    txt = Path(out_dir) / "text"
    bs.fresh_folder(txt)
    bs.colmap_to_text(args.colmap, model, txt, Path(out_dir) / "convert.log", args.timeout)
    if not (txt / "images.txt").is_file():
        return []
    _, images = bc.read_text_model(txt)
    return [(name, bc.camera_centre(images[name][0], images[name][1])) for name in sorted(images)]


def trajectory_svg(panels, path):
    """One panel per model: centres projected on their two principal axes, joined in capture order,
    coloured from blue (first image) to red (last), every 5th image numbered."""
    size, pad = 240, 24
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{size * len(panels)}" height="{size + 20}" '
           'font-family="sans-serif" font-size="10">']
    for k, (title, centres, total) in enumerate(panels):
        x0 = k * size
        svg.append(f'<text x="{x0 + size / 2}" y="14" text-anchor="middle">{title}</text>')
        svg.append(f'<rect x="{x0 + 2}" y="20" width="{size - 4}" height="{size - 4}" fill="none" stroke="#ccc"/>')
        if len(centres) < 3:
            svg.append(f'<text x="{x0 + size / 2}" y="{size / 2}" text-anchor="middle">no model</text>')
            continue
        pts = [c for _, c in centres]
        mean = [sum(p[i] for p in pts) / len(pts) for i in range(3)]
        cov = [[sum((p[i] - mean[i]) * (p[j] - mean[j]) for p in pts) for j in range(3)] for i in range(3)]
        axes = symmetric_eigenvectors(cov)
        xy = [(sum((p[i] - mean[i]) * axes[0][i] for i in range(3)), sum((p[i] - mean[i]) * axes[1][i]
                                                                        for i in range(3))) for p in pts]
        span = max(max(abs(x) for x, _ in xy), max(abs(y) for _, y in xy)) or 1.0
        scale = (size / 2 - pad) / span
        screen = [(x0 + size / 2 + x * scale, 20 + size / 2 - y * scale) for x, y in xy]
        for a, b in zip(screen, screen[1:]):
            svg.append(f'<line x1="{a[0]:.1f}" y1="{a[1]:.1f}" x2="{b[0]:.1f}" y2="{b[1]:.1f}" stroke="#999"/>')
        for idx, ((name, _), (sx, sy)) in enumerate(zip(centres, screen)):
            frac = idx / max(1, len(centres) - 1)
            colour = f"rgb({int(255 * frac)},0,{int(255 * (1 - frac))})"
            svg.append(f'<circle cx="{sx:.1f}" cy="{sy:.1f}" r="3.5" fill="{colour}"/>')
            number = int(Path(name).stem) if Path(name).stem.isdigit() else idx
            if number % 5 == 0:
                svg.append(f'<text x="{sx + 5:.1f}" y="{sy - 4:.1f}">{number}</text>')
        svg.append(f'<text x="{x0 + 6}" y="{size + 12}">{len(centres)}/{total} registered</text>')
    svg.append("</svg>")
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    Path(path).write_text("\n".join(svg) + "\n")


# ----------------------------------------------------------------------------------------------
# Report
# ----------------------------------------------------------------------------------------------

def subgraph_pair_rows(report, check):
    """Per pair of GLOBAL_PRUNED's accepted subgraphs: views, connecting edges, how many of them
    are doppelganger pairs by the reference check, and what the inter-subgraph RANSAC removed."""
    dopp = {tuple(p["pair"]) for p in check["doppelganger_pairs"]}
    accepted = sorted((n for n in report["tree"] if n["accepted_index"] >= 0), key=lambda n: n["accepted_index"])
    names = {tuple(p["pair"]): p["names"] for p in check["pairs"]}
    label = {}
    for p in check["pairs"]:
        for image_id, name in zip(p["pair"], p["names"]):
            label[image_id] = Path(name).stem
    subgraph = {v: n["accepted_index"] for n in accepted for v in n["view_ids"]}
    removed = {tuple(sorted(e["pair"])) for e in report["removed_edges"]}
    rows = []
    for pair in report["subgraph_pairs"]:
        k1, k2 = pair["k1"], pair["k2"]
        between = [p for p in names if {subgraph.get(p[0]), subgraph.get(p[1])} == {k1, k2}]
        rows.append({"k1": k1, "k2": k2, "status": pair["status"], "edges": pair["edges"],
                     "doppelganger": sum(p in dopp for p in between),
                     "removed_doppelganger": sum(p in dopp and p in removed for p in between),
                     "removed_fitting": sum(p not in dopp and p in removed for p in between),
                     "cut_by_loops": bool(pair.get("rejected_by_loops"))})
    views = {n["accepted_index"]: ",".join(sorted(label.get(v, str(v)) for v in n["view_ids"])) for n in accepted}
    return rows, views


TITLE = "Real ambiguous scenes against a sequential-matching reference (books, street)"


def markdown(args, header, results):
    L = list(header)
    L += [f"No ground truth exists for these scenes (`{args.shared}/datasets/ambiguous`, Yan et al. 2017). "
          "The images are in capture order, so a reconstruction from neighbour-only pairs never matches the "
          "doppelgangers: COLMAP 3.8 `feature_extractor` (one SIMPLE_RADIAL camera; **the EXIF focal of "
          "`exif_focal.txt` is given as a known prior**, `--ImageReader.camera_params f,w/2,h/2,0`, so every "
          "engine starts from it), `sequential_matcher` with pairs i, i+1 .. "
          f"i+{args.overlap} (no quadratic overlap, no loop detection), then `mapper` = the reference. "
          "The exhaustive database has the same features, `exhaustive_matcher`. Every engine runs on a copy "
          "of it; `colmap+prune` is COLMAP's mapper on the copy `prunesfm prune` cleaned. AUC@3/5/10 of "
          "the pairwise relative pose errors against the reference (`prunesfm evaluate --estimate M "
          "--ground_truth REF`). Target (issue 5): GLOBAL_PRUNED AUC@5 ≥ 90.", "",
          "How the reference is checked: (1) every image registered in one model; (2) epipolar "
          "consistency: under the reference's poses and intrinsics, the median Sampson error of the "
          "inlier matches of *every pair COLMAP verified in the exhaustive database*; sequential pairs "
          f"must fit (≤ {args.max_sampson_px} px), far pairs that see the same surface fit too, and the "
          "far pairs that do not fit are doppelganger pairs (their matches are between alike copies, "
          "so no single pose explains them); (3) point transfer: every inlier match with a keypoint on a "
          "reference track has that 3D point projected into the other image; a pair whose matches land "
          f"more often > {5 * args.max_transfer_px:g} px from the other keypoint (a copy) than within "
          f"{args.max_transfer_px:g} px (the same point) is a doppelganger pair too, also when it is "
          "sequential. Sampson's test is blind along the epipolar line, and a street's twin lies exactly "
          "there (a facade one period further in the direction the camera walks), so (2) alone misses "
          "it; (4) the trajectory: largest / median step between "
          "consecutive camera centres, and no two images more than "
          f"{args.overlap} frames apart placed at the same spot looking the same way (< 0.3 median "
          "step, < 15°), which is what folding would produce.", ""]
    L += ["| scene | registered | seq. pairs fitting (median Sampson px) | far pairs fitting (by Sampson "
          "alone) | doppelganger "
          "pairs (gap: inliers) | largest / median step | far images merged |",
          "|---|---|---|---|---|---|---|"]
    for scene, r in results.items():
        c = r["check"]
        dopp = ", ".join(f"{p['names'][0][:-4]}–{p['names'][1][:-4]} ({p['gap']}: {p['inliers']})"
                         for p in c["doppelganger_pairs"][:12])
        more = len(c["doppelganger_pairs"]) - 12
        dopp = f"{len(c['doppelganger_pairs'])}: {dopp}" + (f", … {more} more" if more > 0 else "")
        L.append(f"| {scene} | {c['registered']}/{c['images']} in {c['models']} model(s) "
                 f"| {c['sequential_pairs_fitting']}/{c['sequential_pairs']} ({c['sequential_median_sampson_px']}) "
                 f"| {c['far_pairs_fitting']}/{c['far_pairs']} ({c.get('far_pairs_fitting_sampson_only', '–')}) "
                 f"| {dopp} | {c['max_step_ratio']} "
                 f"| {len(c['merged_far_images'])} |")
    L.append("")
    L += ["Camera centres of each model in capture order (blue → red; projected on the model's two "
          "principal axes, each panel in its own frame), to judge by eye: "
          + ", ".join(f"[{scene}](images/ambiguous_{scene}.svg)" for scene in results) + ".", ""]
    L += ["| scene | engine | registered | AUC@3 | AUC@5 | AUC@10 | removed pairs (doppelganger / fitting) "
          "| stages (s) |", "|---|---|---|---|---|---|---|---|"]
    for scene, r in results.items():
        dopp = {tuple(p["pair"]) for p in r["check"]["doppelganger_pairs"]}
        for row in r["engines"]:
            e = row["eval"]
            removed = "–"
            if "removed" in row:
                rem = {tuple(p) for p in row["removed"]}
                removed = f"{len(rem)} ({len(rem & dopp)} / {len(rem - dopp)})"
            stages = " · ".join(f"{s['name']} {s['seconds']:.1f}" + ("" if s["rc"] == 0 else " (failed)")
                                for s in row["stages"])
            L.append(f"| {scene} | {row['engine']} | {e['registered']}/{r['check']['images']} | "
                     f"{e['auc']['3']:.1f} | {e['auc']['5']:.1f} | {e['auc']['10']:.1f} | {removed} | {stages} |")
    L.append("")
    for scene in results:
        report_path = Path(args.work) / scene / "GLOBAL_PRUNED" / "result" / "pruning_report.json"
        if not report_path.is_file():
            continue
        rows, views = subgraph_pair_rows(json.loads(report_path.read_text()), results[scene]["check"])
        L.append(f"{scene}, GLOBAL_PRUNED's inter-subgraph pruning against the reference check (subgraphs: "
                 + "; ".join(f"{k} = {{{v}}}" for k, v in views.items()) + "):")
        L.append("")
        L += ["| subgraph pair | status | connecting edges | doppelganger among them | removed doppelganger "
              "| removed fitting | cut by the loop check |", "|---|---|---|---|---|---|---|"]
        for r in rows:
            L.append(f"| {r['k1']}–{r['k2']} | {r['status']} | {r['edges']} | {r['doppelganger']} "
                     f"| {r['removed_doppelganger']} | {r['removed_fitting']} | {'yes' if r['cut_by_loops'] else ''} |")
        L.append("")
        survivors = [r for r in rows if r["doppelganger"] > r["removed_doppelganger"]]
        if survivors:
            L.append("Doppelganger pairs the pruning leaves: "
                     + ", ".join(f"{r['doppelganger'] - r['removed_doppelganger']} between {r['k1']}–{r['k2']}"
                                 for r in survivors)
                     + ". The inter-subgraph RANSAC keeps the largest mutually consistent set of a pair's edges, "
                     "so where the wrong edges are the majority and agree with each other (one alike copy "
                     "seen from many views) they win; the loop check across pairs cuts such a pair only when "
                     "a triangle through it breaks more often than it closes.")
            L.append("")
    return L


def parse_args(argv):
    p = bs.argument_parser(__doc__, "/tmp/prunesfm-bench-ambiguous")
    p.add_argument("--scenes", default=",".join(SCENES))
    p.add_argument("--engines", default=",".join(ENGINES))
    p.add_argument("--overlap", type=int, default=3, help="sequential pairs: i with i+1 .. i+overlap")
    p.add_argument("--max_sampson_px", type=float, default=4.0,
                   help="a pair fits the reference when its inliers' median Sampson error is below this")
    p.add_argument("--max_transfer_px", type=float, default=4.0,
                   help="a match is true when the reference point of one keypoint projects this close to the other")
    bs.add_options(p, "max_image_size")
    p.add_argument("--reuse", action="store_true",
                   help="keep the features, matches and reference an earlier run left in --work")
    p.add_argument("--prepare_only", action="store_true", help="features, matching, reference and its check only")
    p.add_argument("--rewrite_report", action="store_true",
                   help="run nothing: regenerate the fragment from WORK/results.json and the models in WORK")
    return p.parse_args(argv)


def main(argv):
    args = parse_args(argv)
    if not args.colmap:
        sys.exit("ambiguous_bench: needs Debian's colmap on the PATH (or --colmap)")
    prunesfm = bs.find_prunesfm(args.prunesfm)
    if args.rewrite_report:
        saved = json.loads((Path(args.work) / "results.json").read_text())
        bs.write_fragment("ambiguous", markdown(args, saved["header"], saved["scenes"]))
        return 0
    engines = [e for e in args.engines.split(",") if e]
    for e in engines:
        if e not in ENGINES:
            sys.exit(f"ambiguous_bench: unknown engine {e} (known: {', '.join(ENGINES)})")
    header = bs.header_lines(TITLE, ["bench/ambiguous_bench.py"] + argv, prunesfm, args.colmap)
    results = {}
    for scene in [s for s in args.scenes.split(",") if s]:
        if scene not in SCENES:
            sys.exit(f"ambiguous_bench: unknown scene {scene} (known: {', '.join(SCENES)})")
        print(f"== {scene}", flush=True)
        work = Path(args.work).resolve() / scene
        work.mkdir(parents=True, exist_ok=True)
        images, camera, prep = prepare(args, scene, work)
        model, num_models, txt, ref_stages = build_reference(args, work, images)
        check = check_reference(args, work, txt, num_models)
        (work / "reference_check.json").write_text(json.dumps(check, indent=2) + "\n")
        print(f"  reference: {check['registered']}/{check['images']} registered, sequential pairs fitting "
              f"{check['sequential_pairs_fitting']}/{check['sequential_pairs']}, far pairs fitting "
              f"{check['far_pairs_fitting']}/{check['far_pairs']}, doppelganger pairs "
              f"{len(check['doppelganger_pairs'])}", flush=True)
        result = {"camera": camera, "prep": prep + ref_stages, "check": check, "engines": []}
        panels = [("reference (sequential)", model_centres(args, model, work / "reference"), check["images"])]
        if not args.prepare_only:
            for engine in engines:
                row, estimate = run_engine(args, prunesfm, engine, work, images)
                row["eval"] = bs.evaluate_against(prunesfm, estimate, model, work / engine, str(args.seed),
                                                  args.timeout)
                print(f"  {engine}: {row['eval']}", flush=True)
                result["engines"].append(row)
                centres = model_centres(args, estimate, work / engine) if estimate is not None else []
                panels.append((engine, centres, check["images"]))
            trajectory_svg(panels, bs.REPO / "docs" / "images" / f"ambiguous_{scene}.svg")
        results[scene] = result
    if not args.prepare_only:
        (Path(args.work) / "results.json").write_text(json.dumps({"header": header, "scenes": results}, indent=2) + "\n")
        bs.write_fragment("ambiguous", markdown(args, header, results))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
