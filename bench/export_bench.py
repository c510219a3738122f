#!/usr/bin/env python3
"""Export for dense reconstruction (issue 7) against COLMAP 3.8: `prunesfm export --format
colmap-undistorted` and `colmap image_undistorter` on the same distorted model and images (time,
memory, the undistorted camera each chooses, whether the stereo configuration files are
byte-identical, what `colmap model_analyzer` says of our workspace), and the time of `--format
openmvs` and `--format ply`.

Models: the Middlebury temple ring as COLMAP 3.8 reconstructed it in bench/run_benchmarks.py's
--work folder (`templeSparseRing/colmap/sparse/0`, one SIMPLE_RADIAL camera), and OpenMVG's
reconstruction of Sceaux Castle in ../shared/formats/openmvg (one pinhole_radial_k3 camera,
2832x2128 images), converted to a COLMAP model with `prunesfm convert` so that COLMAP can read it.
Writes bench/sections/export.md. Python 3 standard library only.
"""

import filecmp
import re
import struct
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_support as bs  # noqa: E402

# COLMAP camera model ids and parameter counts (FORMATS.md), enough to read the undistorted cameras.
CAMERA_MODELS = {0: ("SIMPLE_PINHOLE", 3), 1: ("PINHOLE", 4), 2: ("SIMPLE_RADIAL", 4), 3: ("RADIAL", 5),
                 4: ("OPENCV", 8), 5: ("OPENCV_FISHEYE", 8), 6: ("FULL_OPENCV", 12)}


def first_camera(cameras_bin):
    """'PINHOLE 640x480 f 1512.1' for the first camera of a cameras.bin."""
    data = Path(cameras_bin).read_bytes()
    _, model, width, height = struct.unpack_from("<iiQQ", data, 8)
    name, count = CAMERA_MODELS.get(model, (f"model {model}", 0))
    params = struct.unpack_from(f"<{count}d", data, 32)
    return f"{name} {width}x{height} f {params[0]:.1f}"


def analyzer_summary(log):
    text = Path(log).read_text(errors="replace")
    fields = []
    for key in ("Cameras", "Registered images", "Points", "Observations"):
        m = re.search(rf"{key}: (\d+)", text)
        fields.append(f"{key.lower()} {m.group(1) if m else '?'}")
    return ", ".join(fields)


def scene_inputs(args, prunesfm, scene, out):
    """(model path our exporter reads, COLMAP model folder, image folder) or an error string."""
    shared = Path(args.shared)
    if scene == "templeSparseRing":
        model = Path(args.bench_work) / "templeSparseRing" / "colmap" / "sparse" / "0"
        images = shared / "datasets" / "middlebury" / "templeSparseRing" / "images"
        if not (model / "cameras.bin").is_file():
            return f"input missing: {model} (run bench/run_benchmarks.py with the colmap engine first)"
        return model, model, images
    model = shared / "formats" / "openmvg" / "sceaux_castle" / "reconstruction_global" / "sfm_data.json"
    images = shared / "datasets" / "sceaux_castle" / "images"
    if not model.is_file():
        return f"input missing: {model}"
    colmap_model = out / "distorted"
    stage = bs.run_stage("convert", [prunesfm, "convert", "--input", model, "--output", colmap_model],
                         out / "convert.log", args.timeout)
    if stage["rc"] != 0:
        return f"convert failed: {stage.get('error')}"
    return model, colmap_model, images


