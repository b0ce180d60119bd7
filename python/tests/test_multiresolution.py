# SPDX-License-Identifier: MIT
"""Multiresolution surfaces from Python: levels and their counts, positions
and faces of a level as arrays, extraction, adaptive refinement, analysis
and synthesis."""
import numpy as np
import pytest

import cgogn


def cube():
    points = np.array(
        [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float
    )
    quads = np.array([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])
    return cgogn.CMap2.from_arrays(points, quads)


def test_levels_counts_and_arrays():
    m = cgogn.MRMap2(cube())
    assert m.max_level == 0 and m.current_level == 0
    for _ in range(3):
        m.add_level("quadrangular")
    assert m.max_level == 3 and m.current_level == 3
    for k in range(4):
        p = 4**k
        assert m.counts(k) == (6 * p + 2, 12 * p, 6 * p)
        assert m.positions(k).shape == (6 * p + 2, 3)
        faces = m.faces(k)
        assert faces.shape == (6 * p, 4)
        assert faces.max() == 6 * p + 1
    assert sum(m.nb_darts_at_level(k) for k in range(4)) == 24 * 64
    # level 0 keeps the cube's corners; level 1's midpoints are midpoints
    assert sorted(map(tuple, m.positions(0))) == sorted(map(tuple, cube().positions[:8]))
    assert m.check_integrity()["ok"]
    m.current_level = 1
    with pytest.raises(IndexError):
        m.current_level = 4
    with pytest.raises(ValueError):
        m.add_level("hexahedral")
    m.remove_finest_level()
    assert m.max_level == 2


def test_extract_level_and_positions_per_level():
    m = cgogn.MRMap2(cube())
    m.add_level("quadrangular")
    m.synthesis("catmull_clark")
    flat = m.extract_level(1)
    assert (flat.nb_cells("vertex"), flat.nb_cells("edge"), flat.nb_cells("face")) == m.counts(1)
    # a level's positions are its own: moving level 1 leaves level 0
    before0 = m.positions(0)
    moved = m.positions(1) + 1.0
    m.set_positions(1, moved)
    np.testing.assert_array_equal(m.positions(1), moved)
    np.testing.assert_array_equal(m.positions(0), before0)
    with pytest.raises(ValueError):
        m.set_positions(1, np.zeros((3, 3)))


def test_analysis_then_synthesis_gives_the_positions_back():
    m = cgogn.MRMap2(cube())
    for _ in range(2):
        m.add_level("quadrangular")
    m.synthesis("catmull_clark")
    fine = m.positions(2) + 0.01 * np.sin(np.arange(m.positions(2).size)).reshape(-1, 3)
    m.set_positions(2, fine)
    m.analysis("catmull_clark")
    assert np.abs(m.details(2)).max() > 1e-4
    m.synthesis("catmull_clark")
    np.testing.assert_allclose(m.positions(2), fine, atol=1e-12)


def test_adaptive_refinement_by_rows():
    m = cgogn.MRMap2(cube())
    m.subdivide_faces(0, [0])
    assert m.max_level == 1
    levels = m.face_levels(1)
    assert sorted(levels.tolist()) == [0] * 5 + [1] * 4
    offsets, indices = m.faces_csr(1)
    assert len(offsets) == 10 and offsets[-1] == len(indices)
    with pytest.raises(ValueError):
        m.faces(1)  # quads and the pentagons around the refined face
    assert m.check_integrity()["ok"]


def test_hierarchies_round_trip_through_files_and_pickle(tmp_path):
    import copy
    import pickle

    m = cgogn.MRMap2(cube())
    m.add_level("quadrangular")
    m.add_level("quadrangular")
    m.synthesis("catmull_clark")
    m.set_positions(1, m.positions(1) * 2.0)  # level 1 has positions of its own
    m.subdivide_faces(2, [0, 5])  # adaptive: a level 3 in places
    m.current_level = 1
    path = str(tmp_path / "h.cgmap")
    m.save(path)
    for c in (cgogn.load(path), pickle.loads(pickle.dumps(m)), copy.deepcopy(m), cgogn.map_from_bytes(m.to_bytes())):
        assert isinstance(c, cgogn.MRMap2)
        assert c.max_level == m.max_level == 3
        assert c.current_level == 1
        for k in range(m.max_level + 1):
            assert c.counts(k) == m.counts(k)
            assert c.nb_darts_at_level(k) == m.nb_darts_at_level(k)
            np.testing.assert_array_equal(c.positions(k), m.positions(k))
            np.testing.assert_array_equal(c.faces_csr(k)[0], m.faces_csr(k)[0])
            np.testing.assert_array_equal(c.faces_csr(k)[1], m.faces_csr(k)[1])
            np.testing.assert_array_equal(c.face_levels(k), m.face_levels(k))
        assert c.check_integrity()["ok"]
        assert c.to_bytes() == m.to_bytes()
    with pytest.raises(ValueError):
        m.save(str(tmp_path / "h.off"))
    b = m.to_bytes()
    with pytest.raises(cgogn.IOError):
        cgogn.map_from_bytes(b[: len(b) // 2])
