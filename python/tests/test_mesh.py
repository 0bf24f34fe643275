"""dualhex.mesh(): the surface-to-hex pipeline from a file, arrays or the default torus."""
import numpy as np
import pytest

import dualhex


def read_off(path):
    import meshio
    m = meshio.read(path)
    return m.points.astype(np.float64), m.cells_dict["triangle"].astype(np.int64)


def test_the_default_torus_is_all_hex_and_not_inverted():
    m = dualhex.mesh(max_depth=4)
    r = m.report
    assert r["input"] == "<default torus>" and r["options"]["max_depth"] == 4
    assert len(m.hexes) == r["hexes"] > 0 and len(m.points) == r["vertices"]
    assert m.hexes.shape[1] == 8 and m.hexes.max() < len(m.points)
    assert m.quality.min() > 0 and m.quality.min() == pytest.approx(r["scaled_jacobian"]["min"])
    assert m.level is None


def test_the_same_mesh_as_the_command_line(shared_data, cli, tmp_path):
    # a model whose mesh passes the check at this depth (an inverted or flat hex exits 1)
    surface = shared_data / "surfaces" / "gao_eight_tri.off"
    m = dualhex.mesh(surface, max_depth=5, balance="strong")
    c = cli("mesh", str(surface), "-o", str(tmp_path / "j.vtu"), "--max-depth", "5", "--balance", "strong",
            "--accept-topology-change", "--optimise-ms", "0")
    for key in ("leaves", "cells", "hexes", "vertices", "boundary_vertices", "smooth_iterations"):
        assert m.report[key] == c[key], key
    assert m.report["scaled_jacobian"]["min"] == pytest.approx(c["scaled_jacobian"]["min"])
    import meshio
    written = meshio.read(tmp_path / "j.vtu")
    np.testing.assert_allclose(written.points, m.points, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(written.cells_dict["hexahedron"], m.hexes)


def test_arrays_give_the_same_mesh_as_the_file(shared_data):
    surface = shared_data / "surfaces" / "cgal_cube.off"
    from_file = dualhex.mesh(surface, preset="coarse")
    from_arrays = dualhex.mesh(read_off(surface), preset="coarse")
    assert from_arrays.report["input"] == "<(V, F) arrays>"
    np.testing.assert_array_equal(from_file.hexes, from_arrays.hexes)
    np.testing.assert_allclose(from_file.points, from_arrays.points)


def test_an_inward_surface_is_flipped_with_a_warning(shared_data):
    v, f = read_off(shared_data / "surfaces" / "cgal_cube.off")
    with pytest.warns(UserWarning, match="oriented inward; flipped"):
        m = dualhex.mesh((v, f[:, ::-1]), preset="coarse")
    assert any("flipped" in w for w in m.report["warnings"])
    assert len(m.hexes) == len(dualhex.mesh((v, f), preset="coarse").hexes)


def test_options_map_onto_the_pipeline():
    assert dualhex.mesh_option_names()[:2] == ["balance", "max_depth"]
    defaults = dualhex.mesh_defaults()
    assert list(defaults) == dualhex.mesh_option_names() and defaults["balance"] == "weak"
    assert dualhex.mesh(max_depth=4).report["options"] == dict(defaults, max_depth=4)
    m = dualhex.mesh(max_depth=4, smooth_iterations=0, balance="strong")
    assert m.report["options"]["smooth_iterations"] == 0 and m.report["smooth_iterations"] == 0
    assert m.report["options"]["balance"] == "strong"
    assert defaults["release_stuck"] is True
    assert dualhex.mesh(max_depth=4, release_stuck=False).report["options"]["release_stuck"] is False
    with pytest.raises(TypeError):
        dualhex.mesh(max_depth=4, release_stuck="no")


def test_to_meshio_has_the_hexes_and_quality():
    m = dualhex.mesh(max_depth=4)
    mio = m.to_meshio()
    assert len(mio.cells_dict["hexahedron"]) == len(m.hexes)
    assert "level" not in mio.cell_data


def test_a_missing_file_is_an_input_error_naming_it(tmp_path):
    with pytest.raises(dualhex.InputError) as e:
        dualhex.mesh(tmp_path / "nope.off")
    assert str(tmp_path / "nope.off") in str(e.value)


def test_an_open_surface_is_an_input_error(shared_data):
    v, f = read_off(shared_data / "surfaces" / "cgal_cube.off")
    with pytest.raises(dualhex.InputError) as e:
        dualhex.mesh((v, f[1:]))
    assert "<(V, F) arrays>" in str(e.value)


@pytest.mark.parametrize("surface, error", [
    ((np.zeros((4, 2)), np.array([[0, 1, 2]])), ValueError),
    ((np.zeros((4, 3)), np.array([[0.0, 1.0, 2.0]])), ValueError),
    ((np.zeros((4, 3)),), ValueError),
    ((np.eye(3), np.array([[0, 1, 7]])), dualhex.InputError),
    (42, TypeError),
])
def test_malformed_arrays(surface, error):
    with pytest.raises(error):
        dualhex.mesh(surface)


def test_a_preset_is_applied_first_and_refined_by_the_other_options():
    coarse = dualhex.mesh(max_depth=4, preset="coarse", size_rel=0.05).report["options"]
    assert coarse["size_rel"] == 0.05 and coarse["thickness_factor"] == 1.0 and coarse["curvature_angle"] == 50
    assert coarse["max_depth"] == 4
    fine = dualhex.mesh(size_rel=0.2, preset="fine", max_depth=4).report["options"]  # keyword order irrelevant
    assert fine["size_rel"] == 0.2 and fine["thickness_factor"] == dualhex.mesh_defaults()["thickness_factor"]
    absolute = dualhex.mesh(size=0.5, max_depth=4).report["options"]
    assert absolute["size"] == 0.5 and absolute["size_rel"] == 0  # as --size does
    core = dualhex.mesh(max_depth=4, core_margin=0.2, pad_ray_limit=3.0).report["options"]
    assert core["core_margin"] == 0.2 and core["pad_ray_limit"] == 3.0
    assert dualhex.mesh(max_depth=4, refine_rounds=1).report["options"]["refine_rounds"] == 1


def two_cubes():
    """Two cubes, the second far below the octree's resolution (as tests/test_mesh_cli.cpp)."""
    corners = [[(hi if v & 1 else lo), (hi if v & 2 else lo), (hi if v & 4 else lo)]
               for lo, hi in ((0.0, 1.0), (1.5, 1.501)) for v in range(8)]
    tris = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
            [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]
    return np.array(corners, dtype=np.float64), np.array([[a + b, b2 + b, c + b] for b in (0, 8) for a, b2, c in tris])


def test_a_topology_change_raises_unless_accepted():
    with pytest.raises(dualhex.MeshCheckError) as e:
        dualhex.mesh(two_cubes(), max_depth=4)
    assert "topology differs" in str(e.value) and e.value.mesh.report["topology"]["input_euler"] == [2, 2]
    assert len(e.value.mesh.hexes) > 0  # the mesh is there to look at
    accepted = dualhex.mesh(two_cubes(), max_depth=4, accept_topology_change=True)
    assert not accepted.report["topology"]["matches"]
    assert len(dualhex.mesh(two_cubes(), max_depth=4, check=False).hexes) == len(accepted.hexes)


def test_inverted_hexes_raise_naming_them():
    starved = dict(max_depth=4, smooth_iterations=0, optimise_work=0.000001)  # the optimiser gets one visit
    with pytest.raises(dualhex.MeshCheckError) as e:
        dualhex.mesh(**starved)
    inverted = e.value.mesh.report["inverted_hexes"]
    assert inverted and f"{len(inverted)} inverted or flat hex(es): {inverted[0]}" in e.value.problems[0]
    q = e.value.mesh.quality[inverted]
    assert np.logical_or(q <= 1e-6, np.isnan(q)).all()  # the check's flat threshold, kFlatScaledJacobian
    assert dualhex.mesh(max_depth=4).report["inverted_hexes"] == []


@pytest.mark.parametrize("kwargs, error, text", [
    ({"sise": 0.1}, TypeError, "unexpected keyword argument 'sise'"),
    ({"balance": "medium"}, ValueError, "balance"),
    ({"max_depth": 0}, ValueError, "max depth"),
    ({"max_depth": "deep"}, TypeError, "max_depth"),
    ({"max_depth": True}, TypeError, "max_depth"),
    ({"smooth_iterations": -1}, ValueError, "smoothing"),
    ({"preset": "huge"}, ValueError, "preset must be"),
    ({"core_margin": -1.0}, ValueError, "core margin"),
    ({"refine_rounds": 9}, ValueError, "refine"),
])
def test_bad_options(kwargs, error, text):
    with pytest.raises(error) as e:
        dualhex.mesh(**kwargs)
    assert text in str(e.value)


def test_the_command_line_reports_warnings_in_json_and_on_stderr(shared_data, tmp_path):
    """`dualhex mesh --json` without a terminal: the warning is in the JSON and on stderr once."""
    import json
    import os
    import subprocess
    exe = os.environ.get("DUALHEX_EXE")
    if not exe:
        pytest.skip("DUALHEX_EXE not set")
    v, f = read_off(shared_data / "surfaces" / "cgal_cube.off")
    inward = tmp_path / "inward.off"
    lines = ["OFF", f"{len(v)} {len(f)} 0"] + [" ".join(map(repr, p)) for p in v.tolist()]
    inward.write_text("\n".join(lines + [f"3 {a} {b} {c}" for a, b, c in f[:, ::-1].tolist()]) + "\n")
    out = subprocess.run([exe, "mesh", str(inward), "-o", str(tmp_path / "m.vtk"), "--json"],
                         capture_output=True, text=True, check=True)
    warnings = json.loads(out.stdout)["warnings"]
    assert warnings == [f"{inward}: triangles were oriented inward; flipped"]
    assert out.stderr.count("oriented inward") == 1 and out.stderr.count(str(inward)) == 1
    assert f"warning: {warnings[0]}" in out.stderr
