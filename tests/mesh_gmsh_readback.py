"""`dualhex mesh` output read back with gmsh (python3-gmsh, the gmsh 4.8 API, headless):
for the default torus and gmsh_lever.stl, written as legacy VTK and MEDIT .mesh, gmsh must
read as many nodes and elements as the command's --json report says, every element a
hexahedron (gmsh type 5) with 8 distinct nodes.

Then three mutated copies must be rejected by the same check: a .mesh with one hexahedron
removed (element count), a .mesh whose last hexahedron uses a new copy of one of its
vertices (node count; gmsh ignores unreferenced vertices), a .vtk whose last cell is a
tetrahedron (element type). Usage: mesh_gmsh_readback.py DUALHEX_EXE WORK_DIR SHARED_DATA.
Fails (exit 1) without gmsh: scripts/debian-packages.txt installs python3-gmsh."""
import json
import os
import shutil
import subprocess
import sys

try:
    import gmsh
except ImportError:
    print("FAIL: the gmsh Python API is not available (Debian package python3-gmsh, listed in "
          "scripts/debian-packages.txt; run scripts/install-deps.sh). This test does not skip.")
    sys.exit(1)

HEXAHEDRON = 5  # gmsh element type


def gmsh_problems(path, vertices, hexes):
    """What is wrong with `path` as gmsh reads it, compared with the expected counts ([] = ok)."""
    gmsh.clear()
    try:
        gmsh.open(path)
    except Exception as e:  # gmsh raises on a read error
        return [f"gmsh cannot read it: {e}"]
    node_tags, _, _ = gmsh.model.mesh.getNodes()
    types, element_tags, element_nodes = gmsh.model.mesh.getElements()
    problems = []
    if len(node_tags) != vertices:
        problems.append(f"{len(node_tags)} nodes, expected {vertices}")
    elements = sum(len(tags) for tags in element_tags)
    if elements != hexes:
        problems.append(f"{elements} elements, expected {hexes}")
    if any(t != HEXAHEDRON for t in types):
        problems.append(f"element types {sorted(set(types))}, expected only {HEXAHEDRON} (hexahedron)")
    for t, nodes in zip(types, element_nodes):
        if t == HEXAHEDRON:
            nodes = list(nodes)
            if any(len(set(nodes[i:i + 8])) != 8 for i in range(0, len(nodes), 8)):
                problems.append("a hexahedron with repeated nodes")
    return problems


def write_mutated(src, dst, edit):
    with open(src) as f:
        lines = f.read().split("\n")
    with open(dst, "w") as f:
        f.write("\n".join(edit(lines)))


def drop_last_hexahedron(lines):  # MEDIT: decrement the count, remove the last hexahedron
    i = lines.index("Hexahedra")
    n = int(lines[i + 1])
    return lines[:i + 1] + [str(n - 1)] + lines[i + 2:i + 1 + n] + lines[i + 2 + n:]


def split_vertex(lines):  # MEDIT: the last hexahedron's first vertex becomes a new copy of it
    v = lines.index("Vertices")
    n = int(lines[v + 1])
    h = lines.index("Hexahedra")
    last = lines[h + 1 + int(lines[h + 1])].split()
    copy = lines[v + 1 + int(last[0])]
    lines[h + 1 + int(lines[h + 1])] = " ".join([str(n + 1)] + last[1:])
    return lines[:v + 1] + [str(n + 1)] + lines[v + 2:v + 2 + n] + [copy] + lines[v + 2 + n:]


def last_cell_tetrahedron(lines):  # legacy VTK: the last cell becomes a tetrahedron (VTK type 10)
    c = next(i for i, line in enumerate(lines) if line.startswith("CELLS "))
    n = int(lines[c].split()[1])
    last = lines[c + n].split()
    lines[c] = f"CELLS {n} {9 * n - 4}"
    lines[c + n] = " ".join(["4"] + last[1:5])
    t = next(i for i, line in enumerate(lines) if line.startswith("CELL_TYPES "))
    lines[t + n] = "10"
    return lines


exe, work, data = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
gmsh.initialize(readConfigFiles=False)
gmsh.option.setNumber("General.Terminal", 1)   # messages to the terminal, no GUI
gmsh.option.setNumber("General.Verbosity", 2)  # errors and warnings only

lever = os.path.join(data, "surfaces", "gmsh_lever.stl")
# At depth 5 the lever's holes are below the octree's resolution: the mesh is written but
# its topology differs (exit 1); this test is about reading it back, so it accepts that.
lever_args = [lever, "--accept-topology-change"]
cases = [([], "--max-depth", "4", ".vtk"), ([], "--max-depth", "4", ".mesh"),
         (lever_args, "--max-depth", "5", ".vtk"), (lever_args, "--max-depth", "5", ".mesh")]
failures = []
written = {}
for i, (inputs, opt, depth, ext) in enumerate(cases):
    path = os.path.join(work, f"out{i}{ext}")
    proc = subprocess.run([exe, "mesh", *inputs, "-o", path, opt, depth, "--json"], capture_output=True, text=True)
    if proc.returncode != 0:
        print(path, "dualhex mesh failed:", proc.returncode, proc.stderr)
        failures.append(path)
        continue
    report = json.loads(proc.stdout)
    problems = gmsh_problems(path, report["vertices"], report["hexes"])
    if report["hexes"] == 0:
        problems.append("no hexes")
    print(f"{path}: {report['vertices']} vertices, {report['hexes']} hexes: {'; '.join(problems) or 'ok'}")
    if problems:
        failures.append(path)
    written[ext] = (path, report)

# Negative checks: each mutation must be caught.
mutations = [(".mesh", drop_last_hexahedron), (".mesh", split_vertex), (".vtk", last_cell_tetrahedron)]
for ext, edit in mutations:
    if ext not in written:
        failures.append(f"mutation {edit.__name__}: no {ext} output to mutate")
        continue
    src, report = written[ext]
    dst = os.path.join(work, f"mutated_{edit.__name__}{ext}")
    write_mutated(src, dst, edit)
    problems = gmsh_problems(dst, report["vertices"], report["hexes"])
    print(f"{dst}: {'rejected: ' + '; '.join(problems) if problems else 'NOT rejected'}")
    if not problems:
        failures.append(dst)

gmsh.finalize()
shutil.rmtree(work, ignore_errors=True)
if failures:
    print("FAILED:", failures)
    sys.exit(1)
