"""COLMAP's files as the scripts of bench/ read and edit them, beside bench_support.py: databases
(pair ids, copies that keep the write-ahead log, verified pairs, keypoints and inliers), models
(the largest one a mapper wrote, text models with their poses and tracks) and the camera geometry
to use them (rotations from quaternions, small 3x3 algebra, projection and undistortion of the
camera models the benchmarks use). Python 3 standard library only."""

import math
import sqlite3
import struct
import sys
from pathlib import Path

# COLMAP's images and pair ids: pair_id = image_id1 * 2147483647 + image_id2 (image_id1 < image_id2).
COLMAP_PAIR_BASE = 2147483647


def image_pair(pair_id):
    """(image_id1, image_id2) of a COLMAP pair id."""
    return divmod(pair_id, COLMAP_PAIR_BASE)


# ----------------------------------------------------------------------------------------------
# Databases
# ----------------------------------------------------------------------------------------------

def copy_database(src, dst):
    """Copies an SQLite database with its pending write-ahead log (COLMAP 3.8 leaves its changes in
    database.db-wal at exit: copying the file alone loses them)."""
    if Path(dst).exists():
        Path(dst).unlink()
    with sqlite3.connect(str(src)) as source, sqlite3.connect(str(dst)) as target:
        source.backup(target)
    source.close()
    target.close()


def fold_wal(db):
    """COLMAP 3.8 leaves its last writes in DB-wal: checkpoint them into the file."""
    con = sqlite3.connect(str(db))
    try:
        con.execute("PRAGMA wal_checkpoint(TRUNCATE)")
    finally:
        con.close()


def has_keypoints(db):
    if not Path(db).is_file():
        return False
    try:
        con = sqlite3.connect(str(db))
        n = con.execute("SELECT COUNT(*) FROM keypoints WHERE rows > 0").fetchone()[0]
        con.close()
        return n > 0
    except sqlite3.Error:
        return False


def num_verified_pairs(db_path):
    """Pairs with inliers in two_view_geometries, 0 unless every matched pair has been verified (an
    interrupted COLMAP run is not reused) or if the database is missing."""
    if not Path(db_path).is_file():
        return 0
    try:
        # A read-write connection: closing it folds a pending write-ahead log into the file.
        db = sqlite3.connect(str(db_path))
        try:
            verified, inliers = db.execute(
                "SELECT COUNT(*), COALESCE(SUM(rows > 0), 0) FROM two_view_geometries").fetchone()
            matched = db.execute("SELECT COUNT(*) FROM matches").fetchone()[0]
        finally:
            db.close()
    except sqlite3.Error:
        return 0
    return inliers if verified >= matched else 0


def matched_pairs(db_path):
    """names {image_id: name} and the image pairs with putative matches."""
    with sqlite3.connect(str(db_path)) as db:
        names = dict(db.execute("SELECT image_id, name FROM images"))
        pairs = [image_pair(pid) for (pid,) in db.execute("SELECT pair_id FROM matches WHERE rows > 0")]
    return names, pairs


def verified_pairs(db_path):
    """The image pairs with inliers in two_view_geometries."""
    with sqlite3.connect(str(db_path)) as db:
        ids = [pid for (pid,) in db.execute("SELECT pair_id FROM two_view_geometries WHERE rows > 0")]
    db.close()
    return {image_pair(pid) for pid in ids}


def read_database(db_path):
    """names {image_id: name}, keypoints {image_id: [(x, y)]}, inliers {(id1, id2): [(i, j)]}."""
    db = sqlite3.connect(str(db_path))
    try:
        names = dict(db.execute("SELECT image_id, name FROM images"))
        keypoints = {}
        for image_id, rows, cols, data in db.execute("SELECT image_id, rows, cols, data FROM keypoints"):
            values = struct.unpack(f"<{rows * cols}f", data) if rows else ()
            keypoints[image_id] = [(values[r * cols], values[r * cols + 1]) for r in range(rows)]
        inliers = {}
        for pair_id, rows, data in db.execute("SELECT pair_id, rows, data FROM two_view_geometries WHERE rows > 0"):
            values = struct.unpack(f"<{rows * 2}I", data)
            inliers[image_pair(pair_id)] = [(values[2 * r], values[2 * r + 1]) for r in range(rows)]
    finally:
        db.close()
    return names, keypoints, inliers


# ----------------------------------------------------------------------------------------------
# Models
# ----------------------------------------------------------------------------------------------