def run_scene(args, prunesfm, colmap, scene):
    out = Path(args.work) / scene
    bs.fresh_folder(out)
    inputs = scene_inputs(args, prunesfm, scene, out)
    if isinstance(inputs, str):
        return {"scene": scene, "status": inputs}
    model, colmap_model, images = inputs
    threads = str(args.threads)
    row = {"scene": scene, "status": "ok", "images": len(list(images.iterdir()))}
    ours = bs.run_stage("export colmap-undistorted",
                        [prunesfm, "export", "--model", model, "--images", images, "--format", "colmap-undistorted",
                         "--output", out / "ours", "--num_threads", threads], out / "export.log", args.timeout)
    theirs = bs.run_stage("image_undistorter",
                          [colmap, "image_undistorter", "--image_path", images, "--input_path", colmap_model,
                           "--output_path", out / "colmap", "--output_type", "COLMAP"],
                          out / "undistorter.log", args.timeout, bs.colmap_env())
    mvs = bs.run_stage("export openmvs", [prunesfm, "export", "--model", model, "--images", images, "--format",
                                          "openmvs", "--output", out / "mvs", "--num_threads", threads],
                       out / "export_mvs.log", args.timeout)
    ply = bs.run_stage("export ply", [prunesfm, "export", "--model", model, "--images", images, "--format", "ply",
                                      "--output", out / "points.ply", "--num_threads", threads],
                       out / "export_ply.log", args.timeout)
    for stage in (ours, theirs, mvs, ply):
        if stage["rc"] != 0:
            row["status"] = f"{stage['name']} failed: {stage.get('error')}"
            return row
    analyzer = bs.run_stage("model_analyzer", [colmap, "model_analyzer", "--path", out / "ours" / "sparse"],
                            out / "analyzer.log", args.timeout, bs.colmap_env())
    row.update({
        "ours": ours, "colmap": theirs, "openmvs": mvs, "ply": ply,
        "ours_camera": first_camera(out / "ours" / "sparse" / "cameras.bin"),
        "colmap_camera": first_camera(out / "colmap" / "sparse" / "cameras.bin"),
        "original_camera": first_camera(colmap_model / "cameras.bin"),
        "analyzer": analyzer_summary(out / "analyzer.log") if analyzer["rc"] == 0 else f"failed: {analyzer.get('error')}",
        "cfg_identical": all(filecmp.cmp(out / "ours" / "stereo" / f, out / "colmap" / "stereo" / f, shallow=False)
                             for f in ("patch-match.cfg", "fusion.cfg")),
    })
    return row


def fragment(args, argv, prunesfm, colmap, rows):
    lines = bs.header_lines("Export for dense reconstruction against COLMAP's image_undistorter (`bench/export_bench.py`)",
                            argv, prunesfm, colmap)
    lines += ["`prunesfm export --format colmap-undistorted` and `colmap image_undistorter --output_type COLMAP` "
              "on the same distorted model and images; `--format openmvs` and `--format ply` on the same input. "
              "Times are wall seconds with peak memory; the undistorted camera is the first camera each tool "
              "writes (ours keeps the image size and crops to no black borders, COLMAP keeps the focal length "
              "and changes the size). The image content of both workspaces agrees along the same rays to about "
              "1-2 grey levels (measured in `tests/interop` and `docs/export.md`).", "",
              "| scene | image files | original camera | ours: camera | ours: s (MB) | COLMAP: camera | COLMAP: s (MB) "
              "| ours / COLMAP time | stereo cfg identical | model_analyzer on ours | openmvs s (MB) | ply s (MB) |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        if row["status"] != "ok":
            lines.append(f"| {row['scene']} | {row['status']} |" + " |" * 10)
            continue

        def t(stage):
            return f"{stage['seconds']:.1f} ({stage['peak_mb']:.0f})"
        ratio = row["ours"]["seconds"] / max(row["colmap"]["seconds"], 1e-9)
        lines.append(f"| {row['scene']} | {row['images']} | {row['original_camera']} | {row['ours_camera']} | "
                     f"{t(row['ours'])} | {row['colmap_camera']} | {t(row['colmap'])} | {ratio:.2f} | "
                     f"{'yes' if row['cfg_identical'] else 'no'} | {row['analyzer']} | {t(row['openmvs'])} | "
                     f"{t(row['ply'])} |")
    return lines


def main(argv):
    parser = bs.argument_parser(__doc__, "/tmp/prunesfm-export-bench")
    parser.add_argument("--bench_work", default="/tmp/prunesfm-bench",
                        help="bench/run_benchmarks.py's --work folder (COLMAP's temple model)")
    parser.add_argument("--scenes", default="templeSparseRing,sceaux_castle")
    args = parser.parse_args(argv[1:])
    prunesfm = bs.find_prunesfm(args.prunesfm)
    colmap = args.colmap
    if not colmap:
        sys.exit("export_bench: colmap not found (Debian package colmap)")
    rows = [run_scene(args, prunesfm, colmap, scene) for scene in args.scenes.split(",")]
    bs.write_fragment("export", fragment(args, argv, prunesfm, colmap, rows))


if __name__ == "__main__":
    main(sys.argv)
