#!/usr/bin/python3
"""Silhouettes and suggestive contours of a mesh seen from a ring of cameras, in one figure.

  PYTHONPATH=build/python /usr/bin/python3 examples/camera_ring.py [MODEL] [-n 8] [-o ring.png]

The mesh is read once as arrays (linework.load_mesh), given to one Session, and the camera is
moved around it; each view's lines come back as NumPy polylines, no files in between. With
Matplotlib (Debian: python3-matplotlib) the figure is a PNG (or anything savefig writes);
without it, `-o ring.svg` writes the same grid as SVG by hand.
"""
import argparse
import math
import pathlib

import numpy as np

import linework

ROOT = pathlib.Path(__file__).resolve().parents[1]
COLORS = {"silhouette": "#111111", "suggestive": "#b5651d"}


def ring_views(session, vertices, count, elevation_deg=20.0):
    """Yields (angle, lines) for `count` cameras on a circle around the mesh's centre."""
    centre = (vertices.min(axis=0) + vertices.max(axis=0)) / 2
    radius = np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)) * 1.4
    for i in range(count):
        a = 2 * math.pi * i / count
        e = math.radians(elevation_deg)
        eye = centre + radius * np.array([math.sin(a) * math.cos(e), math.sin(e), math.cos(a) * math.cos(e)])
        session.set_camera(eye=eye, target=centre)
        lines = session.lines()
        yield math.degrees(a), {t: lines[t] for t in COLORS}


def save_matplotlib(views, size, columns, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = math.ceil(len(views) / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(3 * columns, 3 * rows * size[1] / size[0]), squeeze=False)
    for ax in axes.flat:
        ax.set_axis_off()
    for ax, (angle, lines) in zip(axes.flat, views):
        for kind, paths in lines.items():
            for p in paths:
                pts = np.vstack([p.points, p.points[:1]]) if p.closed else p.points
                ax.plot(pts[:, 0], pts[:, 1], color=COLORS[kind], linewidth=0.8 if kind == "silhouette" else 0.5,
                        alpha=float(p.fade.mean()))
        ax.set_xlim(0, size[0])
        ax.set_ylim(size[1], 0)  # pixels: y down
        ax.set_aspect("equal")
        ax.set_title(f"{angle:.0f}°", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=150)


def save_svg(views, size, columns, path):
    w, h = size
    rows = math.ceil(len(views) / columns)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w * columns}" height="{h * rows}">',
           f'<rect width="{w * columns}" height="{h * rows}" fill="white"/>']
    for k, (angle, lines) in enumerate(views):
        x0, y0 = (k % columns) * w, (k // columns) * h
        out.append(f'<g transform="translate({x0},{y0})"><text x="4" y="14" font-size="12">{angle:.0f}°</text>')
        for kind, paths in lines.items():
            for p in paths:
                pts = np.vstack([p.points, p.points[:1]]) if p.closed else p.points
                coords = " ".join(f"{x:.2f},{y:.2f}" for x, y in pts)
                out.append(f'<polyline points="{coords}" fill="none" stroke="{COLORS[kind]}" '
                           f'stroke-width="{1.2 if kind == "silhouette" else 0.8}"/>')
        out.append("</g>")
    out.append("</svg>")
    pathlib.Path(path).write_text("\n".join(out) + "\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("model", nargs="?", default=str(ROOT / "scenes/models/spot/spot.glb"))
    p.add_argument("-n", "--views", type=int, default=8, help="cameras on the ring (default 8)")
    p.add_argument("--size", default="320x240", help="each view's size WxH (default 320x240)")
    p.add_argument("--device", default="auto", help="auto, cpu (lavapipe) or gpu")
    p.add_argument("-o", "--output", default="ring.png", help="figure: .png/.pdf (Matplotlib) or .svg")
    a = p.parse_args()
    w, h = map(int, a.size.lower().split("x"))
    vertices, faces, normals = linework.load_mesh(a.model)
    session = linework.Session({"size": [w, h]}, vertices=vertices, faces=faces, normals=normals,
                               name=pathlib.Path(a.model).name, device=a.device)
    views = list(ring_views(session, vertices, a.views))
    columns = min(4, a.views)
    if a.output.endswith(".svg"):
        save_svg(views, (w, h), columns, a.output)
    else:
        save_matplotlib(views, (w, h), columns, a.output)
    counts = {t: sum(len(l[t]) for _, l in views) for t in COLORS}
    print(f"{len(faces)} triangles, {a.views} views: {counts['silhouette']} silhouette and "
          f"{counts['suggestive']} suggestive-contour polylines; wrote {a.output}")


if __name__ == "__main__":
    main()
