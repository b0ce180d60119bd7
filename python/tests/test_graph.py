# SPDX-License-Identifier: MIT
"""Graphs from Python: building from arrays, counts and branches, the
operators and the ids they keep, positions and radii as arrays, .cg/.cgr
files and their errors."""
import numpy as np
import pytest

import cgogn


def path(n):
    points = np.column_stack([np.arange(n, dtype=float), np.zeros(n), np.zeros(n)])
    edges = np.column_stack([np.arange(n - 1), np.arange(1, n)])
    return cgogn.Graph.from_arrays(points, edges)


def test_path_counts_and_branch():
    g = path(10)
    assert (g.nb_vertices, g.nb_edges) == (10, 9)
    assert g.nb_connected_components() == 1
    assert g.cycle_rank() == 0
    (b,) = g.branches()
    assert not b["closed"]
    assert sorted([b["vertices"][0], b["vertices"][-1]]) == [0, 9]
    assert len(b["vertices"]) == 10
    assert g.check_integrity()["ok"]
    np.testing.assert_array_equal(g.edges(), np.column_stack([np.arange(9), np.arange(1, 10)]))


def test_cycle_loop_and_isolated_vertex():
    points = np.zeros((8, 3))
    edges = [(i, (i + 1) % 8) for i in range(8)]
    g = cgogn.Graph.from_arrays(points, np.array(edges))
    (b,) = g.branches()
    assert b["closed"] and len(b["vertices"]) == 9
    lone = g.add_vertex([1.0, 2.0, 3.0])
    assert g.degree(lone) == 0
    assert g.nb_edges == 8
    assert g.nb_connected_components() == 2
    g.connect(lone, lone)
    assert g.degree(lone) == 2
    assert g.cycle_rank() == 2
    np.testing.assert_array_equal(g.positions[lone], [1.0, 2.0, 3.0])


def test_operators_keep_ids():
    g = path(4)  # 0 - 1 - 2 - 3, edges 0, 1, 2
    m = g.cut_edge(1)  # 1 - m - 2
    assert m == 4 and g.nb_edges == 4 and g.degree(m) == 2
    assert g.collapse_edge(0) == 0  # 0 and 1 merged into 0
    assert g.nb_vertices == 4
    assert g.degree(0) == 1
    g.disconnect(2)
    assert g.nb_connected_components() == 2
    g.remove_vertex(3)
    assert g.nb_vertices == 3
    assert list(g.vertex_ids()) == [0, 2, 4]
    with pytest.raises(IndexError):
        g.degree(3)
    with pytest.raises(ValueError):
        g.merge_vertices(0, 0)
    assert g.merge_vertices(0, 2) == 0
    assert g.check_integrity()["ok"]


def test_files_round_trip(tmp_path):
    g = path(5)
    g.positions[:, 1] = np.linspace(0.1, 0.7, 5)
    g.set_radii(np.array([0.5, 0.25, 1.0 / 3.0, 2.0, 1e-9]))
    g.save(str(tmp_path / "p.cgr"))
    h = cgogn.Graph.load(str(tmp_path / "p.cgr"))
    np.testing.assert_array_equal(h.positions, g.positions)
    np.testing.assert_array_equal(h.radii(), g.radii())
    np.testing.assert_array_equal(h.edges(), g.edges())
    g.save(str(tmp_path / "p.cg"))
    assert cgogn.Graph.load(str(tmp_path / "p.cg")).radii() is None
    (tmp_path / "bad.cg").write_text("# D:3 NV:1 NE:1\nv 0 0 0\ne 0 4\n")
    with pytest.raises(cgogn.IOError, match=r"bad\.cg:3: vertex index 4 out of range"):
        cgogn.Graph.load(str(tmp_path / "bad.cg"))
    (tmp_path / "old.cg").write_text("# D:3 NV:2 NE:1\nv 0 0 0\nv 1 0 0\ne 1 2\n")
    assert cgogn.Graph.load(str(tmp_path / "old.cg"), index_base=1).nb_edges == 1


def test_bad_arrays():
    with pytest.raises(ValueError):
        cgogn.Graph.from_arrays(np.zeros((2, 3)), np.array([[0, 2]]))
    with pytest.raises(ValueError):
        cgogn.Graph.from_arrays(np.zeros((2, 2)), np.array([[0, 1]]))
