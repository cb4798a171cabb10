#!/usr/bin/env python3
"""How far a warm-up farm chunk starts from the exact parameterization, against K.

Renders the shot once on this machine with path dumps (the exact reference), then for each
K cuts it with `linework farm --warmup K`, runs the plan's tasks here one after the other
(they are the same command lines a scheduler runs) and compares each chunk's dumps with the
reference (`linework coherence-report --against`). Prints, per K, the phase error of the
chunks' first frames (p90 and max over chunks, periods) and of every chunk frame.

  tools/bench/farm_warmup.py build/linework MODEL --size 640x480 --frames 0:119 --chunk 24 \\
      --orbit 360 --slam scenes/slams/dots.exr --ks 0,2,4,8,16
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile


def run(argv):
    r = subprocess.run(argv, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"failed ({r.returncode}): {' '.join(argv)}\n{r.stdout[-2000:]}\n{r.stderr[-2000:]}")
    return r.stdout


def phase_errors(linework, dumps, reference):
    out = subprocess.run([linework, "coherence-report", dumps, "--against", reference],
                         capture_output=True, text=True, check=True).stdout
    errors = {}
    for m in re.finditer(r"frame (\d+): median ([\d.]+), p90 ([\d.]+), max ([\d.]+)", out):
        errors[int(m.group(1))] = (float(m.group(2)), float(m.group(3)), float(m.group(4)))
    return errors


def sliding(linework, pairs):
    """Median |dt| between consecutive frames over (folder_a, frame_a, folder_b, frame_b) pairs."""
    values = []
    for a_dir, a, b_dir, b in pairs:
        with tempfile.TemporaryDirectory() as tmp:
            for d, f in ((a_dir, a), (b_dir, b)):  # each under its own name: coherence-report checks them
                os.symlink(os.path.join(d, f"frame_{f:04d}.json"), os.path.join(tmp, f"frame_{f:04d}.json"))
            out = subprocess.run([linework, "coherence-report", tmp], capture_output=True, text=True,
                                 check=True).stdout
            values.append(float(re.search(r"sliding: median \|dt\| ([\d.]+)", out).group(1)))
    return max(values)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("linework")
    ap.add_argument("scene")
    ap.add_argument("--frames", default="0:119")
    ap.add_argument("--chunk", type=int, default=24)
    ap.add_argument("--ks", default="0,1,2,4,8,16")
    ap.add_argument("--keep", help="work folder to keep (default: a temporary one)")
    args, render_args = ap.parse_known_args()
    work = args.keep or tempfile.mkdtemp(prefix="lw-warmup-")
    shot = [args.scene, *render_args]
    reference = os.path.join(work, "exact_dumps")
    run([args.linework, "render", *shot, "--frames", args.frames, "-o", os.path.join(work, "exact"),
         "--dump-paths", reference])
    print("phase error against one render (periods): p90 and max over the chunks' first frames, p90 over all")
    print("frames; sliding (median |dt|, worst chunk) across each chunk boundary (C-1 -> C) and from a")
    print("chunk's first frame to its second (C -> C+1), with one render's at the same frames beside it")
    print(f"{'K':>3} {'first p90':>9} {'first max':>9} {'all p90':>8} {'boundary':>9} {'(one)':>7} "
          f"{'C->C+1':>7} {'(one)':>7}")
    for k in [int(x) for x in args.ks.split(",")]:
        farm = os.path.join(work, f"warmup_{k}")
        dumps = os.path.join(work, f"warmup_{k}_dumps")
        run([args.linework, "farm", *shot, "--frames", args.frames, "--chunk", str(args.chunk), "--warmup", str(k),
             "-o", farm, "--dump-paths", dumps])
        plan = json.load(open(os.path.join(farm, "plan.json")))
        for phase in plan["phases"]:
            for task in phase["tasks"]:
                run(task["command"])
        errors = phase_errors(args.linework, dumps, reference)
        firsts = [t["frames"][0] for t in plan["phases"][-1]["tasks"][1:]]  # chunk 0 starts as one render does
        first_p90 = max(errors[f][1] for f in firsts)
        first_max = max(errors[f][2] for f in firsts)
        all_p90 = max(e[1] for e in errors.values())
        boundary = sliding(args.linework, [(dumps, f - 1, dumps, f) for f in firsts])
        boundary_one = sliding(args.linework, [(reference, f - 1, reference, f) for f in firsts])
        settle = sliding(args.linework, [(dumps, f, dumps, f + 1) for f in firsts])
        settle_one = sliding(args.linework, [(reference, f, reference, f + 1) for f in firsts])
        print(f"{k:>3} {first_p90:>9.4f} {first_max:>9.4f} {all_p90:>8.4f} {boundary:>9.4f} {boundary_one:>7.4f} "
              f"{settle:>7.4f} {settle_one:>7.4f}", flush=True)


if __name__ == "__main__":
    main()
