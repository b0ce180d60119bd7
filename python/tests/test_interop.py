# SPDX-License-Identifier: MIT
"""meshio round trips; PyVista and trimesh when installed."""
import numpy as np
import pytest

import cgogn

meshio = pytest.importorskip("meshio")


def test_surface_meshio_round_trip(data):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    mesh = cgogn.to_meshio(m)
    assert len(mesh.points) == m.nb_cells("vertex")
    assert sum(len(c.data) for c in mesh.cells) == m.nb_cells("face")
    back = cgogn.from_meshio(mesh)
    assert [back.nb_cells(k) for k in ("vertex", "edge", "face")] == [m.nb_cells(k) for k in ("vertex", "edge", "face")]
    assert np.allclose(back.positions, m.positions)


def test_volume_meshio_round_trip_through_a_file(data, tmp_path):
    m = cgogn.load(str(data / "volume" / "armadillo_tet_4k.mesh"))
    mesh = cgogn.to_meshio(m)
    path = tmp_path / "tets.vtu"
    meshio.write(str(path), mesh)
    back = cgogn.load(str(path))  # read by cgogn: the orientation meshio wrote is VTK's
    assert back.check_integrity()["ok"]
    for k in ("vertex", "edge", "face", "volume"):
        assert back.nb_cells(k) == m.nb_cells(k)
    again = cgogn.from_meshio(meshio.read(str(path)))
    assert again.nb_cells("volume") == m.nb_cells("volume")
    assert again.euler_characteristic() == m.euler_characteristic()


def test_pyvista_and_trimesh_when_installed(data):
    m = cgogn.load(str(data / "surface" / "hemisphere.off"))
    try:
        import pyvista  # noqa: F401

        assert cgogn.to_pyvista(m).n_cells == m.nb_cells("face")
    except ImportError:
        pass
    try:
        import trimesh  # noqa: F401

        assert len(cgogn.to_trimesh(m).faces) == m.nb_cells("face")
    except ImportError:
        pass


def tag_histogram(mesh, name):
    """{(cell kind, tag): count} of a meshio mesh's integer cell data `name`."""
    counts = {}
    kinds = {"line": "edge", "triangle": "face", "quad": "face", "tetra": "volume", "hexahedron": "volume"}
    for block, values in zip(mesh.cells, mesh.cell_data[name]):
        for tag in values:
            key = (kinds[block.type], int(tag))
            counts[key] = counts.get(key, 0) + 1
    return counts


@pytest.mark.parametrize("source", ["box_tet_v41.msh", "box_hex_v22_bin.msh"])
@pytest.mark.parametrize("ext,binary", [("msh", False), ("msh", True), ("vtu", False), ("vtu", True), ("vtk", False), ("vtk", True), ("mesh", False)])
def test_gmsh_tags_seen_by_meshio_after_conversion(data, tmp_path, source, ext, binary):
    original = meshio.read(str(data / "gmsh" / source))
    expected = tag_histogram(original, "gmsh:physical")
    out = tmp_path / ("box." + ext)
    cgogn.load(str(data / "gmsh" / source)).save(str(out), binary=binary)
    written = meshio.read(str(out))
    assert tag_histogram(written, "medit:ref" if ext == "mesh" else "gmsh:physical") == expected
    if ext != "mesh":
        assert tag_histogram(written, "gmsh:geometrical") == tag_histogram(original, "gmsh:geometrical")
    if ext == "msh":  # the names of the physical groups: {name: [tag, dimension]}
        assert {k: list(v) for k, v in written.field_data.items()} == {k: list(v) for k, v in original.field_data.items()}


@pytest.mark.parametrize("ext,binary", [("msh", False), ("msh", True), ("vtu", False), ("vtu", True), ("vtk", False), ("vtk", True), ("mesh", False)])
def test_surface_tags_of_faces_and_edges_seen_by_meshio(data, tmp_path, ext, binary):
    source = data / "gmsh" / "plate_v41.msh"
    original = meshio.read(str(source))
    expected = tag_histogram(original, "gmsh:physical")
    assert {k for k, _ in expected} == {"face", "edge"}
    m = cgogn.load(str(source))
    assert isinstance(m, cgogn.CMap2)
    out = tmp_path / ("plate." + ext)
    m.save(str(out), binary=binary)
    written = meshio.read(str(out))
    assert tag_histogram(written, "medit:ref" if ext == "mesh" else "gmsh:physical") == expected
    if ext == "msh":
        assert {k: list(v) for k, v in written.field_data.items()} == {k: list(v) for k, v in original.field_data.items()}


@pytest.mark.parametrize("ext,binary", [("vtu", False), ("vtu", True), ("vtk", False), ("vtk", True)])
def test_gmsh_tags_seen_by_vtk_after_conversion(data, tmp_path, ext, binary):
    vtk = pytest.importorskip("vtk")
    from vtk.util.numpy_support import vtk_to_numpy

    source = data / "gmsh" / "box_tet_v22.msh"
    expected = tag_histogram(meshio.read(str(source)), "gmsh:physical")
    out = tmp_path / ("box." + ext)
    cgogn.load(str(source)).save(str(out), binary=binary)
    reader = vtk.vtkXMLUnstructuredGridReader() if ext == "vtu" else vtk.vtkUnstructuredGridReader()
    reader.SetFileName(str(out))
    reader.Update()
    grid = reader.GetOutput()
    kinds = {5: "face", 10: "volume"}
    types = vtk_to_numpy(grid.GetCellTypesArray())
    for name in ("gmsh:physical", "gmsh:geometrical"):
        assert grid.GetCellData().GetArray(name) is not None, name
    tags = vtk_to_numpy(grid.GetCellData().GetArray("gmsh:physical"))
    counts = {}
    for t, tag in zip(types, tags):
        key = (kinds[int(t)], int(tag))
        counts[key] = counts.get(key, 0) + 1
    assert counts == expected
