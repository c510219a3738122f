#!/usr/bin/env python3
"""Disambiguation over a distribution of scenes: the procedural families of `prunesfm synth`
(family_street, family_courtyard, family_object, family_desk, family_loop, family_control), each
seed a different scene, on two input paths, with GLOBAL and COLMAP 3.8 in the same run.

The split is fixed by seed ranges, before any result is seen:
  development  seeds 0 .. N-1            (tune on these)
  held-out     seeds 100000 .. 100000+N-1 (only reported; never used to choose an option)

Input paths:
  own     `prunesfm run --database` on synth's database (putative matches only): our verification
  colmap  COLMAP 3.8 verifies the same putative matches (`exhaustive_matcher`, or
          `matches_importer` for the loops' pair lists), then `prunesfm run --database` takes its
          two-view geometries, and COLMAP's own `mapper` runs on the same database

Every result is kept in --work (one result.json per scene, input and engine) and reused by the next
run unless --fresh, so a long benchmark can be stopped and resumed. Python 3 standard library.

  python3 bench/family_bench.py --per_family 17 --jobs 2          # both splits, both inputs
  python3 bench/family_bench.py --split dev --inputs own --per_family 6 --families family_street
"""

import argparse
import concurrent.futures
import json
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_colmap as bc  # noqa: E402
import bench_support as bs  # noqa: E402

FAMILIES = ["family_street", "family_courtyard", "family_object", "family_desk", "family_loop", "family_control"]
SPLIT_FIRST_SEED = {"dev": 0, "heldout": 100000}
# The oracles (EVALUATION.md): GLOBAL on the pairs whose twin matches do not outnumber their true
# ones (a perfect edge pruning), and on those pairs with every twin match deleted too (perfect
# match filtering). A family the first solves fails at the level of edges; one only the second
# solves fails at the level of matches inside true pairs.
ORACLES = {"GLOBAL@oracle_edges": False, "GLOBAL@oracle_matches": True}
BARS = (90.0, 95.0)


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    bs.add_options(p, "prunesfm", "colmap", prunesfm={"help": bs.NEWEST_BUILD_HELP},
                   colmap={"default": "colmap", "help": None})
    p.add_argument("--families", default=",".join(FAMILIES))
    p.add_argument("--split", default="dev,heldout", help="dev, heldout or both (comma-separated)")
    p.add_argument("--per_family", type=int, default=17, help="scenes per family and split")
    p.add_argument("--inputs", default="own,colmap", help="own, colmap or both")
    p.add_argument("--engines", default="GLOBAL,GLOBAL_PRUNED,colmap",
                   help="ours (GLOBAL, GLOBAL_PRUNED), colmap (its mapper, on the colmap input only) and "
                        "the oracles GLOBAL@oracle_edges, GLOBAL@oracle_matches (own input only)")
    p.add_argument("--extra", default="", help="extra arguments for every `prunesfm run` (a variant)")
    p.add_argument("--label", default="", help="name of the variant given by --extra (its own result folders)")
    p.add_argument("--ablation", action="append", default=[], metavar="NAME=FLAGS",
                   help="also run GLOBAL_PRUNED with FLAGS on the own input (results under GLOBAL_PRUNED+NAME) and "
                        "report it beside the defaults in the ablation table; repeatable")
    bs.add_options(p, "jobs", "timeout", "work",
                   jobs={"default": 2, "help": "scenes run at once (each tool on 1 thread)"},
                   timeout={"default": 1800, "help": "seconds per stage"},
                   work={"default": "/tmp/prunesfm-families", "help": None})
    p.add_argument("--fresh", action="store_true", help="recompute results already in --work")
    p.add_argument("--report_only", action="store_true",
                   help="compute nothing: report the results already in --work (a partial run says how many)")
    p.add_argument("--output", default=None, help="markdown report (default: print only)")
    p.add_argument("--json", default=None, help="every row, machine-readable")
    args = p.parse_args(argv)
    args.ablations = []
    for spec in args.ablation:
        name, sep, flags = spec.partition("=")
        if not sep or not name or "/" in name:
            p.error(f"--ablation {spec!r}: expected NAME=FLAGS")
        args.ablations.append((name, flags))
    return args


def scene_list(args):
    scenes = []
    for split in args.split.split(","):
        first = SPLIT_FIRST_SEED[split]
        for family in args.families.split(","):
            for k in range(args.per_family):
                seed = first + k
                scenes.append({"split": split, "family": family, "seed": seed, "key": f"{family}-{seed}"})
    return scenes


