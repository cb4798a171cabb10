#!/usr/bin/env bash
# tools/make_slam_exemplars.sh — the SLAM exemplars of scenes/exemplars/slam-*.png.
#
# Four are cut from a-painter's brushes (../shared/exemplars/a-painter, MIT: alpha is the
# ink, kept as alpha), three are drawn here from seeded random positions (black ink on
# white). Needs ImageMagick's `convert` and python3. Then:
#   for e in scenes/exemplars/slam-*.png; do n=$(basename $e .png); n=${n#slam-}
#     ./build/linework slam $e -o scenes/slams/$n.exr --preview out/slam-$n.png; done
set -euo pipefail
cd "$(dirname "$0")/.."
src=${A_PAINTER:-../shared/exemplars/a-painter}
out=scenes/exemplars

# a-painter brushes, scaled to a 32-texel-wide stroke.
convert "$src/lines2.png" -resize 50% -gravity center -crop 512x32+0+0 +repage "$out/slam-pencil.png"
convert "$src/lines3.png" -resize 50% -gravity center -crop 512x32+0+0 +repage "$out/slam-brush.png"
convert "$src/lines4.png" -resize 512x32\! "$out/slam-lattice.png"
convert "$src/line_grunge2.png" -resize 50% -gravity center -crop 512x32+0+0 +repage "$out/slam-spatter.png"

# Drawn: irregular dots, dashes and a looping scribble, 512 × 32; identical dots (32 rows), a
# thin line of wedges (8 rows) and a thin wobbly line (16 rows), 512 long.
draw() {  # $1: name, [$ROWS], then python that prints ImageMagick draw primitives
  local name=$1
  shift
  convert -size 512x${ROWS:-32} xc:white -fill black -stroke none -draw "$(python3 -c "$*")" -alpha off -depth 8 "$out/slam-$name.png"
}
draw dots '
import random; random.seed(7); x = 6.0
while x < 506:
    r = random.uniform(3.0, 6.5); y = 16 + random.uniform(-2.5, 2.5)
    print(f"circle {x + r:.1f},{y:.1f} {x + 2 * r:.1f},{y:.1f}"); x += 2 * r + random.uniform(6, 16)'
draw dashes '
import random; random.seed(11); x = 4.0
while x < 480:
    l = random.uniform(18, 44); h = random.uniform(2.5, 4.5); y = 16 + random.uniform(-1.5, 1.5)
    print(f"roundrectangle {x:.1f},{y - h:.1f} {x + l:.1f},{y + h:.1f} {h:.1f},{h:.1f}"); x += l + random.uniform(8, 16)'
convert -size 512x32 xc:white -fill none -stroke black -strokewidth 2 -draw "$(python3 -c '
import math, random; random.seed(5)
pts, t, a = [], 0.0, 0.0
while t < 520:
    r = 8.5 + 3 * math.sin(t / 41.0) + random.uniform(-1, 1)
    pts.append(f"{t - 6 + 1.4 * r * math.cos(a):.1f},{16 + r * math.sin(a):.1f}")
    a += random.uniform(0.14, 0.22); t += 0.75
print("path \"M " + " L ".join(pts) + "\"")')" -alpha off -depth 8 "$out/slam-scribble.png"
# Identical dots (radius 4) at seeded spacings: element sizes must come out equal.
draw beads '
import random; random.seed(3); x = 8.0
while x < 500:
    print(f"circle {x + 4:.1f},16 {x + 8:.1f},16"); x += 8 + random.uniform(7, 13)'
# Wedges: each tapers from 5 px to a point along 40-90 px, end to end, in 8 rows.
ROWS=8 draw wedges '
import random; random.seed(13); x = 2.0
while x < 470:
    l = random.uniform(40, 90); h = random.uniform(2.0, 2.5); y = 4 + random.uniform(-0.4, 0.4)
    print(f"polygon {x:.1f},{y - h:.1f} {x + l:.1f},{y:.1f} {x:.1f},{y + h:.1f}"); x += l + random.uniform(3, 9)'
# A thin wobbly line of slowly varying amplitude, 16 rows.
convert -size 512x16 xc:white -fill none -stroke black -strokewidth 1.5 -draw "$(python3 -c '
import math
pts = [f"{t:.1f},{8 + (2.2 + 1.2 * math.sin(t / 57.0)) * math.sin(t / 9.0 + 0.6 * math.sin(t / 23.0)):.2f}"
       for t in [0.5 * i for i in range(-4, 1030)]]
print("path \"M " + " L ".join(pts) + "\"")')" -alpha off -depth 8 "$out/slam-wobble.png"
