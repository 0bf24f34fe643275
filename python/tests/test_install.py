"""dualhex.install(): arrays and report from a leaf file or an (N, 4) array, and its errors."""
import threading
import time

import numpy as np
import pytest

import dualhex


def leaf_rows(path):
    return np.loadtxt(path, comments="#", dtype=np.int64, ndmin=2)


FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]  # outward, VTK order


def hex_volumes(points, hexes):
    """Each hex's volume by the divergence theorem over its faces, every quad split along
    the diagonal at its smallest point id: the two hexes sharing a face split it alike, so
    the faces inside cancel exactly and the total is the volume the hexes fill."""
    p = points - 0.5
    total = np.zeros(len(hexes))
    for face in FACES:
        quad = hexes[:, face]
        start = np.argmin(quad, axis=1)
        quad = np.take_along_axis(quad, (start[:, None] + np.arange(4)) % 4, axis=1)
        for a, b, c in [(0, 1, 2), (0, 2, 3)]:
            u, v, w = p[quad[:, a]], p[quad[:, b]], p[quad[:, c]]
            total += np.einsum("ij,ij->i", u, np.cross(v, w)) / 6.0
    return total


def test_sphere_strong_d5_matches_the_paper_figures(shared_data):
    m = dualhex.install(shared_data / "grids" / "sphere_strong_d5.leaves", balance="strong")
    r = m.report
    # The figures the paper's published implementation reports on this file.
    assert (r["cells"], r["non_hex_cells"], r["hexes"]) == (13952, 3608, 14745)
    assert r["dual_edge_valences"] == {3: 3192, 4: 36696, 5: 2280, 6: 408}
    assert r["ok"] and r["leaves"] == 11264
    assert m.points.shape == (r["dual_points"], 3) and m.points.dtype == np.float64
    assert m.hexes.shape == (14745, 8) and m.hexes.dtype == np.int64
    assert m.hexes.min() >= 0 and m.hexes.max() < len(m.points)
    assert all(len(set(h)) == 8 for h in m.hexes[:2000])
    assert m.quality.shape == (14745,) and m.quality.min() > 0
    assert set(np.unique(m.level)) <= {4, 5}


def test_the_clipped_dual_fills_the_root_cube(shared_data):
    m = dualhex.install(shared_data / "grids" / "sphere_weak_d5.leaves")
    assert m.points.min() == 0.0 and m.points.max() == 1.0
    volumes = hex_volumes(m.points, m.hexes)
    assert volumes.min() > 0
    assert volumes.sum() == pytest.approx(1.0, abs=1e-9)


def test_an_array_gives_the_same_mesh_as_the_file(shared_data):
    path = shared_data / "grids" / "sphere_weak_d5.leaves"
    from_file = dualhex.install(str(path))
    from_array = dualhex.install(leaf_rows(path))
    assert from_array.report["input"] == "<leaves array>"
    np.testing.assert_array_equal(from_file.hexes, from_array.hexes)
    np.testing.assert_array_equal(from_file.points, from_array.points)
    np.testing.assert_array_equal(from_file.level, from_array.level)


def test_weak_is_the_default_and_strong_refuses_a_weak_grid(shared_data):
    path = shared_data / "grids" / "sphere_weak_d5.leaves"
    assert dualhex.install(path).report["balance"] == "weak"
    with pytest.raises(dualhex.InstallError) as e:
        dualhex.install(path, balance="strong")
    assert "not strongly balanced" in str(e.value) and e.value.file == str(path)
    assert isinstance(e.value, dualhex.InputError)


def test_root_cube_and_a_uniform_grid():
    root = dualhex.install([[0, 0, 0, 0]])
    assert root.report["cells"] == 1 and len(root.hexes) == 8
    uniform = dualhex.install([[1, i, j, k] for i in range(2) for j in range(2) for k in range(2)])
    assert uniform.report["cells"] == 8 and len(uniform.hexes) == 27 and set(uniform.level) == {1}


