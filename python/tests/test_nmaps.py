# SPDX-License-Identifier: MIT
"""The maps of any dimension from Python: the generated shapes against their
closed forms (the values of tests/core/test_nmap.cpp), incidence relations,
attributes, .nmap files and their errors, on CMapN and GMapN."""
import math
import sys

import numpy as np
import pytest

import cgogn

DIMS = [1, 2, 3, 4]
MODELS = [False, True]  # gmap


def simplex_f(d):
    return [math.comb(d + 1, k + 1) for k in range(d + 1)]


def grid_f(d, n):
    return [math.comb(d, k) * n**k * (n + 1) ** (d - k) for k in range(d + 1)]


def model_name(gmap):
    return "GMapN" if gmap else "CMapN"


# ---- classes and generators


@pytest.mark.parametrize("gmap", MODELS)
@pytest.mark.parametrize("d", DIMS)
def test_factories_make_an_empty_map_of_each_dimension(d, gmap):
    m = (cgogn.GMapN if gmap else cgogn.CMapN)(d)
    assert type(m).__name__ == f"{model_name(gmap)}{d}"
    assert isinstance(m, cgogn.NMap)
    assert m.dimension == d == type(m).dimension
    assert m.nb_darts() == 0
    assert m.f_vector() == [0] * (d + 1)
    assert m.euler_characteristic() == 0
    assert m.positions is None
    assert m.check_integrity()["ok"]
    assert len(m.cells(d)) == 0


@pytest.mark.parametrize("factory", [cgogn.CMapN, cgogn.GMapN])
@pytest.mark.parametrize("d", [0, 5, 7, -1])
def test_unsupported_dimensions_raise_value_error(factory, d):
    with pytest.raises(ValueError, match="1 to 4"):
        factory(d)
    with pytest.raises(ValueError, match="1 to 4"):
        cgogn.simplex(d)
    with pytest.raises(TypeError):
        factory(2.5)


@pytest.mark.parametrize("gmap", MODELS)
@pytest.mark.parametrize("d", DIMS)
def test_simplex(d, gmap):
    m = cgogn.simplex(d, gmap=gmap)
    assert isinstance(m, getattr(cgogn, f"{model_name(gmap)}{d}"))
    assert m.f_vector() == simplex_f(d)
    assert m.euler_characteristic() == 1
    assert m.nb_connected_components() == 1
    # (D + 1)! / 2 darts inside a CMapN's simplex, as many outside; twice that in a GMapN
    assert m.nb_darts() == (2 if gmap else 1) * math.factorial(d + 1)
    assert m.check_integrity() == {"ok": True, "nb_errors": 0, "messages": []}
    p = m.positions
    assert p.shape == (d + 1, d) and p.dtype == np.float64
    # the origin and the unit vectors
    assert sorted(map(tuple, p)) == sorted(map(tuple, np.vstack([np.zeros(d), np.eye(d)])))


@pytest.mark.parametrize("gmap", MODELS)
@pytest.mark.parametrize("d", DIMS)
def test_cube_and_grids(d, gmap):
    c = cgogn.cube(d, gmap=gmap)
    assert c.f_vector() == [math.comb(d, k) * 2 ** (d - k) for k in range(d + 1)] == grid_f(d, 1)
    n = {1: 4, 2: 4, 3: 3, 4: 2}[d]
    g = cgogn.cube_grid(d, n, gmap=gmap)
    assert g.f_vector() == grid_f(d, n)
    assert g.euler_characteristic() == 1
    assert g.check_integrity()["ok"]
    assert g.positions.shape == (grid_f(d, n)[0], d)
    assert np.allclose(np.sort(np.unique(g.positions)), np.linspace(0, 1, n + 1))
    f = cgogn.freudenthal_grid(d, n, gmap=gmap)
    fv = f.f_vector()
    assert fv[0] == (n + 1) ** d
    assert fv[-1] == n**d * math.factorial(d)
    assert f.euler_characteristic() == 1
    assert f.check_integrity()["ok"]
    # every cell of a triangulation is a simplex: its k-cells have k + 1 vertices
    for k in range(1, d + 1):
        # (but for the edges of a CMapN1, single darts: the incidence gives their first vertex)
        expected = 1 if (d, k, gmap) == (1, 1, False) else k + 1
        assert np.all(np.diff(incidence_csr(f, k, 0)[0]) == expected)


