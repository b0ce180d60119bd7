# SPDX-License-Identifier: MIT
"""Multiresolution volume meshes from Python: hexahedral and
tetrahedral-octahedral levels and their counts, positions and cells of a
level as arrays, extraction, adaptive refinement, files."""
import itertools

import numpy as np
import pytest

import cgogn


def unit_cube():
    points = np.array(
        [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float
    )
    return cgogn.CMap3.from_arrays(points, np.array([[0, 1, 2, 3, 4, 5, 6, 7]]))


def grid_points(n):
    return sorted(itertools.product([i / n for i in range(n + 1)], repeat=3))


def test_levels_counts_positions_and_hexahedra():
    m = cgogn.MRMap3(unit_cube())
    assert m.max_level == 0 and m.current_level == 0
    m.add_level()
    m.add_level("hexahedral")
    assert m.max_level == 2 and m.current_level == 2
    for k in range(3):
        n = 2**k
        assert m.counts(k) == [(n + 1) ** 3, 3 * n * (n + 1) ** 2, 3 * n * n * (n + 1), n**3]
        # the positions of a level are the n x n x n grid: each new vertex is
        # the centroid of the edge, face or hexahedron it is the middle of
        p = m.positions(k)
        assert sorted(map(tuple, p)) == grid_points(n)
        hexes = m.hexahedra(k)
        assert hexes.shape == (n**3, 8)
        for row in hexes:
            corners = p[row]
            assert len(set(map(tuple, corners))) == 8
            assert np.allclose(corners.max(axis=0) - corners.min(axis=0), 1.0 / n)
            # column j + 4 is joined to column j by an edge of length 1 / n
            assert np.allclose(np.linalg.norm(corners[4:] - corners[:4], axis=1), 1.0 / n)
    assert m.check_integrity()["ok"]


def test_levels_keep_their_own_positions_and_extract():
    m = cgogn.MRMap3(unit_cube())
    m.add_level()
    before = m.positions(0).copy()
    moved = m.positions(1) * 2.0
    m.set_positions(1, moved)
    assert np.array_equal(m.positions(1), moved)
    assert np.array_equal(m.positions(0), before)
    flat = m.extract_level(1)
    assert sorted(map(tuple, flat.positions)) == sorted(map(tuple, moved))
    assert flat.check_integrity()["ok"]
    m.remove_finest_level()
    assert m.max_level == 0
    assert np.array_equal(m.positions(0), before)
    with pytest.raises(ValueError):
        m.set_positions(0, np.zeros((3, 3)))


def test_errors():
    m = cgogn.MRMap3(unit_cube())
    with pytest.raises(ValueError):
        m.add_level("tetra_octa")
    with pytest.raises(IndexError):
        m.current_level = 1
    with pytest.raises(IndexError):
        m.positions(1)
    tet = cgogn.CMap3.from_arrays(np.eye(4, 3), np.array([[0, 1, 2, 3]]))
    t = cgogn.MRMap3(tet)
    with pytest.raises(ValueError):
        t.add_level()
    assert t.max_level == 0


def test_adaptive_refinement_and_coarsening():
    n = 2
    points = np.array(list(itertools.product(range(n + 1), repeat=3)), dtype=float)[:, ::-1]
    index = {tuple(p): i for i, p in enumerate(points)}
    hexes = []
    for x, y, z in itertools.product(range(n), repeat=3):
        corner = [(x, y, z), (x + 1, y, z), (x + 1, y + 1, z), (x, y + 1, z)]
        hexes.append([index[c] for c in corner] + [index[(a, b, c + 1)] for a, b, c in corner])
    m = cgogn.MRMap3(cgogn.CMap3.from_arrays(points, np.array(hexes)))
    # the hexahedron at the origin, then its child at the grid's centre
    origin = [i for i, row in enumerate(m.hexahedra(0)) if m.positions(0)[row].min(axis=0).sum() == 0]
    m.subdivide_volumes(0, origin)
    assert m.max_level == 1 and m.current_level == 0
    levels = m.volume_levels(1)
    assert sorted(levels.tolist()) == [0] * 7 + [1] * 8
    child = [
        i
        for i, row in enumerate(m.hexahedra(1))
        if levels[i] == 1 and m.positions(1)[row].min(axis=0).sum() == 1.5
    ]
    m.subdivide_volumes(1, child)
    assert m.max_level == 2 and m.check_integrity()["ok"]
    # balance: the 6 hexahedra sharing a face or an edge with that child were
    # cut first, not the one sharing only the centre
    assert sorted(m.volume_levels(2).tolist()) == [0] + [1] * 55 + [2] * 8
    p = m.positions(2)
    for k, row in zip(m.volume_levels(2), m.hexahedra(2)):
        # every hexahedron, coarse or fine, gives its own 8 corners: a box
        assert np.allclose(p[row].max(axis=0) - p[row].min(axis=0), 1.0 / 2**k)
        assert np.allclose(np.linalg.norm(p[row][4:] - p[row][:4], axis=1), 1.0 / 2**k)
    with pytest.raises(IndexError):
        m.subdivide_volumes(0, [100])
    # coarsening everything, finest first, gives the grid back
    for k in (1, 0):
        done = m.coarsen_volumes(k, range(len(m.hexahedra(k))))
        assert done > 0
    assert m.max_level == 0 and m.counts(0) == [27, 54, 36, 8]
    assert m.check_integrity()["ok"]


def test_files_and_pickling(tmp_path):
    import pickle

    m = cgogn.MRMap3(unit_cube())
    m.add_level()
    m.subdivide_volumes(1, [0])
    m.current_level = 1
    path = str(tmp_path / "h.cgmap")
    m.save(path)
    for r in (cgogn.load(path), pickle.loads(pickle.dumps(m)), cgogn.map_from_bytes(m.to_bytes())):
        assert isinstance(r, cgogn.MRMap3)
        assert r.max_level == 2 and r.current_level == 1
        for k in range(3):
            assert r.counts(k) == m.counts(k)
            assert np.array_equal(r.positions(k), m.positions(k))
            assert np.array_equal(r.hexahedra(k), m.hexahedra(k))
        assert r.to_bytes() == m.to_bytes()
    with pytest.raises(ValueError):
        m.save(str(tmp_path / "h.off"))


def test_tetra_octa_levels():
    # a regular tetrahedron: every level is made of regular tetrahedra and
    # octahedra with edges half as long as the level before
    points = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float)
    m = cgogn.MRMap3(cgogn.CMap3.from_arrays(points, np.array([[0, 1, 2, 3]])))
    m.add_level("tetra-octa")
    m.add_level("tetra-octa")
    assert m.check_integrity()["ok"]
    assert [m.counts(k) for k in range(3)] == [[4, 6, 4, 1], [10, 24, 20, 5], [35, 120, 120, 34]]
    for k, (nb_tets, nb_octas) in enumerate([(1, 0), (4, 1), (24, 10)]):
        p = m.positions(k)
        edge = 2 * np.sqrt(2) / 2**k
        tets, octas = m.tetrahedra(k), m.octahedra(k)
        assert tets.shape == (nb_tets, 4) and octas.shape == (nb_octas, 6)
        for row in tets:
            a, b, c, d = p[row]
            assert np.allclose([np.linalg.norm(x - y) for x, y in itertools.combinations(p[row], 2)], edge)
            assert np.linalg.det(np.array([b - a, c - a, d - a])) > 0
        for row in octas:
            q = p[row]
            # opposite corners a diagonal apart, the others an edge apart
            for i, j in itertools.combinations(range(6), 2):
                expected = edge * np.sqrt(2) if j == i + 3 else edge
                assert np.isclose(np.linalg.norm(q[i] - q[j]), expected)
            outward = np.cross(q[1] - q[0], q[2] - q[0])
            assert np.dot(outward, q[:3].mean(axis=0) - q.mean(axis=0)) > 0
    with pytest.raises(ValueError):
        m.hexahedra(1)
    cube = cgogn.MRMap3(unit_cube())
    with pytest.raises(ValueError):
        cube.add_level("tetra-octa")
    assert cube.max_level == 0 and cube.check_integrity()["ok"]
