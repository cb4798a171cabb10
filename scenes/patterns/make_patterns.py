#!/usr/bin/env python3
"""Draws the reference patterns of scenes/patterns/ (run once by hand; the SVGs are committed).

    python3 scenes/patterns/make_patterns.py

Each pattern is drawn the way a person would draw it with a tablet: strokes in drawing order,
jittered by a seeded generator, in the SVG subset that `linework pattern` and `linework hatch`
read (path M/L/C/Z, polyline, stroke, stroke-width, data-widths). See README.md.
"""
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))


def fmt(v):
    return f"{v:.2f}".rstrip("0").rstrip(".")


class Drawing:
    def __init__(self, width, height):
        self.width, self.height, self.items = width, height, []

    def polyline(self, pts, color="#000000", width=1.0, widths=None):
        attrs = f' stroke="{color}" stroke-width="{fmt(width)}"'
        if widths:
            attrs += ' data-widths="' + " ".join(fmt(w) for w in widths) + '"'
        self.items.append('<polyline points="' + " ".join(f"{fmt(x)},{fmt(y)}" for x, y in pts) + f'"{attrs}/>')

    def curve(self, p0, p1, p2, p3, color="#000000", width=1.0):
        d = f"M{fmt(p0[0])} {fmt(p0[1])} C{fmt(p1[0])} {fmt(p1[1])} {fmt(p2[0])} {fmt(p2[1])} {fmt(p3[0])} {fmt(p3[1])}"
        self.items.append(f'<path d="{d}" stroke="{color}" stroke-width="{fmt(width)}"/>')

    def loop(self, pts, color="#000000", width=1.0):
        d = "M" + " L".join(f"{fmt(x)} {fmt(y)}" for x, y in pts) + " Z"
        self.items.append(f'<path d="{d}" stroke="{color}" stroke-width="{fmt(width)}"/>')

    def save(self, name, title):
        with open(os.path.join(HERE, name), "w") as f:
            f.write(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {self.width} {self.height}" '
                    f'width="{self.width}" height="{self.height}">\n<title>{title}</title>\n'
                    '<g fill="none" stroke-linecap="round" stroke-linejoin="round">\n')
            f.write("\n".join(self.items) + "\n</g>\n</svg>\n")


def segment(c, angle, length):
    dx, dy = math.cos(angle) * length / 2, math.sin(angle) * length / 2
    return [(c[0] - dx, c[1] - dy), (c[0] + dx, c[1] + dy)]


def sketchy_hatching(rng):
    d = Drawing(420, 80)
    for i in range(24):
        x = 18 + 16 * i + rng.uniform(-1.5, 1.5)
        for _ in range(rng.choice([2, 2, 3])):  # each hatch drawn with 2–3 overlapping gestures
            top = (x + rng.uniform(-1.5, 1.5), 20 + rng.uniform(-3, 3))
            bottom = (x + 4 + rng.uniform(-1.5, 1.5), 60 + rng.uniform(-3, 3))
            bend = rng.uniform(-2.5, 2.5)
            d.curve(top, (top[0] + bend, top[1] + 13), (bottom[0] + bend, bottom[1] - 13), bottom, width=1.2)
    d.save("hatch_sketchy.svg", "1D hatching drawn with sketchy strokes")


def gradients(rng):
    n = 30
    d = Drawing(440, 80)  # orientation from 20° to 160°
    for i in range(n):
        a = math.radians(20 + 140 * i / (n - 1)) + rng.uniform(-0.03, 0.03)
        d.polyline(segment((20 + 14 * i, 40 + rng.uniform(-1, 1)), a, 34), width=1.5)
    d.save("orientation_gradient.svg", "smooth change of orientation along the path")

    d = Drawing(440, 80)  # length from 10 to 52
    for i in range(n):
        length = 10 + 42 * i / (n - 1) + rng.uniform(-1, 1)
        d.polyline(segment((20 + 14 * i, 40), math.radians(90 + rng.uniform(-3, 3)), length), width=1.5)
    d.save("length_gradient.svg", "smooth change of length along the path")

    d = Drawing(440, 80)  # width from 0.8 to 7
    for i in range(n):
        w = 0.8 + 6.2 * i / (n - 1)
        d.polyline(segment((20 + 14 * i, 40), math.radians(90 + rng.uniform(-3, 3)), 36), width=w)
    d.save("thickness_gradient.svg", "smooth change of thickness along the path")


def alternating_colours(rng):
    d = Drawing(420, 80)
    for i in range(26):
        x = 16 + 15 * i + rng.uniform(-1, 1)
        a = math.radians(75 + rng.uniform(-5, 5))
        pts = segment((x, 40 + rng.uniform(-2, 2)), a, 38 + rng.uniform(-3, 3))
        mid = ((pts[0][0] + pts[1][0]) / 2 + rng.uniform(-1.5, 1.5), (pts[0][1] + pts[1][1]) / 2)
        colour = "#c8281e" if i % 2 == 0 else "#1e46b4"
        d.polyline([pts[0], mid, pts[1]], colour, 4.0, widths=[2.0, 4.5, 2.0])  # a brush stroke, tapered
    d.save("alternating_colours.svg", "brush strokes of alternating colours")