def test_the_4d_grid_of_the_docs():
    m = cgogn.cube_grid(4, 3)
    assert m.f_vector() == [256, 768, 864, 432, 81]
    b = m.boundary()
    assert isinstance(b, cgogn.CMapN3)
    assert b.nb_cells(3) == 216
    assert b.euler_characteristic() == 0


@pytest.mark.parametrize("gmap", MODELS)
@pytest.mark.parametrize("d", [2, 3, 4])
def test_boundaries_are_spheres(d, gmap):
    m = cgogn.cube_grid(d, 2, gmap=gmap)
    b = m.boundary()
    assert type(b).__name__ == f"{model_name(gmap)}{d - 1}"
    assert b.euler_characteristic() == (2 if d % 2 == 1 else 0)  # 1 + (-1)^(D - 1)
    assert b.f_vector() == [a - i for a, i in zip(grid_f(d, 2), [math.comb(d, k) * 2**k for k in range(d + 1)])][:d]
    assert b.check_integrity()["ok"]
    assert b.positions.shape == (b.id_bound(0), d)  # vertex attributes carried
    s = cgogn.simplex(d, gmap=gmap).boundary()
    assert s.f_vector() == simplex_f(d)[:-1]
    with pytest.raises(ValueError):
        cgogn.simplex(1, gmap=gmap).boundary()


@pytest.mark.parametrize("d", DIMS)
def test_conversions_between_the_models(d):
    c = cgogn.cube_grid(d, 2)
    c.add_attribute("w", d, "int32")[:] = np.arange(c.id_bound(d))
    g = c.to_gmap()
    assert isinstance(g, getattr(cgogn, f"GMapN{d}"))
    assert g.is_orientable()
    assert g.nb_darts() == 2 * c.nb_darts()
    assert g.f_vector() == c.f_vector()
    assert sorted(g.attribute("w", d)) == list(range(c.id_bound(d)))
    back = g.to_cmap()
    assert isinstance(back, type(c))
    assert back.f_vector() == c.f_vector() and back.nb_darts() == c.nb_darts()


def test_builders_of_complexes():
    # two triangles sharing an edge
    m = cgogn.simplicial_complex([[0, 1, 2], [1, 3, 2]], points=[[0, 0], [1, 0], [0, 1], [1, 1]])
    assert isinstance(m, cgogn.CMapN2)
    assert m.f_vector() == [4, 5, 2] and m.euler_characteristic() == 1
    assert sorted(map(tuple, m.positions)) == [(0, 0), (0, 1), (1, 0), (1, 1)]
    # a tetrahedron's boundary, without points: no positions
    s = cgogn.simplicial_complex([[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]])
    assert s.f_vector() == [4, 6, 4] and s.euler_characteristic() == 2
    assert s.positions is None
    s.positions = np.eye(4, 2)  # creates the attribute
    assert s.positions.shape == (4, 2)
    # two squares side by side: vertex k of a square at the bits of k
    q = cgogn.cubical_complex([[0, 1, 3, 4], [1, 2, 4, 5]], gmap=True)
    assert isinstance(q, cgogn.GMapN2)
    assert q.f_vector() == [6, 7, 2]
    # the Moebius strip of 5 triangles (one boundary cycle 0 2 4 1 3): a G-map
    # keeps it, an oriented map cannot
    strip = [[i, (i + 1) % 5, (i + 2) % 5] for i in range(5)]
    g = cgogn.simplicial_complex(strip, gmap=True)
    assert g.f_vector() == [5, 10, 5] and g.euler_characteristic() == 0
    assert not g.is_orientable()
    with pytest.raises(cgogn.Error, match="orient"):
        cgogn.simplicial_complex(strip)
    with pytest.raises(cgogn.Error, match="not orientable"):
        g.to_cmap()
    with pytest.raises(cgogn.Error):  # an id repeated in a cell
        cgogn.simplicial_complex([[0, 1, 1]])
    with pytest.raises(ValueError):
        cgogn.CMapN3.simplicial_complex([[0, 1, 2]])
    with pytest.raises(ValueError):
        cgogn.simplicial_complex([[0, 1, 2]], points=[[0, 0], [1, 0]])  # point 2 missing
    with pytest.raises(cgogn.Error):
        cgogn.cube_grid(2, 0)