def prepare(args, prunesfm, scene):
    """synth, once per scene (kept in --work)."""
    folder = Path(args.work) / scene["key"]
    synth = folder / "synth"
    if not (synth / "database.db").is_file():
        stage = bs.run_stage("synth", [prunesfm, "synth", "--scene", scene["family"], "--seed", scene["seed"],
                                       "--output", synth], folder / "synth.log", args.timeout)
        if stage["rc"] != 0:
            raise RuntimeError(f"{scene['key']}: synth failed: {stage.get('error')}")
    summary = json.loads((synth / "ground_truth" / "synthetic_scene.json").read_text())
    return synth, summary


def colmap_verified(args, scene, synth):
    """COLMAP 3.8's verification of the scene's putative matches (kept in --work)."""
    folder = Path(args.work) / scene["key"]
    verified = folder / "colmap_verified.db"
    if verified.is_file() and bc.num_verified_pairs(verified) > 0:
        return verified
    scratch = folder / "colmap_verify.db"
    bc.copy_database(synth / "database.db", scratch)
    stage = bs.verify_synthetic_matches("colmap verify", args.colmap, scratch, folder / "pairs.txt",
                                        folder / "colmap_verify.log", 1, args.timeout)
    if stage["rc"] != 0:
        raise RuntimeError(f"{scene['key']}: COLMAP verification failed: {stage.get('error')}")
    bc.copy_database(scratch, verified)
    scratch.unlink()
    return verified


def edge_verdicts(synth, result_dir):
    """How the solve's view graph treats the scene's pairs: verified edges whose twin matches
    outnumber their true ones ("twin edges") and the others, each kept or removed by the pruning
    (view_graph.json of `prunesfm run`); None when the run wrote no view graph."""
    graph_path = Path(result_dir) / "view_graph.json"
    if not graph_path.is_file():
        return None
    stats = {(p["i"], p["j"]): p for p in json.loads((synth / "ground_truth" / "synthetic_scene.json").read_text())["pairs"]}
    counts = {"twin_kept": 0, "twin_removed": 0, "true_kept": 0, "true_removed": 0}
    for edge in json.loads(graph_path.read_text())["edges"]:
        pair = stats.get((min(edge["i"], edge["j"]), max(edge["i"], edge["j"])))
        kind = "twin" if pair is not None and pair["twin"] > pair["true"] else "true"
        counts[f"{kind}_{'removed' if edge['removed'] else 'kept'}"] += 1
    return counts


def engine_label(args, engine, ablation=None):
    """The engine's name in results and folders: ours with the variant's --label (or the ablation's
    name) appended."""
    suffix = ablation[0] if ablation else args.label
    return engine + (f"+{suffix}" if suffix and engine != "colmap" else "")


def with_scene_draws(row, family):
    """The row with the scene's drawn geometry and realised unique share (synthetic_scene.json)."""
    row["geometry"] = family.get("labels", {}).get("geometry")
    row["unique_share"] = family.get("values", {}).get("unique_share")
    return row


def run_engine(args, prunesfm, scene, synth, input_path, database, engine, ablation=None):
    label = engine_label(args, engine, ablation)
    extra = ablation[1] if ablation else args.extra
    out = Path(args.work) / scene["key"] / input_path / label
    result_path = out / "result.json"
    if result_path.is_file() and not args.fresh:
        return json.loads(result_path.read_text())
    bs.fresh_folder(out)
    db = out / "database.db"
    bc.copy_database(database, db)
    images = out / "images"  # empty: synthetic scenes are features only (COLMAP wants the folder)
    images.mkdir()
    if engine in ORACLES:
        truth = synth / "ground_truth"
        twin_pairs, _ = bs.twin_dominated_pairs(truth / "synthetic_scene.json", 1.0)
        bs.delete_pairs(db, twin_pairs)
        if ORACLES[engine]:
            bs.delete_twin_matches(db, bs.read_feature_landmarks(truth / "feature_landmarks.txt"))
    if engine == "colmap":
        stage, model = bs.colmap_mapper(args.colmap, db, images, out, 1, args.timeout, synthetic=True)
    else:
        stage = bs.run_ours_on_database(prunesfm, db, images, out / "result", engine.split("@")[0], out / "run.log",
                                        args.timeout, ["--num_threads", 1, *extra.split()])
        model, _ = bc.largest_model(out / "result" / "sparse")
    evaluation = bs.evaluate_against(prunesfm, model, synth / "ground_truth" / "gt_cameras.txt", out, 0,
                                     args.timeout)
    result = {"scene": scene["key"], "family": scene["family"], "seed": scene["seed"], "split": scene["split"],
              "input": input_path, "engine": label, "seconds": stage["seconds"], "rc": stage["rc"],
              "registered": evaluation["registered"], "num_views": evaluation["num_reference"],
              "auc": evaluation["auc"], "edges": edge_verdicts(synth, out / "result"), "extra": extra}
    db.unlink()
    result_path.write_text(json.dumps(result, indent=1) + "\n")
    return result


