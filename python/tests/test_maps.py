# SPDX-License-Identifier: MIT
"""Maps from files and arrays: counts, positions, faces and incidences equal
what an independent reading of the file gives."""
import numpy as np
import pytest

import cgogn
from conftest import read_off


def test_load_gives_the_files_mesh(data):
    path = data / "surface" / "elephant-with-holes.off"
    points, faces = read_off(path)
    m = cgogn.load(str(path))
    assert isinstance(m, cgogn.CMap2)
    assert m.nb_cells("vertex") == len(points)
    assert m.nb_cells("face") == len(faces)
    edges = {tuple(sorted((f[i], f[(i + 1) % len(f)]))) for f in faces for i in range(len(f))}
    assert m.nb_cells("edge") == len(edges)
    assert m.euler_characteristic() == len(points) - len(edges) + len(faces)
    assert m.is_compact("vertex") and m.is_compact("face")
    assert np.allclose(m.positions, np.array(points))
    got = m.faces()
    assert got.shape == (len(faces), 3)
    # the same triangles, each up to rotation
    def canon(t):
        i = int(np.argmin(t))
        return tuple(t[i:]) + tuple(t[:i])
    assert sorted(canon(list(t)) for t in got) == sorted(canon(f) for f in faces)


@pytest.mark.parametrize("workers", [1, 2])
def test_faces_are_the_rows_of_faces_csr_whatever_the_dart_order(data, tmp_path, workers):
    # faces() scans the darts in ranges, one per worker: on a loaded surface
    # (the darts of each face consecutive) and on a subdivided one (new darts
    # at the end, so a range holds more triangles than its share of darts),
    # it gives the rows of faces_csr, in the same order
    n = cgogn.nb_workers()
    cgogn.set_nb_workers(workers)
    try:
        edited = cgogn.load(str(data / "surface" / "hemisphere.off"))
        edited.subdivide("loop", 2)
        assert edited.nb_darts() > 2**16  # enough darts for one range per worker
        edited.save(str(tmp_path / "big.off"))
        loaded = cgogn.load(str(tmp_path / "big.off"))
        for m in (edited, loaded):
            offsets, indices = m.faces_csr()
            got = m.faces()
            assert got.shape == (m.nb_cells("face"), 3)
            assert np.array_equal(got, indices.reshape(-1, 3))
    finally:
        cgogn.set_nb_workers(n)


def test_polygons_need_faces_csr(data):
    m = cgogn.load(str(data / "surface" / "cube_quad.off"))
    with pytest.raises(ValueError, match="faces_csr"):
        m.faces()
    offsets, indices = m.faces_csr()
    assert offsets.tolist() == list(range(0, 25, 4))
    assert len(indices) == 24 and set(indices.tolist()) == set(range(8))


def test_incidences_match_the_faces(data):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    offsets, indices = m.faces_csr()
    face_vertices = [set(indices[offsets[i] : offsets[i + 1]]) for i in range(len(offsets) - 1)]
    vo, vi = m.incidence("vertex", "face")
    assert len(vo) == m.nb_cells("vertex") + 1
    for v in range(m.nb_cells("vertex")):
        expected = {f for f, fv in enumerate(face_vertices) if v in fv}
        assert set(vi[vo[v] : vo[v + 1]]) == expected
    fo, fi = m.incidence("face", "vertex")
    for f in range(m.nb_cells("face")):
        assert set(fi[fo[f] : fo[f + 1]]) == face_vertices[f]
    # one row at a time, for walking cell by cell
    for v in range(0, m.nb_cells("vertex"), 7):
        assert m.incident("vertex", v, "face") == vi[vo[v] : vo[v + 1]].tolist()
    with pytest.raises(IndexError):
        m.incident("vertex", 10**6, "face")
    # vertex -> vertex: the neighbours through edges
    ao, ai = m.incidence("vertex", "vertex")
    eo, ei = m.incidence("edge", "vertex")
    pairs = {tuple(sorted(ei[eo[e] : eo[e + 1]])) for e in range(m.nb_cells("edge"))}
    for v in range(m.nb_cells("vertex")):
        assert set(ai[ao[v] : ao[v + 1]]) == {a if b == v else b for a, b in pairs if v in (a, b)}


