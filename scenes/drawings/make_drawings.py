#!/usr/bin/env python3
"""Writes the line drawings of scenes/drawings (run once; the SVGs are committed).

spiral.svg: a logarithmic spiral with leaves along it and circles at several sizes around
its centre (320, 240). A log spiral looks the same at every zoom about its centre, so the
16x zoom of scenes/zoom_slam.json always has strokes on screen (the SLAM paper's Fig. 5)."""
import math

cx, cy = 320.0, 240.0
paths = []

def polyline(points, closed=False, width=2.5, color="#1a1a1a"):
    d = "M" + " L".join(f"{x:.2f} {y:.2f}" for x, y in points) + (" Z" if closed else "")
    paths.append(f'<path d="{d}" stroke="{color}" stroke-width="{width}"/>')

# Two arms of r = a·e^{bθ}, from 3 px to 300 px.
b = 0.18
for arm in range(2):
    pts = []
    theta = 0.0
    while True:
        r = 3.0 * math.exp(b * theta)
        if r > 300: break
        a = theta + arm * math.pi
        pts.append((cx + r * math.cos(a), cy + r * math.sin(a)))
        theta += max(0.02, 1.5 / r)  # about 1.5 px steps
    polyline(pts)

# Leaves (closed almond shapes) along the first arm, sized with their radius.
theta = 2.0
while True:
    r = 3.0 * math.exp(b * theta)
    if r > 260: break
    px, py = cx + r * math.cos(theta), cy + r * math.sin(theta)
    size = 0.35 * r
    ang = theta + math.pi / 2
    leaf = []
    for k in range(25):
        t = k / 24 * 2 * math.pi
        u, v = size * 0.5 * (1 - math.cos(t)), 0.22 * size * math.sin(t)
        leaf.append((px + u * math.cos(ang) - v * math.sin(ang), py + u * math.sin(ang) + v * math.cos(ang)))
    polyline(leaf, closed=True, width=2.0)
    theta += 1.1

# Circles at doubling radii about the centre, a little off-centre so they cross the spiral.
for i, radius in enumerate([6, 12, 24, 48, 96, 192]):
    ox, oy = cx + 0.3 * radius, cy - 0.2 * radius
    n = max(24, int(2 * math.pi * radius / 2))
    polyline([(ox + radius * math.cos(2 * math.pi * k / n), oy + radius * math.sin(2 * math.pi * k / n)) for k in range(n)],
             closed=True, width=1.8, color="#3a3a3a")

with open("spiral.svg", "w") as f:
    f.write('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 640 480" width="640" height="480">\n')
    f.write('<title>logarithmic spiral with leaves and circles (zoom test drawing)</title>\n')
    f.write('<g fill="none" stroke-linecap="round" stroke-linejoin="round">\n')
    f.write("\n".join(paths) + "\n</g>\n</svg>\n")
