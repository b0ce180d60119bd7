# SPDX-License-Identifier: MIT
"""Attributes of every dtype, by name and kind, as arrays indexed by cell id."""
import numpy as np
import pytest

import cgogn

DTYPES = [("float64", 1, np.float64), ("float32", 1, np.float32), ("int32", 1, np.int32), ("int64", 1, np.int64),
          ("uint32", 1, np.uint32), ("bool", 1, np.bool_), ("float64", 2, np.float64), ("float64", 3, np.float64),
          ("float64", 4, np.float64)]


@pytest.mark.parametrize("kind", ["vertex", "edge", "face"])
@pytest.mark.parametrize("dtype,components,np_type", DTYPES)
def test_every_dtype_on_every_kind(data, kind, dtype, components, np_type):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    a = m.add_attribute("a", kind, dtype, components)
    n = m.id_bound(kind)
    assert a.dtype == np_type and a.shape == ((n,) if components == 1 else (n, components))
    assert not a.any()  # defaults: zero, False
    values = (np.arange(a.size) % 7).reshape(a.shape).astype(np_type)
    a[...] = values
    assert np.array_equal(m.attribute("a", kind), values)  # the same memory
    m.set_attribute("a", kind, values[::-1].copy())
    assert np.array_equal(a, values[::-1])
    assert ("a", dtype, components) in m.attributes(kind)
    m.remove_attribute("a", kind)
    with pytest.raises(KeyError):
        m.attribute("a", kind)
    assert np.array_equal(a, values[::-1])  # the array keeps its values


def test_volume_attributes(data):
    m = cgogn.load(str(data / "volume" / "liver_hex_624.mesh"))
    w = m.add_attribute("w", "volume", "int64")
    assert w.shape == (624,)
    w[:] = np.arange(624)
    assert m.attribute("w", "volume")[623] == 623


def test_attribute_errors(data):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    m.add_attribute("x", "vertex")
    with pytest.raises(ValueError, match="exists"):
        m.add_attribute("x", "vertex")
    with pytest.raises(ValueError, match="unsupported"):
        m.add_attribute("y", "vertex", "complex128")
    with pytest.raises(ValueError, match="unknown cell kind"):
        m.add_attribute("y", "wedge")
    with pytest.raises(ValueError, match="library"):
        m.add_attribute("__y", "vertex")
    with pytest.raises(ValueError, match="shape"):
        m.set_attribute("x", "vertex", np.zeros(3))
    with pytest.raises(ValueError, match="position"):
        m.remove_attribute("position", "vertex")


def test_new_cells_follow_the_rule_and_survivors_keep_their_values(data):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    m.triangulate()
    t = m.add_attribute("t", "vertex", "int32")
    t[:] = np.arange(len(t)) + 1
    v = m.cut_edge(0)
    t = m.attribute("t", "vertex")
    assert t[v] in t[:v]  # copy: the value of an end of the edge
    assert np.array_equal(t[:v], np.arange(v) + 1)
    m.set_attribute_rule("t", "vertex", "none")
    w = m.cut_edge(0)
    assert m.attribute("t", "vertex")[w] == 0  # none: the default value


def test_attributes_follow_edits(data):
    """Rules: a face region copies to the faces cut from it, a colour
    interpolates at new vertices; record_origins names each face's input face."""
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    m.triangulate()
    region = m.add_attribute("region", "face", "int32")
    region[:] = np.arange(region.size) % 4 + 1
    colour = m.add_attribute("colour", "vertex", "float64", 3)
    pos = m.attribute("position", "vertex")
    colour[:] = (pos - pos.min(axis=0)) / np.ptp(pos, axis=0)
    lo, hi = colour.min(axis=0), colour.max(axis=0)
    flat = m.add_attribute("flat", "vertex", "float64")
    flat[:] = 5.0
    assert m.attribute_rule("region", "face") == "copy"
    assert m.attribute_rule("colour", "vertex") == "interpolate"
    m.set_attribute_rule("flat", "vertex", "none")
    assert m.attribute_rule("flat", "vertex") == "none"
    input_region = m.attribute("region", "face").copy()
    origin = m.record_origins("face")
    assert np.array_equal(origin, np.arange(origin.size, dtype=np.uint32))
    n = m.nb_cells("vertex")
    m.subdivide("loop", 1)
    assert m.check_integrity()["ok"]
    colour = m.attribute("colour", "vertex")
    new = np.arange(n, m.id_bound("vertex"))
    assert (colour[new] >= lo - 1e-12).all() and (colour[new] <= hi + 1e-12).all()
    assert (m.attribute("flat", "vertex")[new] == 0.0).all()
    region, origin = m.attribute("region", "face"), m.attribute("origin", "face")
    assert np.array_equal(region, input_region[origin])
    with pytest.raises(ValueError):
        m.set_attribute_rule("region", "face", "average")
    with pytest.raises(ValueError):
        m.record_origins("face")  # the name is taken


def test_corner_attributes(data):
    """Per-corner data: the OBJ's texture coordinates as a 'corner' attribute,
    in the order of corners_csr(); seams stay through a subdivision."""
    path = data / "surface" / "spot_control_mesh.obj"
    vt, faces = [], []
    for line in path.read_text().splitlines():
        if line.startswith("vt "):
            vt.append([float(x) for x in line.split()[1:3]])
        elif line.startswith("f "):
            faces.append([int(c.split("/")[1]) - 1 for c in line.split()[1:]])
    vt = np.array(vt)
    m = cgogn.load(str(path))
    assert ("tex_coord", "float64", 2) in m.attributes("corner")
    uv = m.attribute("tex_coord", "corner")
    offsets, corners = m.corners_csr()
    f_offsets, f_vertices = m.faces_csr()
    assert np.array_equal(offsets, f_offsets) and len(faces) == len(offsets) - 1
    for k, face in enumerate(faces):  # the file's faces in order, each from its first corner
        assert np.allclose(uv[corners[offsets[k]:offsets[k + 1]]], vt[face])
    assert m.nb_cells("corner") == len(corners)
    with pytest.raises(ValueError):
        m.incidence("corner", "vertex")
    lo, hi = vt.min(axis=0), vt.max(axis=0)
    m.subdivide("catmull-clark", 1)
    uv = m.attribute("tex_coord", "corner")
    offsets, corners = m.corners_csr()
    _, vertices = m.faces_csr()
    assert (uv[corners] >= lo - 1e-12).all() and (uv[corners] <= hi + 1e-12).all()
    # a seam: some vertex has corners of different texture coordinates
    per_vertex = {}
    for v, c in zip(vertices, corners):
        per_vertex.setdefault(v, set()).add(tuple(np.round(uv[c], 12)))
    assert any(len(s) > 1 for s in per_vertex.values())
