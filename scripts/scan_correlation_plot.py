#!/usr/bin/env python3
"""Plot of the residual's correlation against distance on the surface, for
the real Kinect scan and the simulated depth scans.

    scan_benchmark --stats --real SCANS_DIR --tsv scan_correlation.tsv
    python3 scripts/scan_correlation_plot.py scan_correlation.tsv [OUT.png]

The TSV has the columns scan, hops, correlation (one row per scan and graph
distance in edges). OUT.png defaults to
doc/Polygon_mesh_processing/fig/scan_correlation.png. Needs Debian's
python3-pil only. The real scan is drawn thick and black, every simulated
scan thin and coloured by its mesh; white noise along the normals would be a
flat line at 0.
"""

import csv
import os
import sys

from PIL import Image, ImageDraw

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PALETTE = [(31, 119, 180), (255, 127, 14), (44, 160, 44), (214, 39, 40), (148, 103, 189), (140, 86, 75)]


def read_curves(path):
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f, delimiter="\t"):
            curves.setdefault(row["scan"], []).append((int(row["hops"]), float(row["correlation"])))
    for c in curves.values():
        c.sort()
    return curves


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "doc", "Polygon_mesh_processing", "fig",
                                                              "scan_correlation.png")
    curves = read_curves(sys.argv[1])
    if not curves:
        sys.exit("no curve in " + sys.argv[1])
    max_hops = max(h for c in curves.values() for h, _ in c)
    W, H, left, right, top, bottom = 760, 440, 70, 250, 30, 60
    img = Image.new("RGB", (W, H), "white")
    d = ImageDraw.Draw(img)

    def xy(h, c):
        x = left + (h / max_hops) * (W - left - right)
        y = top + (1.0 - (c + 0.2) / 1.2) * (H - top - bottom)  # correlation -0.2 .. 1
        return x, y

    for c in [-0.2, 0.0, 0.2, 0.4, 0.6, 0.8, 1.0]:
        x0, y = xy(0, c)
        x1, _ = xy(max_hops, c)
        d.line([(x0, y), (x1, y)], fill=(120, 120, 120) if c == 0 else (225, 225, 225))
        d.text((left - 40, y - 6), "%.1f" % c, fill="black")
    for h in range(0, max_hops + 1, 2):
        x, y = xy(h, -0.2)
        d.line([(x, y), (x, y + 4)], fill="black")
        d.text((x - 4, y + 8), str(h), fill="black")
    d.text((left + 120, H - 28), "distance on the surface (edges of the mesh graph)", fill="black")
    d.text((left, 8), "correlation of the residual's normal component (noisy - ground truth)", fill="black")

    meshes = sorted({name.split(" ")[1].split("@")[0] for name in curves if name.startswith("simulated")})
    colour = {m: PALETTE[i % len(PALETTE)] for i, m in enumerate(meshes)}
    legend = []
    for name, c in sorted(curves.items(), key=lambda kv: kv[0].startswith("real")):
        pts = [xy(0, 1.0)] + [xy(h, v) for h, v in c]
        if name.startswith("real"):
            d.line(pts, fill="black", width=4)
            legend.append(("real Kinect cone", (0, 0, 0), 4))
        else:
            mesh = name.split(" ")[1].split("@")[0]
            d.line(pts, fill=colour[mesh], width=1)
            if ("simulated " + mesh, colour[mesh], 1) not in legend:
                legend.append(("simulated " + mesh, colour[mesh], 1))
    for i, (label, col, width) in enumerate(legend):
        y = top + 10 + 18 * i
        d.line([(W - right + 20, y), (W - right + 50, y)], fill=col, width=max(width, 2))
        d.text((W - right + 58, y - 6), label, fill="black")
    img.save(out)
    print("wrote", out)


if __name__ == "__main__":
    main()
