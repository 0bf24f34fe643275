"""`dualhex mesh` output read back with meshio (python3-meshio): for the default torus
(.vtk, .vtu, .mesh) and cgal_cube.off (.vtu), the number of points and hexahedra meshio
reads equals the command's --json report, every cell is a hexahedron with 8 distinct
vertices. Usage: mesh_meshio_readback.py DUALHEX_EXE WORK_DIR SHARED_DATA.
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
    print(f"{path}: {len(mesh.points)} points ({report['vertices']}), {len(cells)} cells ({report['hexes']}) "
          f"{types}: {'ok' if ok else 'FAIL'}")
    if not ok:
        failures.append(path)

shutil.rmtree(work, ignore_errors=True)
if failures:
    print("FAILED:", failures)
    sys.exit(1)
