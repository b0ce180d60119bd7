# SPDX-License-Identifier: MIT
"""Whole maps in .cgmap files and bytes: pickle, copy.deepcopy, save and load."""
import copy
import pickle

import numpy as np
import pytest

import cgogn


def surface_with_attributes(data):
    m = cgogn.load(str(data / "surface" / "elephant-with-holes.off"))
    region = m.add_attribute("region", "face", dtype="int32")
    region[:] = np.arange(m.id_bound("face"), dtype=np.int32) % 5
    colour = m.add_attribute("colour", "vertex", components=3)
    colour[:] = np.random.default_rng(3).random((m.id_bound("vertex"), 3))
    for e in (0, 10, 20):  # edits leave free ids, which the copy keeps
        m.collapse_edge(e)
    return m


def expect_same(a, b):
    assert type(a) is type(b)
    assert a.to_bytes() == b.to_bytes()
    for k in ("vertex", "edge", "face"):
        assert a.nb_cells(k) == b.nb_cells(k)
        assert np.array_equal(a.cell_ids(k), b.cell_ids(k))
    assert np.array_equal(a.positions, b.positions)
    assert b.check_integrity()["ok"]


def test_pickle_and_deepcopy_keep_the_whole_surface(data):
    m = surface_with_attributes(data)
    for c in (pickle.loads(pickle.dumps(m)), copy.deepcopy(m), cgogn.map_from_bytes(m.to_bytes())):
        expect_same(m, c)
        assert np.array_equal(c.attribute("region", "face"), m.attribute("region", "face"))
        assert c.attribute("region", "face").dtype == np.int32
        assert np.array_equal(c.attribute("colour", "vertex"), m.attribute("colour", "vertex"))
    # the copy is independent of the original
    c = copy.deepcopy(m)
    c.positions[:] = 0
    assert np.abs(m.positions).max() > 0


def test_every_map_class_pickles(data):
    volume = cgogn.load(str(data / "volume" / "liver_hex_624.mesh"))
    klein = cgogn.load(str(data / "surface" / "klein_bottle.off"), gmap=True)
    for m in (volume, volume.to_gmap(), klein, cgogn.cube_grid(3, 2), cgogn.cube_grid(2, 2, gmap=True)):
        c = pickle.loads(pickle.dumps(m))
        assert type(c) is type(m)
        assert c.to_bytes() == m.to_bytes()
        assert c.nb_darts() == m.nb_darts()
    g = cgogn.Graph.from_arrays(np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0]], float), np.array([[0, 1], [1, 2]]))
    h = copy.deepcopy(g)
    assert isinstance(h, cgogn.Graph)
    assert (h.nb_vertices, h.nb_edges) == (3, 2)
    assert np.array_equal(h.positions, g.positions)


def test_save_and_load_cgmap_files(data, tmp_path):
    m = surface_with_attributes(data)
    m.save(str(tmp_path / "m.cgmap"))
    expect_same(m, cgogn.load(str(tmp_path / "m.cgmap")))
    g = cgogn.Graph.from_arrays(np.zeros((2, 3)), np.array([[0, 1]]))
    g.save(str(tmp_path / "g.cgmap"))
    assert isinstance(cgogn.load(str(tmp_path / "g.cgmap")), cgogn.Graph)
    n = cgogn.cube_grid(3, 2)
    assert n.save(str(tmp_path / "n.cgmap")) == []
    back = cgogn.load(str(tmp_path / "n.cgmap"))
    assert type(back) is type(n)
    assert back.f_vector() == n.f_vector()


def test_bad_bytes_raise_ioerror(data, tmp_path):
    m = surface_with_attributes(data)
    b = m.to_bytes()
    with pytest.raises(cgogn.IOError, match="byte"):
        cgogn.map_from_bytes(b[: len(b) // 2])
    with pytest.raises(cgogn.IOError, match="not a .cgmap file"):
        cgogn.map_from_bytes(b"hello")
    (tmp_path / "x.cgmap").write_bytes(b[:100])
    with pytest.raises(cgogn.IOError, match="x.cgmap"):
        cgogn.load(str(tmp_path / "x.cgmap"))
