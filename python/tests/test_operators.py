# SPDX-License-Identifier: MIT
"""Operators on cell ids, each followed by check_integrity."""
import numpy as np
import pytest

import cgogn


def ok(m):
    r = m.check_integrity()
    assert r["ok"], r["messages"]


def test_surface_operators(data):
    m = cgogn.load(str(data / "surface" / "hemisphere.off"))
    v0, e0, f0 = (m.nb_cells(k) for k in ("vertex", "edge", "face"))
    v = m.cut_edge(5)
    assert v == v0 and m.nb_cells("vertex") == v0 + 1 and m.nb_cells("edge") == e0 + 1
    ok(m)
    # cut the two faces of the new vertex back into triangles
    fo, fi = m.incidence("vertex", "face")
    for f in fi[fo[v] : fo[v + 1]]:
        vo, vi = m.incidence("face", "vertex")
        ids = m.cell_ids("face")
        row = int(np.nonzero(ids == f)[0][0])
        corners = vi[vo[row] : vo[row + 1]].tolist()
        if len(corners) == 4:
            k = corners.index(v)
            m.cut_face(int(f), v, corners[(k + 2) % 4])
            ok(m)
    assert m.nb_cells("face") == f0 + 2
    flips = [e for e in m.cell_ids("edge")[:50] if m.can_flip_edge(int(e))]
    assert flips
    m.flip_edge(int(flips[0]))
    ok(m)
    eo, ei = m.incidence("edge", "vertex")
    collapsible = [e for e in m.cell_ids("edge")[:50] if m.can_collapse_edge(int(e))]
    e = int(collapsible[0])
    ends = ei[eo[e] : eo[e + 1]].tolist()
    p = m.positions[ends[1]].copy()
    assert m.collapse_edge(e, keep=ends[1]) == ends[1]
    assert np.array_equal(m.positions[ends[1]], p)
    ok(m)
    assert not m.is_compact("vertex")
    with pytest.raises(IndexError):
        m.cut_edge(10**9)


def test_refused_operators_raise(data):
    m = cgogn.load(str(data / "surface" / "triangle.off"))
    for e in range(3):  # a lone triangle: no edge can go or turn
        assert not m.can_collapse_edge(e) and not m.can_flip_edge(e)
        with pytest.raises(ValueError, match="refused"):
            m.collapse_edge(e)
        with pytest.raises(ValueError, match="refused"):
            m.flip_edge(e)
    with pytest.raises(ValueError, match="corner"):
        m.cut_face(0, 0, 5)
    ok(m)


def test_split_tetra_and_volume_flips(data):
    m = cgogn.load(str(data / "volume" / "armadillo_tet_4k.mesh"))
    w0, v0 = m.nb_cells("volume"), m.nb_cells("vertex")
    v = m.split_tetra(0)
    assert m.nb_cells("volume") == w0 + 3 and v == v0
    ok(m)
    faces = [f for f in m.cell_ids("face")[:200] if m.can_flip_face(int(f))]
    assert faces
    m.flip_face(int(faces[0]))
    ok(m)
    assert m.nb_cells("volume") == w0 + 4
    edges = [e for e in m.cell_ids("edge")[:300] if m.can_collapse_edge(int(e))]
    assert edges
    m.collapse_edge(int(edges[0]))
    ok(m)
