#!/usr/bin/env python3
"""A picture of a hex mesh and its cross-section, for the README (Python standard library only).

  docs/render_mesh.py MESH.vtk OUT.png [--cut-axis x|y|z] [--cut-at F] [--up x|y|z]
                      [--azimuth DEG] [--elevation DEG] [--width W] [--height H] [--force]

Reads the legacy ASCII VTK that `dualhex mesh -o MESH.vtk` writes (points, VTK_HEXAHEDRON
cells, the `scaled_jacobian` cell data), keeps the hexes whose centroid lies on the low side
of the plane at fraction F of the bounding box along the axis (default x at 0.5), and draws
what is left: the mesh's boundary quads (the surface) in grey, the quads the cut exposes
(faces of two hexes, one of them removed) coloured by their kept hex's scaled Jacobian
(red 0, yellow 0.5, green 1), every quad's edges in dark grey. Orthographic view, flat
shading, a z-buffer; nothing is smoothed or simplified, so what is seen is the mesh.
"""
import argparse
import math
import os
import struct
import sys
import zlib

# The 6 faces of a VTK_HEXAHEDRON, each listed counter-clockwise seen from outside.
HEX_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def fail(message):
    sys.exit("render_mesh.py: " + message)


def read_vtk(path):
    """(points, hexes, scaled_jacobian or None) of a legacy ASCII VTK unstructured grid."""
    try:
        with open(path, encoding="ascii") as f:
            tokens = f.read().split()
    except (OSError, UnicodeDecodeError) as e:
        fail(f"{path}: {e}")
    try:
        points, hexes, sj = parse_vtk(path, tokens)
    except (ValueError, IndexError):
        fail(f"{path}: a malformed or truncated POINTS, CELLS or scaled_jacobian section")
    if any(i < 0 or i >= len(points) for h in hexes for i in h):
        fail(f"{path}: a hexahedron refers to a point that is not in POINTS")
    if sj is not None and len(sj) != len(hexes):
        fail(f"{path}: {len(sj)} scaled_jacobian values for {len(hexes)} hexahedra")
    return points, hexes, sj


def parse_vtk(path, tokens):
    at = 0

    def find(word):
        nonlocal at
        while at < len(tokens) and tokens[at] != word:
            at += 1
        if at == len(tokens):
            fail(f"{path}: no {word} section (an ASCII VTK from dualhex mesh is expected)")
        at += 1

    find("POINTS")
    n = int(tokens[at])
    at += 2
    coords = [float(t) for t in tokens[at:at + 3 * n]]
    if len(coords) != 3 * n:
        raise ValueError("truncated")
    points = [tuple(coords[3 * i:3 * i + 3]) for i in range(n)]
    find("CELLS")
    cells, at = int(tokens[at]), at + 2
    hexes = []
    for _ in range(cells):
        k = int(tokens[at])
        ids = tuple(int(t) for t in tokens[at + 1:at + 1 + k])
        at += 1 + k
        if k == 8:
            hexes.append(ids)
    sj = None
    if "scaled_jacobian" in tokens:
        at = tokens.index("scaled_jacobian") + 3  # SCALARS scaled_jacobian double 1 [LOOKUP_TABLE default]
        if tokens[at] == "LOOKUP_TABLE":
            at += 2
        sj = [float(t) for t in tokens[at:at + len(hexes)]]
    return points, hexes, sj


def sj_colour(s):
    """red (<= 0) -> yellow (0.5) -> green (1)."""
    s = max(0.0, min(1.0, s))
    if s < 0.5:
        return (0.85, 0.15 + 1.4 * s, 0.1)
    return (0.85 - 1.4 * (s - 0.5), 0.85, 0.1)


def visible_quads(points, hexes, sj, axis, cut_at):
    """(corner ids, colour) of the quads to draw: the kept hexes' faces that no kept hex shares."""
    lo = min(p[axis] for p in points)
    hi = max(p[axis] for p in points)
    plane = lo + cut_at * (hi - lo)
    uses = {}
    for h, ids in enumerate(hexes):
        for face in HEX_FACES:
            key = tuple(sorted(ids[i] for i in face))
            uses.setdefault(key, []).append((h, tuple(ids[i] for i in face)))
    kept = [sum(points[i][axis] for i in ids) / 8 <= plane for ids in hexes]
    quads = []
    for key, owners in uses.items():
        shown = [(h, loop) for h, loop in owners if kept[h]]
        if len(shown) != 1:
            continue
        h, loop = shown[0]
        if len(owners) == 1:
            quads.append((loop, (0.72, 0.74, 0.78)))
        else:
            quads.append((loop, sj_colour(sj[h]) if sj else (0.9, 0.6, 0.2)))
    return quads