def cached_rows(args, scene):
    """The results of `scene` already in --work, for --report_only."""
    folder = Path(args.work) / scene["key"]
    summary_path = folder / "synth" / "ground_truth" / "synthetic_scene.json"
    family = json.loads(summary_path.read_text()).get("family", {}) if summary_path.is_file() else {}
    rows = []
    for input_path in args.inputs.split(","):
        for engine in args.engines.split(","):
            result_path = folder / input_path / engine_label(args, engine) / "result.json"
            if result_path.is_file():
                rows.append(with_scene_draws(json.loads(result_path.read_text()), family))
    for ablation in args.ablations:
        result_path = folder / "own" / engine_label(args, "GLOBAL_PRUNED", ablation) / "result.json"
        if "own" in args.inputs.split(",") and result_path.is_file():
            rows.append(dict(with_scene_draws(json.loads(result_path.read_text()), family), ablation=ablation[0]))
    return rows


def print_row(scene, input_path, row):
    print(f"{scene['key']} {input_path} {row['engine']}: AUC@10 {row['auc']['10']:.1f} "
          f"({row['registered']}/{row['num_views']}, {row['seconds']:.0f} s)", flush=True)


def run_scene(args, prunesfm, scene):
    if args.report_only:
        return cached_rows(args, scene)
    synth, summary = prepare(args, prunesfm, scene)
    family = summary.get("family", {})
    rows = []
    engines = args.engines.split(",")
    for input_path in args.inputs.split(","):
        database = synth / "database.db" if input_path == "own" else colmap_verified(args, scene, synth)
        for engine in engines:
            if (engine == "colmap" and input_path != "colmap") or (engine in ORACLES and input_path != "own"):
                continue
            row = with_scene_draws(run_engine(args, prunesfm, scene, synth, input_path, database, engine), family)
            rows.append(row)
            print_row(scene, input_path, row)
        if input_path != "own":
            continue
        for ablation in args.ablations:
            row = with_scene_draws(run_engine(args, prunesfm, scene, synth, input_path, database, "GLOBAL_PRUNED",
                                              ablation), family)
            rows.append(dict(row, ablation=ablation[0]))
            print_row(scene, input_path, row)
    return rows


def percentile(values, q):
    """Linear-interpolated q-th percentile (q in [0, 100]) of a non-empty list."""
    ordered = sorted(values)
    position = (len(ordered) - 1) * q / 100.0
    low = int(position)
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (position - low)


def summarise(rows):
    """Per (split, family, input, engine): n, median, 10th percentile, shares above the bars."""
    groups = {}
    for row in rows:
        groups.setdefault((row["split"], row["family"], row["input"], row["engine"]), []).append(row["auc"]["10"])
    table = []
    for (split, family, input_path, engine), values in sorted(groups.items()):
        table.append({"split": split, "family": family, "input": input_path, "engine": engine, "n": len(values),
                      "median": statistics.median(values), "p10": percentile(values, 10),
                      **{f"share_{bar:g}": sum(v >= bar for v in values) / len(values) for bar in BARS}})
    return table


def failure_kinds(rows, bar=95.0):
    """Per (split, family): how many scenes each oracle solves (own input)."""
    oracle = {}
    for row in rows:
        if row["input"] == "own" and row["engine"] in ORACLES:
            oracle.setdefault((row["split"], row["family"], row["seed"]), {})[row["engine"]] = row["auc"]["10"]
    kinds = {}
    for (split, family, _), values in oracle.items():
        if len(values) < len(ORACLES):
            continue
        edges, matches = values["GLOBAL@oracle_edges"], values["GLOBAL@oracle_matches"]
        k = kinds.setdefault((split, family), {"n": 0, "edges": 0, "matches": 0, "neither": 0, "edge_auc": [],
                                               "match_auc": []})
        k["n"] += 1
        k["edges" if edges >= bar else "matches" if matches >= bar else "neither"] += 1
        k["edge_auc"].append(edges)
        k["match_auc"].append(matches)
    return kinds


def control_drops(rows):
    """For each twin-free control: GLOBAL_PRUNED's AUC@10 minus GLOBAL's on the same input."""
    by_key = {(r["scene"], r["input"], r["engine"]): r["auc"]["10"] for r in rows if r["family"] == "family_control"}
    drops = []
    for (scene, input_path, engine), value in by_key.items():
        if engine.startswith("GLOBAL_PRUNED") and (scene, input_path, "GLOBAL") in by_key:
            drops.append((value - by_key[(scene, input_path, "GLOBAL")], scene, input_path))
    return sorted(drops)


