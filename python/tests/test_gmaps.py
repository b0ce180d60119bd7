# SPDX-License-Identifier: MIT
"""The generalized maps from Python: non-orientable meshes kept whole, and
conversions that agree with the oriented maps."""
import numpy as np
import pytest

import cgogn


def sorted_faces(m):
    offsets, indices = m.faces_csr()
    pos = m.positions
    # each face as the sorted tuple of its vertex positions: ids may differ
    return sorted(
        tuple(sorted(tuple(np.round(pos[i], 9)) for i in indices[offsets[k] : offsets[k + 1]]))
        for k in range(len(offsets) - 1)
    )


@pytest.mark.parametrize(
    "name, v, e, f, chi, loops",
    [
        ("mobius_strip.off", 48, 72, 24, 0, 1),
        ("klein_bottle.off", 128, 256, 128, 0, 0),
        ("hemi_icosahedron.off", 6, 15, 10, 1, 0),
    ],
)
def test_non_orientable_surfaces_load_whole(data, name, v, e, f, chi, loops):
    g = cgogn.load(str(data / "surface" / name), gmap=True)
    assert isinstance(g, cgogn.GMap2)
    assert (g.nb_cells("vertex"), g.nb_cells("edge"), g.nb_cells("face")) == (v, e, f)
    assert g.euler_characteristic() == chi
    assert not g.is_orientable()
    assert g.check_integrity()["ok"]
    assert g.positions.shape == (g.id_bound("vertex"), 3)
    with pytest.raises(cgogn.Error, match="not orientable"):
        g.to_cmap()
    # the oriented map cuts it apart along its orientation conflicts
    c = cgogn.load(str(data / "surface" / name))
    assert c.nb_cells("vertex") > v


def test_conversions_keep_the_surface_and_its_attributes(data):
    c = cgogn.load(str(data / "surface" / "torus_quad.off"))
    c.add_attribute("height", "vertex")[:] = c.positions[:, 2]
    g = c.to_gmap()
    assert isinstance(g, cgogn.GMap2)
    assert g.is_orientable()
    assert g.nb_darts() == 2 * c.nb_darts()
    for kind in ("vertex", "edge", "face"):
        assert g.nb_cells(kind) == c.nb_cells(kind)
    assert np.array_equal(g.attribute("height", "vertex"), g.positions[:, 2])
    assert sorted_faces(g) == sorted_faces(c)
    back = g.to_cmap()
    assert isinstance(back, cgogn.CMap2)
    assert back.nb_darts() == c.nb_darts()
    assert back.euler_characteristic() == c.euler_characteristic() == 0
    assert back.check_integrity()["ok"]


def test_gmap2_from_arrays_keeps_a_twisted_strip():
    # a strip of 4 quads glued back with a half turn: the last face lists its
    # edge to the first one the other way round
    points = np.array(
        [[np.cos(t), np.sin(t), z] for t in np.linspace(0, 2 * np.pi, 4, endpoint=False) for z in (-1, 1)],
        dtype=float,
    )
    faces = np.array([[0, 2, 3, 1], [2, 4, 5, 3], [4, 6, 7, 5], [6, 1, 0, 7]])
    g = cgogn.GMap2.from_arrays(points, faces)
    assert (g.nb_cells("vertex"), g.nb_cells("edge"), g.nb_cells("face")) == (8, 12, 4)
    assert not g.is_orientable()
    assert g.euler_characteristic() == 0
    assert len(g.faces_csr()[0]) == 5
    c = cgogn.CMap2.from_arrays(points, faces)
    assert c.nb_cells("edge") > 12  # cut along the conflict


def test_gmap3_matches_the_3map(data):
    path = str(data / "volume" / "liver_hex_624.mesh")
    c = cgogn.load(path)
    g = cgogn.load(path, gmap=True)
    assert isinstance(g, cgogn.GMap3)
    assert g.nb_darts() == 2 * c.nb_darts()
    for kind in ("vertex", "edge", "face", "volume"):
        assert g.nb_cells(kind) == c.nb_cells(kind)
    assert g.euler_characteristic() == c.euler_characteristic()
    assert g.is_orientable()
    assert g.check_integrity()["ok"]
    assert sorted_faces(g) == sorted_faces(c)  # the boundary faces
    assert isinstance(g.to_cmap(), cgogn.CMap3)
    assert isinstance(c.to_gmap(), cgogn.GMap3)
    assert repr(g).startswith("<cgogn.GMap3 vertices=")


def test_gmap_save_and_load_round_trip(data, tmp_path):
    g = cgogn.load(str(data / "surface" / "klein_bottle.off"), gmap=True)
    out = tmp_path / "klein.obj"
    g.save(str(out))
    h = cgogn.load(str(out), gmap=True)
    assert (h.nb_cells("vertex"), h.nb_cells("edge"), h.nb_cells("face")) == (128, 256, 128)
    assert not h.is_orientable()