# ---- incidence


def incidence_csr(m, i, j):
    indptr, indices, shape = m._incidence(i, j)
    return indptr, indices, shape


def rows(m, i, j):
    indptr, indices, _ = incidence_csr(m, i, j)
    return [set(indices[indptr[r] : indptr[r + 1]].tolist()) for r in range(len(indptr) - 1)]


@pytest.mark.parametrize("gmap", MODELS)
def test_incidence_of_the_4_simplex(gmap):
    sp = pytest.importorskip("scipy.sparse")
    d = 4
    m = cgogn.simplex(d, gmap=gmap)
    f = m.f_vector()
    vertices = {k: [frozenset(r) for r in rows(m, k, 0)] for k in range(d + 1)}
    for i in range(d + 1):
        # the i-cells of a simplex are the subsets of i + 1 of its 5 vertices, each once
        assert all(len(v) == i + 1 for v in vertices[i])
        assert len(set(vertices[i])) == f[i] == math.comb(d + 1, i + 1)
        for j in range(d + 1):
            a = m.incidence(i, j)
            assert isinstance(a, sp.csr_matrix)
            assert a.shape == (f[i], f[j])
            assert a.dtype == np.int32 and a.max() == 1
            expected = math.comb(i + 1, j + 1) if j <= i else math.comb(d - i, j - i)
            assert np.all(np.asarray(a.sum(axis=1)).ravel() == expected)
            # exactly the j-cells whose vertices are in the i-cell's, or contain them
            for r, cols in enumerate(rows(m, i, j)):
                want = {
                    c
                    for c in range(f[j])
                    if (vertices[j][c] <= vertices[i][r] if j <= i else vertices[i][r] <= vertices[j][c])
                }
                assert cols == want
            # incidence(j, i) is the transpose
            assert (a != m.incidence(j, i).T).nnz == 0
    assert (m.incidence(2, 2) != sp.identity(f[2], dtype=np.int32, format="csr")).nnz == 0
    # the kinds by name
    assert (m.incidence("edge", "vertex") != m.incidence(1, 0)).nnz == 0
    # adjacency by a product: the edges of the 4-simplex all meet at a vertex, pairwise but for 3 each
    e = m.incidence(1, 0) @ m.incidence(0, 1)
    assert np.all(e.diagonal() == 2)
    assert np.all(np.asarray((e > 0).sum(axis=1)).ravel() == 1 + 6)


@pytest.mark.parametrize("gmap", MODELS)
def test_incidence_of_a_grid(gmap):
    m = cgogn.cube_grid(3, 2, gmap=gmap)
    # an edge has 2 vertices, a square 4 edges and 4 vertices, a cube 6 faces; inner faces are in 2 cubes
    assert np.all(np.diff(incidence_csr(m, 1, 0)[0]) == 2)
    assert np.all(np.diff(incidence_csr(m, 2, 1)[0]) == 4)
    assert np.all(np.diff(incidence_csr(m, 2, 0)[0]) == 4)
    assert np.all(np.diff(incidence_csr(m, 3, 2)[0]) == 6)
    faces_per_cube = np.bincount(np.diff(incidence_csr(m, 2, 3)[0]), minlength=3)
    assert faces_per_cube.tolist() == [0, 24, 12]  # boundary cells are not listed
    # rows are cell ids, as attribute rows are
    assert incidence_csr(m, 3, 0)[2] == (m.id_bound(3), m.id_bound(0))
    assert m.cells(3).tolist() == list(range(8))


