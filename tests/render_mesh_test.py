#!/usr/bin/env python3
"""docs/render_mesh.py (the README's mesh picture) on a 2x2x2 block of unit hexes: a cut
shows section faces coloured by scaled Jacobian (green at 1) beside grey surface quads, no
cut shows none; an existing picture is kept without --force; a file that is not a VTK mesh
is refused with a message naming it.
Usage: render_mesh_test.py SCRIPT WORK_DIR"""
import os
import subprocess
import sys
import zlib


def block_vtk(path):
    pts = [(i, j, k) for k in range(3) for j in range(3) for i in range(3)]
    pid = lambda i, j, k: i + 3 * (j + 3 * k)
    hexes = []
    for k in range(2):
        for j in range(2):
            for i in range(2):
                hexes.append([pid(i, j, k), pid(i + 1, j, k), pid(i + 1, j + 1, k), pid(i, j + 1, k),
                              pid(i, j, k + 1), pid(i + 1, j, k + 1), pid(i + 1, j + 1, k + 1), pid(i, j + 1, k + 1)])
    with open(path, "w") as f:
        f.write("# vtk DataFile Version 4.2\nblock\nASCII\nDATASET UNSTRUCTURED_GRID\n")
        f.write(f"POINTS {len(pts)} double\n" + "".join(f"{x} {y} {z}\n" for x, y, z in pts))
        f.write(f"CELLS {len(hexes)} {9 * len(hexes)}\n" + "".join("8 " + " ".join(map(str, h)) + "\n" for h in hexes))
        f.write(f"CELL_TYPES {len(hexes)}\n" + "12\n" * len(hexes))
        f.write(f"CELL_DATA {len(hexes)}\nSCALARS scaled_jacobian double 1\nLOOKUP_TABLE default\n" + "1\n" * len(hexes))


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    at, idat, width, height = 8, b"", 0, 0
    while at < len(data):
        n = int.from_bytes(data[at:at + 4], "big")
        kind, body = data[at + 4:at + 8], data[at + 8:at + 8 + n]
        if kind == b"IHDR":
            width, height = int.from_bytes(body[:4], "big"), int.from_bytes(body[4:8], "big")
            assert body[8:10] == b"\x08\x02", "8-bit RGB expected"
        elif kind == b"IDAT":
            idat += body
        at += 12 + n
    raw = zlib.decompress(idat)
    stride = 1 + 3 * width
    assert len(raw) == stride * height
    assert all(raw[y * stride] == 0 for y in range(height)), "filter type 0 expected"
    return width, height, [tuple(raw[y * stride + 1 + 3 * x:y * stride + 4 + 3 * x]) for y in range(height) for x in range(width)]


def kinds(pixels):
    green = sum(1 for r, g, b in pixels if g > 1.5 * r and g > 2 * b and g > 60)
    grey = sum(1 for r, g, b in pixels if r > 60 and abs(r - g) < 20 and abs(g - b) < 25 and r < 250)
    return green, grey


def main():
    script, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    mesh, png = os.path.join(work, "block.vtk"), os.path.join(work, "block.png")
    block_vtk(mesh)
    run = lambda *extra: subprocess.run([sys.executable, script, mesh, png, "--width", "160", "--height", "120", "--force", *extra],
                                        capture_output=True, text=True, timeout=60)
    failures = []
    r = run("--cut-axis", "x", "--cut-at", "0.5", "--azimuth", "20")
    if r.returncode != 0:
        failures.append("cut run failed: " + r.stderr)
    else:
        width, height, pixels = read_png(png)
        green, grey = kinds(pixels)
        print(f"cut: {width}x{height}, {green} section pixels, {grey} surface pixels; {r.stdout.strip()}")
        if (width, height) != (160, 120) or green < 200 or grey < 200:
            failures.append("the cut picture lacks its section or its surface")
    r = run("--cut-at", "1.0")
    if r.returncode != 0:
        failures.append("uncut run failed: " + r.stderr)
    else:
        green, grey = kinds(read_png(png)[2])
        print(f"no cut: {green} section pixels, {grey} surface pixels")
        if green != 0 or grey < 200:
            failures.append("without a cut there must be surface only")
    r = subprocess.run([sys.executable, script, mesh, png], capture_output=True, text=True, timeout=60)
    print(f"existing output: exit {r.returncode}, {r.stderr.strip()}")
    if r.returncode == 0 or "--force" not in r.stderr:
        failures.append("an existing picture must not be overwritten without --force")
    os.remove(png)
    bad = os.path.join(work, "not_a_mesh.vtk")
    with open(bad, "w") as f:
        f.write("solid nothing\nendsolid\n")
    r = subprocess.run([sys.executable, script, bad, png], capture_output=True, text=True, timeout=60)
    print(f"bad input: exit {r.returncode}, {r.stderr.strip()}")
    if r.returncode == 0 or "not_a_mesh.vtk" not in r.stderr:
        failures.append("a file that is no VTK mesh must be refused, naming the file")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