def test_from_arrays_triangles_and_csr():
    points = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    m = cgogn.CMap2.from_arrays(points, np.array([[0, 1, 2], [0, 2, 3]]))
    assert (m.nb_cells("vertex"), m.nb_cells("edge"), m.nb_cells("face")) == (4, 5, 2)
    assert np.array_equal(m.positions, points)
    q = cgogn.CMap2.from_arrays(points, (np.array([0, 4]), np.array([0, 1, 2, 3])))
    assert q.nb_cells("face") == 1 and q.faces_csr()[1].tolist() == [0, 1, 2, 3]
    with pytest.raises(ValueError, match="point 7"):
        cgogn.CMap2.from_arrays(points, np.array([[0, 1, 7]]))
    with pytest.raises(ValueError, match="not finite"):
        cgogn.CMap2.from_arrays(np.array([[0, 0, np.nan]] * 3), np.array([[0, 1, 2]]))


def test_volume_from_arrays_and_cells():
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=float)
    tets = np.array([[0, 1, 2, 3], [1, 2, 3, 4]])
    m = cgogn.CMap3.from_arrays(points, tets)
    assert m.nb_cells("volume") == 2 and m.nb_cells("vertex") == 5
    assert m.euler_characteristic() == 1
    back = m.cells()
    assert sorted(map(sorted, back.tolist())) == sorted(map(sorted, tets.tolist()))
    # the same orientation: rebuilding from cells() gives a valid map again
    again = cgogn.CMap3.from_arrays(points, back)
    assert again.check_integrity()["ok"] and again.nb_cells("face") == m.nb_cells("face")
    offsets, indices = m.faces_csr()  # the boundary triangles
    assert len(offsets) - 1 == 6


def test_positions_alias_the_map(data):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    before = m.face_areas().sum()
    p = m.positions
    assert p.flags.writeable and p.dtype == np.float64
    p *= 2.0  # in place: the C++ algorithms see it
    assert m.face_areas().sum() == pytest.approx(4 * before)
    m.positions = np.asarray(p) / 2.0  # assignment copies in
    assert m.face_areas().sum() == pytest.approx(before)


def test_compaction_is_refused_while_arrays_alias_the_map(data):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    p = m.positions
    m.collapse_edge(0) if m.can_collapse_edge(0) else None
    with pytest.raises(RuntimeError, match="alias"):
        m.compact()
    del p
    import gc

    gc.collect()
    m.compact()
    assert m.is_compact("vertex") and m.check_integrity()["ok"]


def test_euler_characteristic_of_a_torus(data):
    m = cgogn.load(str(data / "surface" / "torus_quad.off"))
    assert m.euler_characteristic() == 0
    assert m.nb_connected_components() == 1


def test_split_vertices_get_ids_after_the_others(data):
    path = data / "surface" / "Wuson.off"
    points, faces = read_off(path)
    m = cgogn.load(str(path))
    extra = m.nb_cells("vertex") - len(points)
    assert extra > 0  # this file has non-manifold vertices, each split
    original = m.attribute("original_vertex", "vertex")
    p = m.positions
    for v in range(len(points), m.nb_cells("vertex")):
        assert np.array_equal(p[v], p[original[v]])


def test_many_position_reads_keep_compaction_possible(data):
    m = cgogn.load(str(data / "surface" / "hemisphere.off"))
    total = 0.0
    for _ in range(1000):
        total += float(m.positions[0, 0])  # each read makes a view that dies at once
    import gc

    gc.collect()
    m.compact()
    assert m.check_integrity()["ok"]