def test_incidence_without_scipy(monkeypatch):
    m = cgogn.simplex(3)
    indptr, indices, shape = m._incidence(2, 0)
    monkeypatch.setitem(sys.modules, "scipy.sparse", None)
    t = m.incidence(2, 0)
    assert isinstance(t, tuple) and len(t) == 3
    assert np.array_equal(t[0], indptr) and np.array_equal(t[1], indices) and t[2] == shape == (4, 4)
    assert t[0].dtype == np.uint32 and t[1].dtype == np.uint32


def test_cell_dimensions_are_checked():
    m = cgogn.cube(2)
    with pytest.raises(ValueError, match="0..2"):
        m.nb_cells(3)
    with pytest.raises(ValueError, match="0..2"):
        m.incidence(0, -1)
    with pytest.raises(ValueError, match="unknown cell kind"):
        m.cells("cube")
    with pytest.raises(TypeError):
        m.cells(1.0)
    assert m.nb_cells("face") == m.nb_cells(2) == 1
    assert m.nb_cells(np.int64(0)) == 4


# ---- attributes


@pytest.mark.parametrize("gmap", MODELS)
@pytest.mark.parametrize("d", DIMS)
def test_attributes_on_cells_of_every_dimension(d, gmap):
    m = cgogn.cube_grid(d, 2, gmap=gmap)
    f = m.f_vector()
    for k in range(d + 1):
        a = m.add_attribute("x", k)
        assert a.shape == (m.id_bound(k),) == (f[k],) and a.dtype == np.float64
        assert not a.any()
        i = m.add_attribute("i", k, "int32")
        assert i.shape == (f[k],) and i.dtype == np.int32
        v = m.add_attribute("v", k, components=3)
        assert v.shape == (f[k], 3) and v.dtype == np.float64
        u = m.add_attribute("u", k, "int64")
        assert u.dtype == np.int64
        # the arrays alias the map: writes are seen through new arrays
        a[:] = np.arange(f[k]) * 0.5
        v[:, 2] = 7
        assert np.array_equal(m.attribute("x", k), np.arange(f[k]) * 0.5)
        assert np.all(m.attribute("v", k)[:, 2] == 7)
        m.set_attribute("i", k, -np.arange(f[k]))
        assert np.array_equal(i, -np.arange(f[k]))
        names = {name: (dtype, c) for name, dtype, c in m.attributes(k)}
        assert names["x"] == ("float64", 1) and names["i"] == ("int32", 1) and names["v"] == ("float64", 3)
        assert names["u"] == ("int64", 1)
        m.remove_attribute("u", k)
        with pytest.raises(KeyError):
            m.attribute("u", k)
    assert ("position", "float64", d) in m.attributes(0)
    assert m.positions.shape == (f[0], d)


def test_attribute_errors():
    m = cgogn.cube(3)
    m.add_attribute("a", 1)
    with pytest.raises(ValueError, match="exists already"):
        m.add_attribute("a", 1)
    with pytest.raises(ValueError, match="library's own"):
        m.add_attribute("__a", 1)
    with pytest.raises(ValueError, match="unsupported attribute type"):
        m.add_attribute("b", 1, "bool")
    with pytest.raises(ValueError, match="unsupported attribute type"):
        m.add_attribute("b", 1, components=5)
    with pytest.raises(ValueError, match="unsupported attribute type"):
        m.add_attribute("b", 1, "uint64")
    with pytest.raises(ValueError, match=r"shape \(12\)"):
        m.set_attribute("a", 1, np.zeros(3))
    with pytest.raises(KeyError):
        m.attribute("a", 2)
    with pytest.raises(KeyError):
        m.remove_attribute("nothing", 0)
    # an array outlives the removal of its attribute and the map
    a = m.attribute("a", "edge")
    a[:] = 3
    m.remove_attribute("a", 1)
    del m
    assert np.all(a == 3)
    # positions are assigned whole
    c = cgogn.cube(2)
    with pytest.raises(ValueError, match=r"shape \(4, 2\)"):
        c.positions = np.zeros((4, 3))
    c.positions = c.positions * 2
    assert c.positions.max() == 2


# ---- files