def jittered_grid(rng, w, h, spacing, jitter):
    pts, row = [], 0
    y = spacing / 2
    while y < h:
        x = spacing / 2 + (spacing / 2 if row % 2 else 0)
        while x < w:
            pts.append((x + rng.uniform(-jitter, jitter), y + rng.uniform(-jitter, jitter), row))
            x += spacing
        y += spacing * 0.866
        row += 1
    return pts


def stipples(rng):
    d = Drawing(240, 240)
    for x, y, _ in jittered_grid(rng, 240, 240, 17, 4):
        d.polyline([(x, y), (x + rng.uniform(0.2, 0.8), y + rng.uniform(-0.4, 0.4))], width=rng.uniform(2.5, 4.0))
    d.save("stipples.svg", "2D stipples")


def multi_bars(rng):
    d = Drawing(260, 260)
    for x, y, _ in jittered_grid(rng, 260, 260, 26, 4):
        a = math.radians(rng.choice([0, 45, 90, 135]) + rng.uniform(-6, 6))
        d.polyline(segment((x, y), a, 16 + rng.uniform(-2, 2)), width=2.0)
    d.save("multi_bars.svg", "bars in several directions")


def flowers(rng):
    d = Drawing(300, 300)
    colours = ["#d0302a", "#e08a1c", "#7a3aa8"]
    for x, y, _ in jittered_grid(rng, 300, 300, 46, 6):
        colour = rng.choice(colours)
        turn = rng.uniform(0, 2 * math.pi)
        for p in range(5):  # five petals, each a small closed loop
            a = turn + 2 * math.pi * p / 5
            cx, cy = x + 6 * math.cos(a), y + 6 * math.sin(a)
            loop = []
            for k in range(8):
                t = 2 * math.pi * k / 8
                u, v = 4.5 * math.cos(t), 2.2 * math.sin(t)
                loop.append((cx + u * math.cos(a) - v * math.sin(a), cy + u * math.sin(a) + v * math.cos(a)))
            d.loop(loop, colour, 1.2)
        d.polyline([(x - 0.5, y), (x + 0.5, y)], "#3a2a10", 3.0)  # the heart
    d.save("flowers.svg", "small flowers drawn with several strokes")


def two_kinds(rng):
    d = Drawing(280, 280)
    for x, y, row in jittered_grid(rng, 280, 280, 30, 3):
        kind = (int(x // 30) + row) % 2
        if kind == 0:  # three short parallel strokes
            for k in (-4, 0, 4):
                d.polyline(segment((x + k, y), math.radians(90 + rng.uniform(-4, 4)), 12), width=1.3)
        else:  # one long diagonal
            d.polyline(segment((x, y), math.radians(35 + rng.uniform(-4, 4)), 22), "#404040", 2.2)
    d.save("two_kinds.svg", "two alternating kinds of elements")


def crosses(rng):
    d = Drawing(260, 260)
    for x, y, _ in jittered_grid(rng, 260, 260, 40, 4):
        a = rng.uniform(-0.2, 0.2)
        d.polyline(segment((x, y), a, 16), width=1.5)
        d.polyline(segment((x, y), a + math.pi / 2, 16), width=1.5)
    d.save("crosses.svg", "crosses, each drawn with two strokes")


def hatch_training(rng):
    d = Drawing(360, 80)
    x = 14.0
    for i in range(41):  # hatching as a hand draws it: spacing, length and slant drift slowly
        length = 34 + 8 * math.sin(i / 6.0) + rng.uniform(-3, 3)
        slant = math.radians(70 + 10 * math.sin(i / 9.0) + rng.uniform(-4, 4))
        c = (x, 40 + rng.uniform(-3, 3))
        p0, p1 = segment(c, slant, length)
        bend = rng.uniform(-2, 2)
        mid0 = (p0[0] + (p1[0] - p0[0]) / 3 + bend, p0[1] + (p1[1] - p0[1]) / 3)
        mid1 = (p0[0] + 2 * (p1[0] - p0[0]) / 3 + bend, p0[1] + 2 * (p1[1] - p0[1]) / 3)
        d.curve(p0, mid0, mid1, p1, width=1.1 + rng.uniform(-0.2, 0.2))
        x += 7.5 + 2 * math.sin(i / 4.0) + rng.uniform(-1, 1)
    d.save("hatch_training.svg", "a hatching training sequence (41 strokes, drawn left to right)")

    d = Drawing(400, 300)  # brush paths along which `linework hatch --along` lays sequences
    d.curve((30, 60), (130, 10), (250, 110), (370, 50))
    d.curve((30, 150), (120, 200), (260, 100), (370, 160))
    d.curve((60, 260), (150, 220), (240, 290), (340, 240))
    d.save("hatch_paths.svg", "brush paths for hatching along (Jodoin et al. 2002, Fig. 8)")


if __name__ == "__main__":
    rng = random.Random(2006)
    sketchy_hatching(rng)
    gradients(rng)
    alternating_colours(rng)
    stipples(rng)
    multi_bars(rng)
    flowers(rng)
    two_kinds(rng)
    crosses(rng)
    hatch_training(rng)
