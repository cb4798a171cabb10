#!/usr/bin/python3
"""The Python module's overhead on line extraction, side by side with `linework-bench lines`.

  PYTHONPATH=build/python /usr/bin/python3 tools/bench/python_lines.py MODEL [--size WxH]
      [--frames N] [--pairs K] [--device cpu|gpu] [--bench build/linework-bench]

Pair by pair (these machines are noisy), it runs `linework-bench lines MODEL --shaded` for N
frames and takes its "line frame, drawn and released (wall)" median (the frame with its vertex
buffers and paths freed, as a loop pays for it), then times N calls of Session.lines() on the
same model, size and framing camera (the toon-shaded frame a bare model gets, as --shaded
draws it) in this process. It prints each pair, the medians over pairs and their ratio, and
splits the Python side into the frame itself (the session's own timing) and the conversion of
the paths to NumPy polylines. Figures go to docs/BENCHMARKS.md.
"""
import argparse
import re
import statistics
import subprocess
import time

import linework


def bench_median(bench, model, size, frames, device):
    out = subprocess.run([bench, "lines", model, "--shaded", "--size", size, "--frames", str(frames),
                          "--device", device], capture_output=True, text=True, check=True).stdout
    # The frame as a loop pays for it, drawn and released, as Session.lines() is timed here.
    match = re.search(r"line frame, drawn and released \(wall\)\s+median\s+([\d.]+) ms", out)
    if not match:
        raise SystemExit("linework-bench printed no line frame median:\n" + out)
    segments = re.search(r"(\d+) segments, (\d+) paths", out)
    return float(match.group(1)), segments.group(0) if segments else ""


def python_medians(session, frames):
    wall, frame_ms, read_ms = [], [], []
    for _ in range(frames):
        start = time.perf_counter()
        result = session.frame(image=False, lines=True)
        wall.append((time.perf_counter() - start) * 1000.0)
        frame_ms.append(result.timings["total_ms"])
        # What a script then pays to read every polyline's points and surface points.
        start = time.perf_counter()
        for paths in result.lines.values():
            for p in paths:
                p.points, p.position
        read_ms.append((time.perf_counter() - start) * 1000.0)
    paths = sum(len(v) for v in result.lines.values())
    return statistics.median(wall), statistics.median(frame_ms), statistics.median(read_ms), paths


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("model")
    p.add_argument("--size", default="960x720")
    p.add_argument("--frames", type=int, default=20)
    p.add_argument("--pairs", type=int, default=7)
    p.add_argument("--device", default="cpu")
    p.add_argument("--bench", default="build/linework-bench")
    a = p.parse_args()
    w, h = map(int, a.size.split("x"))
    session = linework.Session(a.model, device=a.device, size=(w, h), validation=False)
    for _ in range(3):  # warm-up, as linework-bench draws two frames first
        session.lines()
    cpp, py, py_frame, py_read = [], [], [], []
    for k in range(a.pairs):
        c, counts = bench_median(a.bench, a.model, a.size, a.frames, a.device)
        wall, frame_ms, read_ms, paths = python_medians(session, a.frames)
        cpp.append(c)
        py.append(wall)
        py_frame.append(frame_ms)
        py_read.append(read_ms)
        print(f"pair {k + 1}: linework-bench {c:7.2f} ms ({counts})   Session.lines() {wall:7.2f} ms "
              f"(frame {frame_ms:.2f} ms, {paths} polylines; reading their points {read_ms:.2f} ms)   "
              f"ratio {wall / c:.3f}")
    mc, mp, mf = statistics.median(cpp), statistics.median(py), statistics.median(py_frame)
    ratios = [p_ / c_ for p_, c_ in zip(py, cpp)]
    print(f"medians over {a.pairs} pairs of {a.frames} frames: linework-bench lines {mc:.2f} ms, "
          f"Session.lines() {mp:.2f} ms (its frame {mf:.2f} ms, conversion to NumPy {mp - mf:.2f} ms); "
          f"ratio of medians {mp / mc:.3f}, median of pair ratios {statistics.median(ratios):.3f}; reading every "
          f"polyline's points and positions afterwards {statistics.median(py_read):.2f} ms")


if __name__ == "__main__":
    main()
