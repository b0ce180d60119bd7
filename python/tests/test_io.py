# SPDX-License-Identifier: MIT
"""Round trips through every file format, and bad files."""
import numpy as np
import pytest

import cgogn
from conftest import BAD


def same_surface(a, b):
    assert [a.nb_cells(k) for k in ("vertex", "edge", "face")] == [b.nb_cells(k) for k in ("vertex", "edge", "face")]
    assert np.allclose(a.positions, b.positions, atol=1e-5)


@pytest.mark.parametrize("ext,binary", [("off", False), ("obj", False), ("ply", False), ("ply", True), ("stl", False), ("stl", True)])
def test_surface_round_trip(data, tmp_path, ext, binary):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    m.triangulate()  # STL holds triangles only
    out = tmp_path / ("mesh." + ext)
    m.save(str(out), binary=binary)
    back = cgogn.load(str(out))
    assert isinstance(back, cgogn.CMap2)
    if ext == "stl":  # STL has no shared vertices: compare the geometry
        assert back.nb_cells("face") == m.nb_cells("face")
        assert back.face_areas().sum() == pytest.approx(m.face_areas().sum(), rel=1e-5)
    else:
        same_surface(m, back)


@pytest.mark.parametrize("ext,binary", [("mesh", False), ("vtk", False), ("vtk", True), ("vtu", False), ("vtu", True), ("msh", False), ("msh", True), ("ele", False), ("ovm", False)])
def test_volume_round_trip(data, tmp_path, ext, binary):
    # TetGen files hold tetrahedra only
    name = "armadillo_tet_4k.mesh" if ext == "ele" else "liver_hex_624.mesh"
    m = cgogn.load(str(data / "volume" / name))
    out = tmp_path / ("mesh." + ext)
    m.save(str(out), binary=binary)
    back = cgogn.load(str(out))
    assert isinstance(back, cgogn.CMap3)
    for k in ("vertex", "edge", "face", "volume"):
        assert back.nb_cells(k) == m.nb_cells(k)
    assert np.allclose(np.sort(back.positions, axis=0), np.sort(m.positions, axis=0), atol=1e-6)


def test_every_bad_file_raises_an_io_error_naming_it():
    files = sorted(p for p in BAD.iterdir() if p.suffix != ".node")
    assert len(files) > 20
    for path in files:
        with pytest.raises(cgogn.IOError) as e:
            cgogn.load(str(path))
        assert path.name in str(e.value) or path.stem in str(e.value)
        assert isinstance(e.value, cgogn.Error)


def test_missing_file_and_unknown_extension(tmp_path):
    with pytest.raises(cgogn.IOError, match="nothing.off"):
        cgogn.load(str(tmp_path / "nothing.off"))
    (tmp_path / "a.xyz").write_text("1 2 3\n")
    with pytest.raises(cgogn.IOError):
        cgogn.load(str(tmp_path / "a.xyz"))


@pytest.mark.parametrize("ext", ["ply", "vtu"])
def test_integer_attributes_keep_their_type(data, tmp_path, ext):
    if ext == "ply":
        m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
        kind = "face"
    else:
        m = cgogn.load(str(data / "volume" / "liver_hex_624.mesh"))
        kind = "volume"
    for dtype in ("int8", "uint8", "int16", "uint16", "int32", "uint32"):
        a = m.add_attribute("tag_" + dtype, kind, dtype)
        a[:] = np.arange(len(a)) % 100
    out = tmp_path / ("mesh." + ext)
    m.save(str(out))
    back = cgogn.load(str(out))
    held = {name: dtype for name, dtype, _ in back.attributes(kind)}
    for dtype in ("int8", "uint8", "int16", "uint16", "int32", "uint32"):
        assert held["tag_" + dtype] == dtype
        values = back.attribute("tag_" + dtype, kind)[back.cell_ids(kind)]
        assert sorted(values) == sorted(m.attribute("tag_" + dtype, kind)[m.cell_ids(kind)])
