#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Estimates a matrix's CPU cost per scene (to size a Slurm array) from a timed sample of its cells.

Method: every scene of MATRIX is rendered at its resolved settings (integrator, depth, patterns, every spp) but at
1/DIVISOR of its width and height, with 4 of its seeds, --threads 1, through stipple-validate (which times each
render's loop). A render's cost is proportional to its pixel count (each pixel's samples are independent work;
the small image samples the whole view), so each cell's mean render seconds over the 4 seeds, times the pixel
ratio and the matrix's seed count, is its CPU cost at full size. The reference is sampled at 4 x the largest spp
and scaled by the matrix's reference spp (the independent pattern costs the same per sample at any spp).
Wall seconds of a single-threaded render are CPU seconds only on an idle machine; on a shared one they are
converted with the run's own ratio of process CPU time (getrusage) to wall time.

Prints per scene: cells and reference CPU-hours, the most expensive (scene, spp, seed) group (the unit of
sharding: all patterns of one group run in one task), then the wall time of an array of TASKS tasks of THREADS
threads each, by replaying the shard assignment (group g goes to task g mod n + 1).

usage: estimate-cost.py MATRIX --bin STIPPLE_VALIDATE [--divisor 32] [--work DIR] [--tasks 32] [--threads 2]
Exit status: 0 the estimate, 2 a bad argument or matrix, 3 a sample run of stipple-validate failed.
"""
import argparse, json, os, pathlib, re, resource, subprocess, sys, time

import yaml


def fail(status, message):
    print(f"estimate-cost: {message}", file=sys.stderr)
    sys.exit(status)


def count(lo, hi):
    def parse(text):
        try:
            v = int(text, 10)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected an integer in [{lo}, {hi}], got '{text}'")
        if not lo <= v <= hi:
            raise argparse.ArgumentTypeError(f"expected an integer in [{lo}, {hi}], got '{text}'")
        return v
    return parse


ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("matrix")
ap.add_argument("--bin", required=True)
ap.add_argument("--divisor", type=count(1, 4096), default=32)
ap.add_argument("--work", default="cost-sample")
ap.add_argument("--tasks", type=count(1, 10000), default=32)
ap.add_argument("--threads", type=count(1, 1024), default=2)
a = ap.parse_args()  # exits 2 with the option named

matrix_path = pathlib.Path(a.matrix).resolve()
try:
    m = yaml.safe_load(matrix_path.read_text())
except (OSError, UnicodeDecodeError, yaml.YAMLError) as e:
    fail(2, f"{a.matrix}: cannot read the matrix: {e}")
if not isinstance(m, dict) or not all(k in m for k in ("scenes", "patterns", "spp", "seeds")):
    fail(2, f"{a.matrix}: not a matrix (a map with scenes, patterns, spp and seeds)")
# The sample renders through stipple-render at a reduced size; an external renderer's cost is its own.
external = [str(e.get("name", e.get("file"))) if isinstance(e, dict) else str(e)
            for e in m["scenes"] if m.get("renderer") or (isinstance(e, dict) and e.get("renderer"))]
if external:
    fail(2, f"{a.matrix}: scenes {', '.join(external)} use an external renderer; estimate-cost samples "
            f"stipple-render only: time a few of the host renderer's cells instead")
if not (os.path.isfile(a.bin) and os.access(a.bin, os.X_OK)):
    fail(2, f"--bin {a.bin}: not an executable file")
work = pathlib.Path(a.work).resolve()
work.mkdir(parents=True, exist_ok=True)
seeds = m["seeds"] if isinstance(m["seeds"], list) else list(range(1, int(m["seeds"]) + 1))
spps = m["spp"] if isinstance(m["spp"], list) else [m["spp"]]
spps = sorted(spps)
ref = m.get("reference", {}) or {}
ref_spp_default = int(ref.get("spp", 1024))
sample_ref_spp = 4 * spps[-1]

scenes = []
for index, entry in enumerate(m["scenes"]):
    e = {"file": entry} if isinstance(entry, str) else dict(entry)
    path = (matrix_path.parent / e["file"]).resolve()
    name = str(e.get("name", path.stem))
    try:
        render = (yaml.safe_load(path.read_text()) or {}).get("render") or {}
    except (OSError, UnicodeDecodeError, yaml.YAMLError, AttributeError) as err:
        fail(2, f"{a.matrix}: scene {name}: cannot read {path}: {err}")
    w, h = int(e.get("width", render.get("width"))), int(e.get("height", render.get("height")))
    sw, sh = max(1, round(w / a.divisor)), max(1, round(h / a.divisor))
    sample = {"file": str(path), "name": name, "width": sw, "height": sh}
    for k in ("integrator", "max_depth"):
        if k in e: sample[k] = e[k]
    # The files of the sample go inside --work under a name of plain characters, whatever the scene is called
    # ("../x" must not write outside it).
    stem = f"{index:03d}-" + (re.sub(r"[^A-Za-z0-9_-]", "_", name)[:64] or "scene")
    scenes.append({"name": name, "stem": stem, "w": w, "h": h, "sw": sw, "sh": sh, "sample": sample,
                   "ref_spp": int(e.get("reference_spp", ref_spp_default))})

print(f"sample of {matrix_path.name}: every cell at 1/{a.divisor} of each side, seeds {seeds[:4]}, --threads 1; "
      f"load average {os.getloadavg()[0]:.1f}", flush=True)
results = []
for s in scenes:
    sample = {"name": f"cost-{s['name']}", "scenes": [s["sample"]], "patterns": m["patterns"], "spp": spps,
              "seeds": seeds[:4], "reference": {"pattern": ref.get("pattern", "independent"), "spp": sample_ref_spp,
                                                "seed": int(ref.get("seed", 1000003))}}
    mp = work / f"{s['stem']}.yaml"
    mp.write_text(yaml.safe_dump(sample, sort_keys=False))
    out = work / s["stem"]
    # An earlier sample's results must never stand in for this one's.
    stale = out / "results.json"
    if stale.is_file() and not stale.is_symlink():
        stale.unlink()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    run = subprocess.run([a.bin, str(mp), "-o", str(out), "--cache", str(work / "cache"), "--threads", "1"],
                         check=False, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, errors="replace")
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if run.returncode != 0:  # the sample has no checks: anything but 0 is a failed run
        tail = "\n".join(run.stderr.strip().splitlines()[-5:])
        fail(3, f"the sample of scene {s['name']} failed: {a.bin} exited {run.returncode}\n{tail}")
    try:
        r = json.loads((out / "results.json").read_text())
    except (OSError, ValueError) as err:
        fail(3, f"the sample of scene {s['name']} left no readable results.json: {err}")
    info = r["scenes"][0]
    cpu_per_wall = min(1.0, cpu / wall) if wall > 0 else 1.0
    scale = (s["w"] * s["h"]) / (s["sw"] * s["sh"])
    cell = {}  # (pattern, spp) -> CPU seconds of one full-size render
    for row in r["rows"]:
        cell.setdefault((row["pattern"], row["spp"]), []).append(row["render_seconds"])
    cell = {k: sum(v) / len(v) * cpu_per_wall * scale for k, v in cell.items()}
    group = {spp: sum(cell[(p, spp)] for p in m["patterns"]) for spp in spps}  # one (spp, seed) group
    cells_cpu = sum(group.values()) * len(seeds)
    ref_cpu = info["reference_seconds"] * cpu_per_wall * scale * s["ref_spp"] / sample_ref_spp
    s.update(cell=cell, group=group, cells_cpu=cells_cpu, ref_cpu=ref_cpu, sample_cpu=cpu, sample_wall=wall,
             ratio=cpu_per_wall, load=info["load_seconds"] + info["build_seconds"])
    print(f"  {s['name']}: sample {s['sw']}x{s['sh']} of {s['w']}x{s['h']} (x{scale:.0f} pixels): {cpu:.1f} s CPU "
          f"in {wall:.1f} s wall (CPU/wall {cpu_per_wall:.2f})", flush=True)

H = 3600.0
print(f"\nCPU-hours at full size ({len(seeds)} seeds, spp {spps}):")
print(f"{'scene':16} {'cells':>8} {'reference':>10} {'total':>8}   largest group (all patterns, one seed)")
for s in scenes:
    top = spps[-1]
    worst = max(s["cell"][(p, top)] for p in m["patterns"])
    worst_p = max(m["patterns"], key=lambda p: s["cell"][(p, top)])
    print(f"{s['name']:16} {s['cells_cpu'] / H:8.2f} {s['ref_cpu'] / H:10.2f} {(s['cells_cpu'] + s['ref_cpu']) / H:8.2f}"
          f"   {s['group'][top] / H:.2f} h at {top} spp ({worst_p} {worst / H:.2f} h of it)")
total = sum(s["cells_cpu"] + s["ref_cpu"] for s in scenes)
print(f"{'all':16} {sum(s['cells_cpu'] for s in scenes) / H:8.2f} {sum(s['ref_cpu'] for s in scenes) / H:10.2f} "
      f"{total / H:8.2f}")
print("  per spp, CPU-hours of all patterns x seeds: " + ", ".join(
    f"{spp}: {sum(s['group'][spp] for s in scenes) * len(seeds) / H:.2f}" for spp in spps))

# The array: groups in matrix order (scene, spp, seed); group g runs in task g mod n + 1 on THREADS threads
# (renders scale with threads: tiles are independent). References first, one scene per task at once.
n, t = a.tasks, a.threads
load = [0.0] * n
g = 0
for s in scenes:
    for spp in spps:
        for _ in seeds:
            load[g % n] += s["group"][spp] / t
            g += 1
ref_wall = max(s["ref_cpu"] for s in scenes) / t
print(f"\narray of {n} tasks x {t} threads ({g} groups, {g // n}-{-(-g // n)} per task): references first "
      f"(--references-only, one scene per task) {ref_wall / H:.2f} h wall, then the slowest task {max(load) / H:.2f} h "
      f"(mean {sum(load) / n / H:.2f} h): {(ref_wall + max(load)) / H:.2f} h wall in all; "
      f"{total / H / (n * t):.2f} h if the work were spread perfectly")
