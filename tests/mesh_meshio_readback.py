"""`dualhex mesh` output read back with meshio (python3-meshio): for the default torus
(.vtk, .vtu, .mesh) and cgal_cube.off (.vtu), the number of points and hexahedra meshio
reads equals the command's --json report, every cell is a hexahedron with 8 distinct
vertices; the cell data is there with one value per cell: scaled_jacobian (its minimum the
report's) and level (in [0, octree depth]) in .vtk and .vtu, the level as the MEDIT
reference (medit:ref) in .mesh. Usage: mesh_meshio_readback.py DUALHEX_EXE WORK_DIR SHARED_DATA.
Exit 77 (CTest skip) without meshio."""
import json
import os
import shutil
import subprocess
import sys

try:
    import meshio
except ImportError:
    print("meshio not available: skipped")
    sys.exit(77)

exe, work, data = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

def cell_field(mesh, name):
    """The cell field `name` over all blocks, or None."""
    if name not in mesh.cell_data:
        return None
    return [v for block in mesh.cell_data[name] for v in block]


def cell_data_ok(mesh, ext, report, n_cells):
    depth = report["size"]["octree_depth"]
    level = cell_field(mesh, "medit:ref" if ext == ".mesh" else "level")
    if level is None or len(level) != n_cells or not all(0 <= int(v) <= depth for v in level):
        print("  level cell data missing or wrong:", None if level is None else len(level))
        return False
    if ext == ".mesh":
        return True
    sj = cell_field(mesh, "scaled_jacobian")
    if sj is None or len(sj) != n_cells or abs(min(sj) - report["scaled_jacobian"]["min"]) > 1e-9:
        print("  scaled_jacobian cell data missing or wrong")
        return False
    return True


cases = [([], ".vtk"), ([], ".vtu"), ([], ".mesh"), ([os.path.join(data, "surfaces", "cgal_cube.off")], ".vtu")]
failures = []
for i, (inputs, ext) in enumerate(cases):
    path = os.path.join(work, f"out{i}{ext}")
    proc = subprocess.run([exe, "mesh", *inputs, "-o", path, "--max-depth", "4", "--json"],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        print(path, "dualhex mesh failed:", proc.returncode, proc.stderr)
        failures.append(path)
        continue
    report = json.loads(proc.stdout)
    mesh = meshio.read(path)
    types = sorted({block.type for block in mesh.cells})
    cells = [c for block in mesh.cells for c in block.data]
    distinct = all(len(set(map(int, c))) == 8 for c in cells)
    ok = (types == ["hexahedron"] and len(cells) == report["hexes"] and len(mesh.points) == report["vertices"]
          and distinct and report["hexes"] > 0)
    ok = ok and cell_data_ok(mesh, ext, report, len(cells))
    print(f"{path}: {len(mesh.points)} points ({report['vertices']}), {len(cells)} cells ({report['hexes']}) "
          f"{types}: {'ok' if ok else 'FAIL'}")
    if not ok:
        failures.append(path)

shutil.rmtree(work, ignore_errors=True)
if failures:
    print("FAILED:", failures)
    sys.exit(1)
