# SPDX-License-Identifier: MIT
"""Incidence graphs from Python: non-manifold files with their true counts,
faces as CSR, the operators and their refusals, exact round trips, the
conversion to and from CMap2."""
import numpy as np
import pytest

import cgogn
from conftest import read_off


def book():
    """Three triangles on the spine (0, 1)."""
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=float)
    offsets = np.array([0, 3, 6, 9])
    indices = np.array([0, 1, 2, 0, 1, 3, 0, 1, 4])
    return cgogn.IncidenceGraph.from_arrays(points, offsets, indices)


def test_book_counts_and_cut():
    ig = book()
    assert (ig.nb_vertices, ig.nb_edges, ig.nb_faces) == (5, 7, 3)
    spine = [e for e, (a, b) in zip(ig.edge_ids(), ig.edges()) if {a, b} == {0, 1}][0]
    assert ig.edge_degree(spine) == 3
    assert ig.nb_non_manifold_edges() == 1
    w = ig.cut_edge(spine)
    assert (ig.nb_vertices, ig.nb_edges, ig.nb_faces) == (6, 8, 3)
    assert ig.vertex_degree(w) == 2
    assert ig.check_integrity()["ok"]
    offsets, indices = ig.faces()
    assert list(np.diff(offsets)) == [4, 4, 4]


def test_refusals_change_nothing():
    ig = cgogn.IncidenceGraph()
    v = [ig.add_vertex([float(i), 0.0, 0.0]) for i in range(4)]
    path = [ig.add_edge(v[0], v[1]), ig.add_edge(v[1], v[2]), ig.add_edge(v[2], v[3])]
    with pytest.raises(ValueError):
        ig.add_face(np.array(path))
    with pytest.raises(ValueError):
        ig.add_edge(v[0], v[0])
    with pytest.raises(IndexError):
        ig.add_edge(v[0], 99)
    assert (ig.nb_vertices, ig.nb_edges, ig.nb_faces) == (4, 3, 0)
    closing = ig.add_edge(v[3], v[0])
    f = ig.add_face(np.array([path[2], closing, path[0], path[1]]))
    assert ig.nb_faces == 1
    e = ig.cut_face(f, v[0], v[2])
    assert ig.edge_degree(e) == 2 and ig.nb_faces == 2
    assert ig.check_integrity()["ok"]


def test_non_manifold_file_round_trip(data, tmp_path):
    src = data / "surface" / "icositetrachoron_2skeleton.off"
    ig = cgogn.IncidenceGraph.load(str(src))
    assert (ig.nb_vertices, ig.nb_edges, ig.nb_faces) == (24, 96, 96)
    assert ig.euler_characteristic() == 24
    assert ig.nb_non_manifold_edges() == 96
    points, faces = read_off(src)
    np.testing.assert_array_equal(ig.positions, np.array(points))
    offsets, indices = ig.faces()
    assert [list(indices[offsets[k] : offsets[k + 1]]) for k in range(len(faces))] == faces
    for name in ["copy.off", "copy.ig"]:
        ig.save(str(tmp_path / name))
        back = cgogn.IncidenceGraph.load(str(tmp_path / name))
        np.testing.assert_array_equal(back.positions, ig.positions)
        b_offsets, b_indices = back.faces()
        np.testing.assert_array_equal(b_offsets, offsets)
        np.testing.assert_array_equal(b_indices, indices)
    with pytest.raises(cgogn.IOError):
        (tmp_path / "bad.ig").write_text("IG 1 0 0\nv 0 0\n")
        cgogn.IncidenceGraph.load(str(tmp_path / "bad.ig"))


def test_attributes_as_arrays():
    ig = book()
    tag = ig.add_attribute("tag", "face", "int32")
    assert tag.shape == (3,)
    tag[:] = [7, 8, 9]
    heat = ig.add_attribute("heat", "vertex")
    heat[:] = np.arange(5)
    ig.add_attribute("w", "edge", "float64", 3)
    assert ("tag", "int32", 1) in ig.attributes("face")
    w = ig.cut_edge([e for e, (a, b) in zip(ig.edge_ids(), ig.edges()) if {a, b} == {0, 1}][0])
    np.testing.assert_array_equal(ig.attribute("tag", "face"), [7, 8, 9])  # the faces keep their ids
    assert ig.attribute("heat", "vertex")[w] == 0.0  # a new vertex: the default value
    with pytest.raises(ValueError):
        ig.add_attribute("v", "volume")
    with pytest.raises(KeyError):
        ig.attribute("missing", "vertex")


def test_cmap2_round_trip(data):
    m = cgogn.load(str(data / "surface" / "hemisphere.off"))
    counts = tuple(m.nb_cells(k) for k in ("vertex", "edge", "face"))
    ig = cgogn.IncidenceGraph.from_cmap2(m)
    assert (ig.nb_vertices, ig.nb_edges, ig.nb_faces) == counts
    assert ig.nb_non_manifold_vertices() == 0
    back = ig.to_cmap2()
    assert tuple(back.nb_cells(k) for k in ("vertex", "edge", "face")) == counts
    np.testing.assert_array_equal(np.sort(back.positions, axis=0), np.sort(m.positions, axis=0))
