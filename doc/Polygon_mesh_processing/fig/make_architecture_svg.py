# Writes architecture.svg (next to this script): the data flow of intrinsic_denoising(),
# the picture of the manual's section "Architecture". Run: python3 make_architecture_svg.py
W, H = 900, 560
boxes = {}  # name -> (x, y, w, h, title, lines)
def box(name, x, y, w, h, title, lines, fill="#eef3fb"):
    boxes[name] = (x, y, w, h, title, lines, fill)
box("user", 20, 20, 250, 60, "your mesh", ["any FaceGraph, property maps"], "#fff6e0")
box("flat", 20, 120, 250, 78, "mesh/mesh_access.h, core/input_checks.h", ["checks, then a flat copy:", "mesh/flat_mesh.h (positions, triangles)"])
box("face", 20, 240, 250, 78, "mesh/face_data.h", ["normals, areas, centroids;", "Morton order; d"])
box("nbr", 320, 120, 260, 60, "neighborhoods/neighborhoods.h", ["faces within r of each face (CSR)"])
box("paths", 320, 220, 260, 98, "paths/, built once (path_forest.h)", ["square_pattern_paths.h (section 4)", "geodesic_paths.h (exact geodesics)", "graph_paths.h, direct paths"])
box("setup", 320, 360, 260, 60, "filter/intrinsic_setup.h", ["parameters -> kernel, radius, paths"])
box("pass", 630, 120, 250, 78, "weights/normal_filter_pass.h", ["eq. 8-9: path_weights.h engine", "or path_weights_simd.h kernels"])
box("vu", 630, 240, 250, 78, "vertices/vertex_update.h", ["eq. 10 + fold safeguard, or", "least_squares_vertex_update.h"])
box("iter", 630, 360, 250, 60, "filter/filter_iterations.h", ["Algorithm 1: pass, update, repeat"])
box("driver", 320, 460, 560, 78, "intrinsic_denoiser.h (driver of intrinsic_denoising())", ["automatic/automatic_mode.h: candidates stopped by their residual, sparse noise, self-check;", "or given parameters (automatic/automatic_parameters.h) and the stopping rule"], "#e8f6ec")
box("out", 20, 470, 250, 60, "your mesh, updated once", ["+ Intrinsic_denoising_report"], "#fff6e0")
arrows = [("user", "flat", "down"), ("flat", "face", "down"), ("face", "nbr", "right"), ("nbr", "paths", "down"),
          ("paths", "setup", "down"), ("setup", "iter", "right"), ("pass", "vu", "down"), ("vu", "iter", "down"),
          ("iter", "pass", "loop"), ("setup", "driver", "down"), ("driver", "out", "left")]
def center(b, side):
    x, y, w, h = boxes[b][:4]
    return {"top": (x + w / 2, y), "bottom": (x + w / 2, y + h), "left": (x, y + h / 2), "right": (x + w, y + h / 2)}[side]
out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d" font-family="sans-serif">' % (W, H, W, H),
       '<defs><marker id="a" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="#444"/></marker></defs>',
       '<rect width="100%" height="100%" fill="white"/>']
for name, (x, y, w, h, title, lines, fill) in boxes.items():
    out.append('<rect x="%d" y="%d" width="%d" height="%d" rx="6" fill="%s" stroke="#555"/>' % (x, y, w, h, fill))
    out.append('<text x="%d" y="%d" font-size="13" font-weight="bold">%s</text>' % (x + 8, y + 18, title))
    for i, l in enumerate(lines):
        out.append('<text x="%d" y="%d" font-size="12">%s</text>' % (x + 8, y + 36 + 16 * i, l.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")))
for a, b, kind in arrows:
    if kind == "down":
        (x1, y1), (x2, y2) = center(a, "bottom"), center(b, "top")
        if a == "setup" and b == "driver":
            x1 = x2 = 450
    elif kind == "right":
        (x1, y1), (x2, y2) = center(a, "right"), center(b, "left")
    elif kind == "left":
        (x1, y1), (x2, y2) = center(a, "left"), center(b, "right")
    if kind == "loop":
        x, y, w, h = boxes["iter"][:4]
        out.append('<path d="M%d,%d C%d,%d %d,%d %d,%d" fill="none" stroke="#444" stroke-width="1.5" marker-end="url(#a)"/>' % (x + w, y + h / 2, x + w + 15, y + h / 2, x + w + 15, 159, x + w, 159))
        out.append('<text x="%d" y="%d" font-size="11" fill="#444">k times</text>' % (x + w - 55, 350))
        continue
    out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="#444" stroke-width="1.5" marker-end="url(#a)"/>' % (x1, y1, x2, y2))
out.append('<text x="460" y="446" font-size="11" fill="#444">one setup per radius; the driver runs the iterations on it</text>')
out.append('</svg>')
open(__import__("os").path.join(__import__("os").path.dirname(__import__("os").path.abspath(__file__)), "architecture.svg"), "w").write("\n".join(out) + "\n")