def camera(azimuth, elevation, up_axis):
    """(towards the viewer, screen right, screen up) for a view from azimuth / elevation
    (degrees) around the up axis (0, 1, 2)."""
    a, e = math.radians(azimuth), math.radians(elevation)
    first, second = (up_axis + 1) % 3, (up_axis + 2) % 3

    def vec(along_first, along_second, along_up):
        v = [0.0, 0.0, 0.0]
        v[first], v[second], v[up_axis] = along_first, along_second, along_up
        return tuple(v)

    view = vec(math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e))
    right = vec(-math.sin(a), math.cos(a), 0.0)
    up = (view[1] * right[2] - view[2] * right[1], view[2] * right[0] - view[0] * right[2],
          view[0] * right[1] - view[1] * right[0])
    return view, right, up


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def render(points, quads, width, height, azimuth, elevation, up_axis):
    view, right, up = camera(azimuth, elevation, up_axis)
    screen = [(dot(p, right), dot(p, up), dot(p, view)) for p in points]
    xs = [s[0] for s in screen]
    ys = [s[1] for s in screen]
    scale = 0.92 * min(width / (max(xs) - min(xs)), height / (max(ys) - min(ys)))
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    px = [((s[0] - cx) * scale + width / 2, height / 2 - (s[1] - cy) * scale, s[2] * scale) for s in screen]
    depth = [-math.inf] * (width * height)
    image = bytearray(b"\xff" * (3 * width * height))
    edges = []
    for loop, colour in quads:
        a, b, c, d = (points[i] for i in loop)
        u = (c[0] - a[0], c[1] - a[1], c[2] - a[2])
        v = (d[0] - b[0], d[1] - b[1], d[2] - b[2])
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        length = math.sqrt(dot(n, n)) or 1.0
        facing = dot(n, view) / length
        if facing <= 0:
            continue  # seen from behind: a kept hex's far side
        shade = 0.35 + 0.65 * facing
        rgb = bytes(min(255, int(255 * shade * ch)) for ch in colour)
        corners = [px[i] for i in loop]
        fill_triangle(corners[0], corners[1], corners[2], rgb, image, depth, width, height)
        fill_triangle(corners[0], corners[2], corners[3], rgb, image, depth, width, height)
        edges.append(corners)
    bias = 1e-3 * scale
    for corners in edges:
        for k in range(4):
            draw_line(corners[k], corners[(k + 1) % 4], bias, image, depth, width, height)
    return image


def fill_triangle(p0, p1, p2, rgb, image, depth, width, height):
    x0, x1 = max(0, int(min(p0[0], p1[0], p2[0]))), min(width - 1, int(max(p0[0], p1[0], p2[0])) + 1)
    y0, y1 = max(0, int(min(p0[1], p1[1], p2[1]))), min(height - 1, int(max(p0[1], p1[1], p2[1])) + 1)
    area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1])
    if area == 0:
        return
    for y in range(y0, y1 + 1):
        for x in range(x0, x1 + 1):
            qx, qy = x + 0.5, y + 0.5
            w0 = ((p1[0] - qx) * (p2[1] - qy) - (p2[0] - qx) * (p1[1] - qy)) / area
            w1 = ((p2[0] - qx) * (p0[1] - qy) - (p0[0] - qx) * (p2[1] - qy)) / area
            w2 = 1 - w0 - w1
            if w0 < 0 or w1 < 0 or w2 < 0:
                continue
            z = w0 * p0[2] + w1 * p1[2] + w2 * p2[2]
            i = y * width + x
            if z > depth[i]:
                depth[i] = z
                image[3 * i:3 * i + 3] = rgb


def draw_line(a, b, bias, image, depth, width, height):
    steps = int(max(abs(b[0] - a[0]), abs(b[1] - a[1]))) + 1
    for s in range(steps + 1):
        t = s / steps
        x, y = int(a[0] + t * (b[0] - a[0])), int(a[1] + t * (b[1] - a[1]))
        if 0 <= x < width and 0 <= y < height:
            i = y * width + x
            if a[2] + t * (b[2] - a[2]) + bias >= depth[i]:
                image[3 * i:3 * i + 3] = b"\x30\x30\x30"


def write_png(path, image, width, height):
    rows = b"".join(b"\x00" + bytes(image[3 * width * y:3 * width * (y + 1)]) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mesh")
    ap.add_argument("png")
    ap.add_argument("--cut-axis", choices="xyz", default="x")
    ap.add_argument("--cut-at", type=float, default=0.5, help="fraction of the bounding box (1: no cut)")
    ap.add_argument("--up", choices="xyz", default="z", help="the axis drawn upwards")
    ap.add_argument("--azimuth", type=float, default=35.0)
    ap.add_argument("--elevation", type=float, default=25.0)
    ap.add_argument("--width", type=int, default=900)
    ap.add_argument("--height", type=int, default=700)
    ap.add_argument("--force", action="store_true", help="overwrite PNG if it exists")
    args = ap.parse_args()
    if os.path.exists(args.png) and not args.force:
        fail(f"{args.png} exists (--force overwrites it)")
    if not (0 < args.width <= 8192 and 0 < args.height <= 8192):
        fail("--width and --height must be in 1..8192")
    points, hexes, sj = read_vtk(args.mesh)
    if not hexes:
        fail(f"{args.mesh}: no hexahedra")
    quads = visible_quads(points, hexes, sj, "xyz".index(args.cut_axis), args.cut_at)
    image = render(points, quads, args.width, args.height, args.azimuth, args.elevation, "xyz".index(args.up))
    write_png(args.png, image, args.width, args.height)
    print(f"{args.png}: {len(hexes)} hexes, {len(quads)} quads drawn (cut {args.cut_axis} at {args.cut_at})")


if __name__ == "__main__":
    main()