def ablation_lines(args, rows):
    """The ablation table: per split and family, GLOBAL_PRUNED at the defaults and each --ablation
    variant (own input): median / 10th percentile / share >= 95."""
    names = [name for name, _ in args.ablations]
    cells = {}
    for row in rows:
        if row["input"] != "own" or not (row["engine"] == "GLOBAL_PRUNED" or row.get("ablation") in names):
            continue
        column = row.get("ablation", "defaults")
        cells.setdefault((row["split"], row["family"], column), []).append(row["auc"]["10"])
    columns = ["defaults", *names]
    lines = ["### Ablation (own input)", "",
             "GLOBAL_PRUNED at the defaults and with each variant's flags: AUC@10 median / 10th percentile / share "
             "of scenes >= 95, on both splits. " +
             "; ".join(f"`{name}`: `{flags}`" for name, flags in args.ablations) + ".", "",
             "| split | family | " + " | ".join(columns) + " |", "|---|---|" + "---|" * len(columns)]
    for split in ("heldout", "dev"):
        for family in args.families.split(","):
            row_cells = []
            for column in columns:
                values = cells.get((split, family, column))
                row_cells.append(f"{statistics.median(values):.1f} / {percentile(values, 10):.1f} / "
                                 f"{100 * sum(v >= 95.0 for v in values) / len(values):.0f} %" if values else "–")
            if any(c != "–" for c in row_cells):
                lines.append(f"| {split} | {family} | " + " | ".join(row_cells) + " |")
    return lines + [""]


def stage_seconds(args, row):
    """{stage: seconds summed over its runs} of the run behind `row` (its timings.json), or {}."""
    path = Path(args.work) / row["scene"] / row["input"] / row["engine"] / "result" / "timings.json"
    if not path.is_file():
        return {}
    return bs.stage_totals(json.loads(path.read_text()).get("stages", []))


def cost_lines(args, rows):
    """Per split, family and input: GLOBAL's time, GLOBAL_PRUNED's time over GLOBAL's, and the share
    of GLOBAL's run spent verifying the pairs (from the stages of each run's timings.json)."""
    by_scene = {}
    for row in rows:
        if row["engine"] in ("GLOBAL", "GLOBAL_PRUNED") and row["rc"] == 0:
            by_scene.setdefault((row["split"], row["family"], row["input"], row["seed"]), {})[row["engine"]] = row
    cells = {}
    for (split, family, input_path, _), engines in by_scene.items():
        if len(engines) < 2:
            continue
        glob_stages = stage_seconds(args, engines["GLOBAL"])
        pruned_stages = stage_seconds(args, engines["GLOBAL_PRUNED"])
        if not glob_stages or not pruned_stages:
            continue
        glob_total, pruned_total = sum(glob_stages.values()), sum(pruned_stages.values())
        cell = cells.setdefault((split, family, input_path), {"global": [], "ratio": [], "verification": []})
        cell["global"].append(glob_total)
        cell["ratio"].append(pruned_total / max(glob_total, 1e-9))
        cell["verification"].append(glob_stages.get("verification", 0.0) / max(glob_total, 1e-9))
    if not cells:
        return []
    lines = ["### Cost", "",
             "Per scene, the stages of each run (its `timings.json`, summed; one thread, two scenes at a time): "
             "GLOBAL's time, GLOBAL_PRUNED's time over GLOBAL's (median, largest, and how many scenes stay within "
             "1.3), and the share of GLOBAL's time spent verifying the pairs (median, largest; from COLMAP's input "
             "this re-estimates each stored pair's pose).", "",
             "| split | family | input | scenes | GLOBAL median s | GLOBAL_PRUNED / GLOBAL median | largest | "
             "<= 1.3 | verification share median | largest |", "|---|---|---|---|---|---|---|---|---|---|"]
    for (split, family, input_path), cell in sorted(cells.items()):
        n = len(cell["ratio"])
        lines.append(f"| {split} | {family} | {input_path} | {n} | {statistics.median(cell['global']):.1f} | "
                     f"{statistics.median(cell['ratio']):.2f} | {max(cell['ratio']):.2f} | "
                     f"{sum(r <= 1.3 for r in cell['ratio'])} of {n} | "
                     f"{100 * statistics.median(cell['verification']):.0f} % | "
                     f"{100 * max(cell['verification']):.0f} % |")
    return lines + [""]


