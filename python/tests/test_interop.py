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