def values_by_cell(m, k, name):
    """{the vertex positions of a cell: its value}: the same cells have the
    same vertices in a map and in its copy, whatever their ids."""
    pos = m.positions
    indptr, indices, _ = m._incidence(k, 0)
    a = m.attribute(name, k)
    out = {}
    for r in m.cells(k):
        key = frozenset(tuple(pos[v]) for v in indices[indptr[r] : indptr[r + 1]])
        assert key not in out
        out[key] = np.asarray(a[r]).tolist()
    return out


@pytest.mark.parametrize("gmap", MODELS)
@pytest.mark.parametrize("d", DIMS)
def test_nmap_round_trip(tmp_path, d, gmap):
    m = cgogn.cube_grid(d, 2, gmap=gmap)
    m.add_attribute("tag", d - 1, "int32")[:] = np.arange(m.id_bound(d - 1)) - 5
    m.add_attribute("w", d, "float64")[:] = np.linspace(0.1, 0.9, m.id_bound(d))
    m.add_attribute("n", 1, "float64", 3)[:] = np.arange(3 * m.id_bound(1)).reshape(-1, 3) / 7
    m.add_attribute("big", 0, "int64")[:] = 2**40 + np.arange(m.id_bound(0))
    path = tmp_path / "m.nmap"
    assert m.save(str(path)) == []
    assert path.read_text().startswith("cgogn_nmap 1\nmodel " + ("gmap" if gmap else "cmap"))
    back = cgogn.load(str(path))
    assert type(back) is type(m)
    assert back.nb_darts() == m.nb_darts()
    assert back.f_vector() == m.f_vector()
    assert back.check_integrity()["ok"]
    assert back.positions.shape == m.positions.shape
    assert sorted(map(tuple, back.positions)) == sorted(map(tuple, m.positions))
    for k, name, dtype, comps in [(d - 1, "tag", "int32", 1), (d, "w", "float64", 1), (1, "n", "float64", 3), (0, "big", "int64", 1)]:
        assert (name, dtype, comps) in back.attributes(k)
        assert back.attribute(name, k).dtype == m.attribute(name, k).dtype
        assert values_by_cell(back, k, name) == values_by_cell(m, k, name)
    # and the same file again
    back.save(str(tmp_path / "again.nmap"))
    assert (tmp_path / "again.nmap").read_text() == path.read_text()


def test_load_as_gmap_and_the_formats_page_example(tmp_path):
    path = tmp_path / "triangle.nmap"
    path.write_text(
        "cgogn_nmap 1\nmodel cmap\ndimension 2\ndarts 6\n1 3 0\n2 5 0\n0 4 0\n4 0 1\n5 2 1\n3 1 1\n"
        "attribute 0 position float64x2 3\n0 0 0\n1 1 0\n2 0 1\nend\n"
    )
    m = cgogn.load(str(path))
    assert isinstance(m, cgogn.CMapN2)
    assert m.f_vector() == [3, 3, 1] and m.nb_darts() == 6
    assert sorted(map(tuple, m.positions)) == [(0, 0), (0, 1), (1, 0)]
    g = cgogn.load(str(path), gmap=True)
    assert isinstance(g, cgogn.GMapN2)
    assert g.f_vector() == [3, 3, 1] and g.nb_darts() == 12
    assert sorted(map(tuple, g.positions)) == [(0, 0), (0, 1), (1, 0)]
    # a GMapN file stays a GMapN
    g.save(str(tmp_path / "g.NMAP"))
    assert isinstance(cgogn.load(str(tmp_path / "g.NMAP")), cgogn.GMapN2)


