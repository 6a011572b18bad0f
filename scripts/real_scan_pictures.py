#!/usr/bin/env python3
"""Pictures of the real scans: noisy input, automatic mode, the paper's fixed
setting and a wider, longer setting, side by side, one row a scan.

    python3 scripts/real_scan_pictures.py SCANS_DIR [OUT.png]

SCANS_DIR holds the real scans (kinect_cone_noisy.obj with
kinect_cone_groundtruth.obj, angel.obj, rabbit.obj, iron.ply); OUT.png
defaults to doc/Polygon_mesh_processing/fig/real_scans.png. Needs the built
`denoise` tool (build/tools/denoise/denoise), the renderer
of tools/render (scripts/install_render_deps.sh) and Debian's python3-numpy
and python3-pil. Each scan is turned so that its mean face normal (the
scanner's viewing direction) faces the renderer's camera. The E_n, the
iterations and the seconds of every run are printed.
"""

import os
import re
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image, ImageDraw

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DENOISE = os.path.join(ROOT, "build", "tools", "denoise", "denoise")
RENDER = os.path.join(ROOT, "tools", "render", "render.mjs")
# the renderer's default viewing direction (tools/render/viewer.js)
CAMERA = np.array([1.0, 0.6, 1.4]) / np.linalg.norm([1.0, 0.6, 1.4])
SETTINGS = [
    ("noisy", ["--fixed", "-k", "0"]),
    ("automatic", []),
    ("fixed (k 30, r 4d, sigma 0.4)", ["--fixed"]),
    ("k 60, r 6d, sigma 0.8", ["-k", "60", "--relative-radius", "6", "--sigma-spatial", "0.8", "--sigma-range", "0.8"]),
]
SCANS = [("kinect_cone_noisy.obj", "kinect_cone_groundtruth.obj"), ("angel.obj", None), ("rabbit.obj", None),
         ("iron.ply", None)]
TILE = 360


def read_off(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#")[0].split()]
    n, m = int(tokens[1]), int(tokens[2])
    V = np.array(tokens[4:4 + 3 * n], dtype=np.float64).reshape(n, 3)
    F = np.array(tokens[4 + 3 * n:4 + 3 * n + 4 * m], dtype=np.int64).reshape(m, 4)[:, 1:]
    return V, F


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        np.savetxt(f, V, fmt="%.17g")
        np.savetxt(f, np.hstack([np.full((len(F), 1), 3), F]), fmt="%d")


def rotation_to(d, v):
    """The rotation taking unit vector d to unit vector v (Rodrigues)."""
    axis = np.cross(d, v)
    s, c = np.linalg.norm(axis), float(np.dot(d, v))
    if s < 1e-12:
        return np.eye(3) if c > 0 else -np.eye(3)
    k = axis / s
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + s * K + (1 - c) * K @ K


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    scans_dir = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "doc", "Polygon_mesh_processing", "fig",
                                                             "real_scans.png")
    sheet = Image.new("RGB", (TILE * len(SETTINGS), (TILE + 24) * len(SCANS)), "white")
    draw = ImageDraw.Draw(sheet)
    with tempfile.TemporaryDirectory() as tmp:
        for row, (scan, truth) in enumerate(SCANS):
            rotation = None
            for col, (label, args) in enumerate(SETTINGS):
                off = os.path.join(tmp, "%d_%d.off" % (row, col))
                cmd = [DENOISE, os.path.join(scans_dir, scan)] + args + ["-o", off]
                if truth:
                    cmd += ["--reference", os.path.join(scans_dir, truth)]
                text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
                seconds = re.search(r"denoised in ([0-9.e+-]+) s", text)
                iterations = re.search(r"iterations: (\d+)", text)
                error = re.search(r"E_n \(degrees\): input [0-9.]+, denoised ([0-9.]+)", text)
                print("%-28s %-32s iterations %-4s seconds %-8s E_n %s" %
                      (scan, label, iterations.group(1) if iterations else "-",
                       seconds.group(1)[:6] if seconds else "-", error.group(1) if error else "-"))
                V, F = read_off(off)
                if rotation is None:  # from the noisy input, the same for every column
                    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]).sum(0)
                    rotation = rotation_to(n / np.linalg.norm(n), CAMERA)
                write_off(off, V @ rotation.T, F)
                png = off + ".png"
                subprocess.run(["node", RENDER, "--mesh", off, "--out", png, "--tile", str(TILE)], check=True,
                               capture_output=True)
                sheet.paste(Image.open(png).convert("RGB").resize((TILE, TILE)), (col * TILE, row * (TILE + 24) + 24))
                draw.text((col * TILE + 8, row * (TILE + 24) + 6), "%s: %s" % (scan.split(".")[0], label), fill="black")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    sheet.convert("L").save(out, optimize=True)  # the renders are grey
    print("wrote", out)


if __name__ == "__main__":
    main()
