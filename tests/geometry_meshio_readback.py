"""Reads the files geometry_write_samples writes back with meshio (python3-meshio):
counts of points and cells, every cell a hexahedron, the cube's corners in VTK order;
the block's cell data (scaled_jacobian and level in .vtk/.vtu, the level as medit:ref in
.mesh) with one value per cell, as written;\nthe polyhedral complex's face file as 36 quads.
Usage: geometry_meshio_readback.py WRITER_EXE WORK_DIR. Exit 77 (CTest skip) without meshio."""
import os
import shutil
import subprocess
import sys

try:
    import meshio
except ImportError:
    print("meshio not available: skipped")
    sys.exit(77)

writer, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
subprocess.run([writer, work], check=True)

def block_cell_data_ok(mesh, ext, n_hexes):
    # geometry_write_samples writes level h % 3 and scaled Jacobian 1 - h / 100 for hex h.
    def field(name):
        return [v for block in mesh.cell_data.get(name, []) for v in block]
    level = field("medit:ref" if ext == ".mesh" else "level")
    if [int(v) for v in level] != [h % 3 for h in range(n_hexes)]:
        print("  level:", level)
        return False
    if ext == ".mesh":
        return True
    sj = field("scaled_jacobian")
    return len(sj) == n_hexes and all(abs(v - (1 - h / 100)) < 1e-15 for h, v in enumerate(sj))


failures = []
expected = {"cube": (8, 1), "block": (36, 12)}
for name, (n_points, n_hexes) in expected.items():
    for ext in (".vtk", ".vtu", ".mesh"):
        path = os.path.join(work, name + ext)
        mesh = meshio.read(path)
        types = sorted({block.type for block in mesh.cells})
        n_cells = sum(len(block.data) for block in mesh.cells)
        ok = len(mesh.points) == n_points and n_cells == n_hexes and types == ["hexahedron"]
        if name == "block" and ok:
            ok = block_cell_data_ok(mesh, ext, n_hexes)
        if name == "cube" and ok:
            conn = mesh.cells[0].data[0]
            pts = mesh.points[conn]
            # VTK order: 0-1-2-3 bottom counter-clockwise seen from the top, 4-7 above.
            ok = list(map(tuple, pts.round(12))) == [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                                                     (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
        print(f"{path}: {len(mesh.points)} points, {n_cells} cells {types}: {'ok' if ok else 'FAIL'}")
        if not ok:
            failures.append(path)

# The polyhedral complex's faces as polygons (meshio cannot read VTK_POLYHEDRON legacy cells).
path = os.path.join(work, "complex_faces.vtk")
mesh = meshio.read(path)
n_faces = sum(len(block.data) for block in mesh.cells)
sizes = sorted({block.data.shape[1] for block in mesh.cells})
ok = len(mesh.points) == 27 and n_faces == 36 and sizes == [4]
print(f"{path}: {len(mesh.points)} points, {n_faces} polygons of sizes {sizes}: {'ok' if ok else 'FAIL'}")
if not ok:
    failures.append(path)

shutil.rmtree(work, ignore_errors=True)
if failures:
    print("FAILED:", failures)
    sys.exit(1)