def test_attribute_types_only_files_make(tmp_path):
    path = tmp_path / "path.nmap"
    # a cycle of two edges (a 1-map: phi1 only) with attributes of the types Python does not create
    path.write_text(
        "cgogn_nmap 1\nmodel cmap\ndimension 1\ndarts 2\n1 0\n0 0\n"
        "attribute 0 id uint64 2\n0 18446744073709551615\n1 7\n"
        "attribute 1 v float64x6 2\n0 1 2 3 4 5 6\n1 0 0 0 0 0 1\n"
        "attribute 1 u uint32 2\n0 4000000000\n1 3\n"
        "end\n"
    )
    m = cgogn.load(str(path))
    assert isinstance(m, cgogn.CMapN1)
    assert m.f_vector() == [2, 2]
    assert ("id", "uint64", 1) in m.attributes(0)
    assert ("v", "float64", 6) in m.attributes(1) and ("u", "uint32", 1) in m.attributes(1)
    assert sorted(m.attribute("id", 0)[:2].tolist()) == [7, 2**64 - 1]
    assert m.attribute("v", 1).shape == (2, 6) and m.attribute("u", 1).dtype == np.uint32
    m.attribute("u", 1)[:] += 1
    m.save(str(tmp_path / "again.nmap"))
    back = cgogn.load(str(tmp_path / "again.nmap"))
    assert sorted(back.attribute("u", 1).tolist()) == [4, 4000000001]
    assert sorted(map(tuple, back.attribute("v", 1))) == sorted(map(tuple, m.attribute("v", 1)))


BAD_FILES = [
    ("cgogn_map 1\n", "bad.nmap:1: not a .nmap file"),
    ("cgogn_nmap 1\nmodel map\n", "bad.nmap:2: unknown model 'map'"),
    ("cgogn_nmap 1\nmodel cmap\ndimension 0\n", "bad.nmap:3: the dimension 0 is out of"),
    ("cgogn_nmap 1\nmodel cmap\ndimension 5\ndarts 0\nend\n", "bad.nmap: the file holds a map of dimension 5"),
    ("cgogn_nmap 1\nmodel cmap\ndimension 1\ndarts 2\n1 0\n7 0\n", "bad.nmap:6: relation 1 points to dart 7, out of range"),
    ("cgogn_nmap 1\nmodel cmap\ndimension 1\ndarts 2\n0 0\n0 0\nend\n", "the darts do not make a valid map"),
    ("cgogn_nmap 1\nmodel cmap\ndimension 1\ndarts 2\n1 0\n", "bad.nmap:5: the file ends where a dart is expected"),
    (
        "cgogn_nmap 1\nmodel cmap\ndimension 1\ndarts 2\n1 0\n0 0\nattribute 0 w complex 1\n0 1\nend\n",
        "bad.nmap:7: unknown value type 'complex'",
    ),
]


@pytest.mark.parametrize("text, message", BAD_FILES)
def test_malformed_nmap_files_raise_io_errors(tmp_path, text, message):
    path = tmp_path / "bad.nmap"
    path.write_text(text)
    with pytest.raises(cgogn.IOError) as e:
        cgogn.load(str(path))
    assert message in str(e.value)
    assert isinstance(e.value, cgogn.Error)


def test_missing_file_and_unwritable_paths(tmp_path):
    with pytest.raises(cgogn.IOError, match="nothing.nmap"):
        cgogn.load(str(tmp_path / "nothing.nmap"))
    m = cgogn.simplex(2)
    with pytest.raises(cgogn.IOError, match="no_dir"):
        m.save(str(tmp_path / "no_dir" / "m.nmap"))
    with pytest.raises(cgogn.IOError, match="unknown extension"):
        m.save(str(tmp_path / "m.off"))


def test_vtu_output(tmp_path):
    m = cgogn.cube_grid(4, 2)
    m.boundary().save(str(tmp_path / "b.vtu"))
    text = (tmp_path / "b.vtu").read_text()
    assert "UnstructuredGrid" in text and 'NumberOfCells="' + str(m.boundary().nb_cells(3)) + '"' in text
    m.save(str(tmp_path / "s.vtu"), dimensions=[0, 1])
    assert 'NumberOfCells="' + str(81 + 216) + '"' in (tmp_path / "s.vtu").read_text()
    with pytest.raises(cgogn.IOError, match="position"):
        cgogn.GMapN(2).save(str(tmp_path / "e.vtu"))
    with pytest.raises(ValueError):
        m.save(str(tmp_path / "m.nmap"), dimensions=[1])
