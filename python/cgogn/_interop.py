# SPDX-License-Identifier: MIT
"""Conversions to and from meshio, PyVista and trimesh (imported lazily)."""

import numpy as np

from ._cgogn import CMap2, CMap3

# meshio cell types of the volumes a CMap3 builds, by vertex count
_VOLUME_TYPES = {4: "tetra", 5: "pyramid", 6: "wedge", 8: "hexahedron"}
_SURFACE_TYPES = {3: "triangle", 4: "quad"}


def _compact_points(m, lists):
    """Points in vertex id order, with the cell lists renumbered densely."""
    ids = m.cell_ids("vertex")
    points = np.asarray(m.positions)[ids]
    if len(ids) == m.id_bound("vertex"):
        return points, lists
    dense = np.full(m.id_bound("vertex"), -1, dtype=np.int64)
    dense[ids] = np.arange(len(ids))
    return points, [dense[x] for x in lists]


def to_meshio(m):
    """A ``meshio.Mesh`` with the map's points and cells: the faces of a CMap2
    (triangles, quads, polygons by size) or the volumes of a CMap3 given as
    tetrahedra (other volumes are not written). Needs the meshio package."""
    import meshio

    if isinstance(m, CMap2):
        offsets, indices = m.faces_csr()
        sizes = np.diff(offsets)
        blocks = []
        for k in np.unique(sizes):
            rows = np.nonzero(sizes == k)[0]
            cols = offsets[rows][:, None] + np.arange(k)[None, :]
            blocks.append((int(k), indices[cols].astype(np.int64)))
        points, lists = _compact_points(m, [b[1] for b in blocks])
        cells = [(_SURFACE_TYPES.get(k, "polygon"), c) for (k, _), c in zip(blocks, lists)]
        return meshio.Mesh(points, cells)
    tets = m.cells().astype(np.int64)
    # (a, b, c, d) with d on the side of the normal of (a, b, c), as VTK and meshio order them
    points, (tets,) = _compact_points(m, [tets])
    return meshio.Mesh(points, [("tetra", tets)])


def from_meshio(mesh):
    """A CMap3 when the meshio mesh has volume cells (tetra, pyramid, wedge,
    hexahedron), otherwise a CMap2 of its polygons (triangle, quad, polygon)."""
    points = np.asarray(mesh.points, dtype=np.float64)
    if points.shape[1] == 2:
        points = np.hstack([points, np.zeros((len(points), 1))])
    volume_blocks = [c for c in mesh.cells if c.type in ("tetra", "pyramid", "wedge", "hexahedron")]
    if volume_blocks:
        sizes, ids = [], []
        for c in volume_blocks:
            data = np.asarray(c.data, dtype=np.int64)
            sizes.extend([data.shape[1]] * len(data))
            ids.append(data.ravel())
        offsets = np.concatenate([[0], np.cumsum(sizes)])
        return CMap3.from_arrays(points, (offsets, np.concatenate(ids)))
    sizes, ids = [], []
    for c in mesh.cells:
        if c.type in ("triangle", "quad", "polygon") or c.type.startswith("polygon"):
            data = np.asarray(c.data, dtype=np.int64)
            sizes.extend([data.shape[1]] * len(data))
            ids.append(data.ravel())
    if not sizes:
        raise ValueError("the meshio mesh has no polygon or volume cells")
    offsets = np.concatenate([[0], np.cumsum(sizes)])
    return CMap2.from_arrays(points, (offsets, np.concatenate(ids)))


def to_pyvista(m):
    """A ``pyvista.PolyData`` of the faces (boundary faces for a CMap3). Needs pyvista."""
    import pyvista

    offsets, indices = m.faces_csr()
    points, (indices,) = _compact_points(m, [indices.astype(np.int64)])
    sizes = np.diff(offsets)
    faces = np.insert(indices, offsets[:-1].astype(np.int64), sizes)
    return pyvista.PolyData(points, faces)


def to_trimesh(m):
    """A ``trimesh.Trimesh`` of the triangles (boundary triangles for a CMap3). Needs trimesh."""
    import trimesh

    faces = m.faces().astype(np.int64)
    points, (faces,) = _compact_points(m, [faces])
    return trimesh.Trimesh(points, faces, process=False)
