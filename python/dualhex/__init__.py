"""dualhex: octree dual transition schemes as exact integer topology, and hex meshing.

    import dualhex
    m = dualhex.install("grid.leaves")          # or an (N, 4) int array of rows level i j k
    m = dualhex.mesh("part.off", max_depth=6)   # or (V, F) arrays, or None for a torus
    m.points, m.hexes, m.quality, m.level, m.report, m.to_meshio()
    dualhex.verify()["ok"], dualhex.classify()

Errors: dualhex.InputError (a bad file or array; .file, .line, .message), its subclass
dualhex.InstallError (a grid that is not paired / balanced as required), ValueError for
a bad option value, TypeError for an unknown option, dualhex.VerificationError for a
result that fails its own verification (a bug), dualhex.MeshCheckError for a mesh that fails
the mesh check (inverted or flat hexes, or a topology other than the input's): the
`dualhex mesh` exit 1 (.mesh holds the mesh, .problems says what failed and where).
"""
from ._dualhex import (InputError, InstallError, VerificationError, classify, elements_directory,
                       list_checks, mesh_defaults, mesh_option_names, verify)
from . import _dualhex

__all__ = ["Mesh", "install", "mesh", "verify", "list_checks", "classify", "mesh_option_names",
           "mesh_defaults", "elements_directory", "InputError", "InstallError", "VerificationError",
           "MeshCheckError"]


class MeshCheckError(RuntimeError):
    """dualhex.mesh()'s check failed (as `dualhex mesh` exits 1): .problems (list of str),
    .mesh (the dualhex.Mesh, to look at)."""

    def __init__(self, problems, mesh):
        super().__init__("; ".join(problems))
        self.problems = problems
        self.mesh = mesh


class Mesh:
    """An all-hex mesh: points (N, 3) float64, hexes (M, 8) int64 in VTK_HEXAHEDRON order,
    quality (M,) the scaled Jacobian of each hex, level (M,) int64 or None, report (dict)."""

    def __init__(self, parts):
        self.points = parts["points"]
        self.hexes = parts["hexes"]
        self.quality = parts["quality"]
        self.level = parts["level"]
        self.report = parts["report"]

    def __repr__(self):
        return f"<dualhex.Mesh: {len(self.points)} points, {len(self.hexes)} hexes>"

    def to_meshio(self):
        """The mesh as a meshio.Mesh (cells "hexahedron"; cell data scaled_jacobian, level)."""
        import meshio
        cell_data = {"scaled_jacobian": [self.quality]}
        if self.level is not None:
            cell_data["level"] = [self.level]
        return meshio.Mesh(self.points, [("hexahedron", self.hexes)], cell_data=cell_data)


def install(leaves, balance="weak", outside_root="coarse", check=True):
    """Installs the elements into a paired, balanced grid and returns its clipped dual.

    leaves: a path to a leaf file, or an (N, 4) integer array of rows level i j k (validated
    like a file; errors name the row as the line). balance: "weak" (the weak rule, accepts
    strongly balanced grids too) or "strong". outside_root: "coarse" or "mirror". With
    check (default) a result that fails its verification raises VerificationError.
    level[h] is the level of the finest leaf around hex h's primal vertex.
    """
    return Mesh(_dualhex._install(leaves, balance, outside_root, check))


def mesh(surface=None, check=True, accept_topology_change=False, **options):
    """Meshes a closed triangle surface with hexahedra (the `dualhex mesh` pipeline).

    surface: a path (OBJ/OFF/STL/PLY), a pair (V, F) of an (N, 3) float array and an
    (M, 3) integer array, or None for the embedded torus. options: see
    dualhex.mesh_option_names() / mesh_defaults() (balance, max_depth, ...), and
    preset="coarse" | "medium" | "fine" (the size options of `dualhex mesh --preset`, applied
    before the others). Warnings about the surface (e.g. flipped orientation) are issued as
    UserWarning and kept in report["warnings"]. level is None (the pipeline does not keep it).
    check (default): raise MeshCheckError where `dualhex mesh` exits 1: an inverted or flat
    hex (report["inverted_hexes"]), or boundary topology other than the input's unless
    accept_topology_change (report["topology"]). check=False returns the mesh either way.
    """
    m = Mesh(_dualhex._mesh(surface, **options))
    if check:
        problems = _check_problems(m.report, accept_topology_change)
        if problems:
            raise MeshCheckError(problems, m)
    return m


def _check_problems(report, accept_topology_change):
    problems = []
    inverted = report["inverted_hexes"]
    if inverted:
        shown = ", ".join(str(h) for h in inverted[:5]) + (", ..." if len(inverted) > 5 else "")
        problems.append(f"{len(inverted)} inverted or flat hex(es): {shown}")
    topology = report["topology"]
    if not topology["matches"] and not accept_topology_change:
        problems.append("boundary topology differs from the input's: " + "; ".join(topology["problems"]))
    return problems