def test_to_meshio_round_trips_through_a_file(tmp_path, shared_data):
    import meshio
    m = dualhex.install(shared_data / "grids" / "sphere_strong_d5.leaves")
    mio = m.to_meshio()
    assert mio.cells[0].type == "hexahedron" and len(mio.cells[0].data) == len(m.hexes)
    mio.write(tmp_path / "m.vtu")
    back = meshio.read(tmp_path / "m.vtu")
    np.testing.assert_array_equal(back.cells[0].data, m.hexes)
    np.testing.assert_allclose(back.cell_data["scaled_jacobian"][0], m.quality)


def test_a_missing_file_is_an_input_error_naming_it(tmp_path):
    missing = tmp_path / "nope.leaves"
    with pytest.raises(dualhex.InputError) as e:
        dualhex.install(missing)
    assert str(missing) in str(e.value) and e.value.file == str(missing)


def test_a_malformed_file_names_file_and_line(tmp_path):
    f = tmp_path / "bad.leaves"
    f.write_text("# two lines of leaves\n1 0 0 0\n1 0 zero 1\n")
    with pytest.raises(dualhex.InputError) as e:
        dualhex.install(f)
    assert e.value.file == str(f) and e.value.line == 3
    assert "not an integer: 'zero'" in str(e.value) and str(e.value).startswith(f"{f}:3:")


@pytest.mark.parametrize("rows, line, text", [
    ([[1, 0, 0, 0], [1, 0, 0, 0]], 2, "duplicate leaf 1 0 0 0"),
    ([[1, 2, 0, 0]], 1, "invalid leaf 1 2 0 0"),
    ([[99, 0, 0, 0]], 1, "level must be in [0, 30]"),
    ([[-1, 0, 0, 0]], 1, "invalid leaf -1 0 0 0"),
])
def test_a_bad_leaf_row_names_the_row(rows, line, text):
    with pytest.raises(dualhex.InputError) as e:
        dualhex.install(np.array(rows))
    assert e.value.line == line and text in str(e.value), str(e.value)
    assert e.value.file == "<leaves array>"


def test_a_gap_is_an_input_error_without_a_line():
    with pytest.raises(dualhex.InputError) as e:
        dualhex.install([[1, 0, 0, 0]])
    assert "gap" in str(e.value) and e.value.line is None


@pytest.mark.parametrize("leaves", [np.zeros((3, 3), dtype=np.int64), np.zeros(4, dtype=np.int64),
                                    np.array([[0.0, 0.5, 0.0, 0.0]]), [[0, 0, 0], [1, 1, 1, 1]]])
def test_a_malformed_array_is_a_value_error(leaves):
    with pytest.raises(ValueError):
        dualhex.install(leaves)


@pytest.mark.parametrize("kwargs", [{"balance": "medium"}, {"outside_root": "inside"}])
def test_a_bad_option_is_a_value_error(kwargs):
    with pytest.raises(ValueError) as e:
        dualhex.install([[0, 0, 0, 0]], **kwargs)
    assert list(kwargs.values())[0] in str(e.value)


def test_not_a_path_nor_an_array_is_a_type_error():
    with pytest.raises(TypeError):
        dualhex.install(5)


def test_the_gil_is_released_while_installing(shared_data):
    path = shared_data / "grids" / "sphere_strong_d6.leaves"
    call = {}

    def work():
        t0 = time.perf_counter()
        call["hexes"] = len(dualhex.install(path).hexes)
        call["seconds"] = time.perf_counter() - t0

    thread = threading.Thread(target=work)
    last, longest = time.perf_counter(), 0.0
    thread.start()
    while thread.is_alive():  # this thread runs only while the other does not hold the GIL
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    thread.join()
    assert call["hexes"] > 0
    assert longest < 0.5 * call["seconds"], (longest, call["seconds"])
