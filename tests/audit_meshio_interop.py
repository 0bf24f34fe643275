#!/usr/bin/env python3
"""`dualhex audit` on files written by meshio (another implementation's writers): a 3x2x2
hex block in every format and encoding meshio writes that the audit reads, and the same
block with one hex's corner repeated. Each good file must pass (exit 0, 12 hexes), each
defective one must fail distinct-vertices (exit 1) naming cell 5.
Usage: audit_meshio_interop.py DUALHEX WORKDIR. Exit 77 (skip) without meshio."""
import json
import os
import subprocess
import sys

try:
    import meshio
    import numpy as np
except ImportError:
    print("meshio not available: skipped")
    sys.exit(77)

exe, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)

nx, ny, nz = 3, 2, 2
pid = lambda i, j, k: i + (nx + 1) * (j + (ny + 1) * k)
points = np.array([[i * 0.5, j * 0.5, k * 0.5] for k in range(nz + 1) for j in range(ny + 1) for i in range(nx + 1)])
hexes = np.array([[pid(i, j, k), pid(i + 1, j, k), pid(i + 1, j + 1, k), pid(i, j + 1, k),
                   pid(i, j, k + 1), pid(i + 1, j, k + 1), pid(i + 1, j + 1, k + 1), pid(i, j + 1, k + 1)]
                  for k in range(nz) for j in range(ny) for i in range(nx)])
bad = hexes.copy()
bad[5][7] = bad[5][6]

variants = [("ascii.vtk", dict(binary=False)), ("binary.vtk", dict(binary=True)),
            ("ascii.vtu", dict(binary=False)), ("binary.vtu", dict(binary=True, compression=None)),
            ("medit.mesh", {})]
failures = 0
for name, kwargs in variants:
    for label, cells in (("good", hexes), ("bad", bad)):
        path = os.path.join(work, label + "_" + name)
        meshio.write(path, meshio.Mesh(points, [("hexahedron", cells)]), **kwargs)
        r = subprocess.run([exe, "audit", path, "--json"], capture_output=True, text=True)
        try:
            report = json.loads(r.stdout)
        except json.JSONDecodeError:
            report = {}
        if label == "good":
            ok = r.returncode == 0 and report.get("statistics", {}).get("hexes") == 12
        else:
            check = [c for c in report.get("checks", []) if c["name"] == "distinct-vertices"]
            ok = r.returncode == 1 and check and check[0]["violations"] == 1 and check[0]["listed"][0]["cell"] == 5
        print(("ok  " if ok else "FAIL"), path, "rc", r.returncode, r.stderr.strip())
        failures += 0 if ok else 1
sys.exit(1 if failures else 0)