def markdown(args, argv, prunesfm, rows):
    lines = bs.header_lines("Disambiguation over the scene families", ["python3", "bench/family_bench.py", *argv],
                            prunesfm, args.colmap)
    lines += ["AUC@10 (pairwise relative pose, `prunesfm evaluate`) per family, input path and engine: the median, "
              "the 10th percentile and the share of scenes at or above 90 and 95. Development seeds "
              f"0..{args.per_family - 1}, held-out seeds 100000..{100000 + args.per_family - 1} "
              "(`bench/family_bench.py` says how the split is fixed).", ""]
    ablated = [row for row in rows if "ablation" in row]
    rows = [row for row in rows if "ablation" not in row]
    table = summarise(rows)
    for split in ("heldout", "dev"):
        part = [t for t in table if t["split"] == split]
        if not part:
            continue
        lines += [f"### {'Held-out' if split == 'heldout' else 'Development'} split", "",
                  "| family | input | engine | scenes | median | 10th pct | >= 90 | >= 95 |",
                  "|---|---|---|---|---|---|---|---|"]
        for t in part:
            lines.append(f"| {t['family']} | {t['input']} | {t['engine']} | {t['n']} | {t['median']:.1f} | "
                         f"{t['p10']:.1f} | {100 * t['share_90']:.0f} % | {100 * t['share_95']:.0f} % |")
        lines.append("")
    kinds = failure_kinds(rows)
    if kinds:
        lines += ["### Edge failures and match failures (the oracles, own input)", "",
                  "Per scene, the kind of failure the oracles reveal (EVALUATION.md): *edges* when GLOBAL reaches "
                  "AUC@10 >= 95 on the pairs whose twin matches do not outnumber their true ones, *matches* when it "
                  "needs the twin matches inside those pairs deleted too, *neither* when both oracles stay below 95.",
                  "", "| split | family | scenes | edges | matches | neither | edge oracle median | match oracle median |",
                  "|---|---|---|---|---|---|---|---|"]
        for (split, family), k in sorted(kinds.items()):
            lines.append(f"| {split} | {family} | {k['n']} | {k['edges']} | {k['matches']} | {k['neither']} | "
                         f"{statistics.median(k['edge_auc']):.1f} | {statistics.median(k['match_auc']):.1f} |")
        lines.append("")
    lines += ["### What the pruning does to the edges", "",
              "Verified edges whose twin matches outnumber their true ones (twin edges) and the others (true "
              "edges), summed over the scenes: the share of each that the pruning removed.", "",
              "| split | family | input | engine | twin edges | removed | true edges | removed |",
              "|---|---|---|---|---|---|---|---|"]
    sums = {}
    for row in rows:
        if row.get("edges") and row["engine"].startswith("GLOBAL_PRUNED"):
            key = (row["split"], row["family"], row["input"], row["engine"])
            total = sums.setdefault(key, dict.fromkeys(row["edges"], 0))
            for name, count in row["edges"].items():
                total[name] += count
    for (split, family, input_path, engine), c in sorted(sums.items()):
        twins, trues = c["twin_kept"] + c["twin_removed"], c["true_kept"] + c["true_removed"]
        lines.append(f"| {split} | {family} | {input_path} | {engine} | {twins} | "
                     f"{100 * c['twin_removed'] / max(1, twins):.0f} % | {trues} | "
                     f"{100 * c['true_removed'] / max(1, trues):.0f} % |")
    lines.append("")
    drops = control_drops(rows)
    if drops:
        worst = drops[0]
        lines += [f"Twin-free controls: GLOBAL_PRUNED minus GLOBAL, worst {worst[0]:+.1f} ({worst[1]}, {worst[2]} "
                  f"input), {sum(d < -0.5 for d, _, _ in drops)} of {len(drops)} below -0.5.", ""]
    lines += cost_lines(args, rows)
    if args.ablations:
        lines += ablation_lines(args, rows + ablated)
    return lines


def main(argv):
    args = parse_args(argv)
    prunesfm = bs.find_prunesfm(args.prunesfm)
    Path(args.work).mkdir(parents=True, exist_ok=True)
    scenes = scene_list(args)
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(run_scene, args, prunesfm, scene): scene for scene in scenes}
        for future in concurrent.futures.as_completed(futures):
            try:
                rows += future.result()
            except RuntimeError as error:
                print(f"error: {error}", file=sys.stderr, flush=True)
    rows.sort(key=lambda r: (r["split"], r["family"], r["seed"], r["input"], r["engine"]))
    lines = markdown(args, argv, prunesfm, rows)
    print("\n".join(lines))
    if args.output:
        Path(args.output).write_text("\n".join(lines) + "\n")
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