def num_registered(model_dir):
    images_bin = model_dir / "images.bin"
    if images_bin.is_file():
        with open(images_bin, "rb") as f:
            return struct.unpack("<Q", f.read(8))[0]
    images_txt = model_dir / "images.txt"
    if images_txt.is_file():
        lines = [l for l in images_txt.read_text().splitlines() if l and not l.startswith("#")]
        return len(lines) // 2
    return 0


def largest_model(sparse_dir):
    """COLMAP's mapper writes sparse/0, sparse/1, ...: the model with most registered images."""
    if not sparse_dir.is_dir():
        return None, 0
    models = [d for d in sorted(sparse_dir.iterdir()) if d.is_dir() and
              ((d / "cameras.bin").is_file() or (d / "cameras.txt").is_file())]
    if not models:
        return None, 0
    best = max(models, key=lambda d: (num_registered(d), -int(d.name) if d.name.isdigit() else 0))
    return best, len(models)


def read_text_model(folder):
    """cameras {id: (model, w, h, params)}, images {name: (R, t, camera_id)} (world to camera)."""
    cameras, images = {}, {}
    for line in (Path(folder) / "cameras.txt").read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            f = line.split()
            cameras[int(f[0])] = (f[1], int(f[2]), int(f[3]), [float(x) for x in f[4:]])
    lines = [l for l in (Path(folder) / "images.txt").read_text().splitlines() if not l.startswith("#")]
    for line in lines[0::2]:
        f = line.split()
        if len(f) < 10:
            continue
        images[f[9]] = (quat_to_rot(*map(float, f[1:5])), [float(x) for x in f[5:8]], int(f[8]))
    return cameras, images


def read_text_tracks(folder):
    """The tracks of a text model: point ids {name: [point3D_id per keypoint, -1 = none]} and
    points {point3D_id: xyz}."""
    lines = [l for l in (Path(folder) / "images.txt").read_text().splitlines() if not l.startswith("#")]
    point_ids = {}
    for header, observations in zip(lines[0::2], lines[1::2]):
        f = header.split()
        if len(f) < 10:
            continue
        values = observations.split()
        point_ids[f[9]] = [int(values[k]) for k in range(2, len(values), 3)]
    points = {}
    for line in (Path(folder) / "points3D.txt").read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            f = line.split()
            points[int(f[0])] = [float(x) for x in f[1:4]]
    return point_ids, points


# ----------------------------------------------------------------------------------------------
# Small 3-vector / 3x3 algebra and COLMAP's cameras
# ----------------------------------------------------------------------------------------------

def quat_to_rot(qw, qx, qy, qz):
    n = math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz)
    w, x, y, z = qw / n, qx / n, qy / n, qz / n
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def matvec(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def norm(v):
    return math.sqrt(sum(x * x for x in v))


def skew(t):
    return [[0, -t[2], t[1]], [t[2], 0, -t[0]], [-t[1], t[0], 0]]


def camera_centre(R, t):
    """The centre -R^T t of a camera whose pose maps world to camera (COLMAP's convention)."""
    return [-x for x in matvec(transpose(R), t)]


def intrinsics(camera):
    """fx, fy, cx, cy, k (radial) of a text model's camera (SIMPLE_RADIAL, the model the benchmarks
    give COLMAP; PINHOLE/SIMPLE_PINHOLE for completeness)."""
    model, _, _, p = camera
    if model == "SIMPLE_RADIAL":
        return p[0], p[0], p[1], p[2], p[3]
    if model == "SIMPLE_PINHOLE":
        return p[0], p[0], p[1], p[2], 0.0
    if model == "PINHOLE":
        return p[0], p[1], p[2], p[3], 0.0
    sys.exit(f"{Path(sys.argv[0]).stem}: camera model {model} not handled")


def project(camera, R, t, X):
    """Pixel of world point X in a camera (COLMAP convention), None behind it."""
    fx, fy, cx, cy, k = intrinsics(camera)
    x = [a + b for a, b in zip(matvec(R, X), t)]
    if x[2] <= 0:
        return None
    u, v = x[0] / x[2], x[1] / x[2]
    s = 1.0 + k * (u * u + v * v)
    return fx * u * s + cx, fy * v * s + cy


def normalized(camera, xy):
    """Pixel (COLMAP convention) -> undistorted normalized coordinates."""
    fx, fy, cx, cy, k = intrinsics(camera)
    ud, vd = (xy[0] - cx) / fx, (xy[1] - cy) / fy
    u, v = ud, vd
    for _ in range(20):  # x_d = x_u (1 + k r_u^2): fixed point
        s = 1.0 + k * (u * u + v * v)
        u, v = ud / s, vd / s
    return u, v
