# SPDX-License-Identifier: MIT
"""cgogn: combinatorial maps for mesh processing.

Surfaces are :class:`CMap2`, volume meshes :class:`CMap3`; meshes that may
not be orientable are :class:`GMap2` and :class:`GMap3` (``load(path,
gmap=True)``, ``to_gmap()``, ``to_cmap()``). Cells (vertices,
edges, faces, volumes) are named by integer *ids*: after loading, building
from arrays or :meth:`CMap2.compact`, the ids of a kind are exactly
0..nb_cells-1 in traversal order. Editing operators keep the ids of the
cells they keep, give new cells new ids and free the ids of removed cells,
so ids may then have gaps until ``compact()`` renumbers them densely.
Attribute arrays (``positions``, ``attribute(...)``) have one row per id
(``id_bound(kind)`` rows); arrays that list cells (``faces()``,
``incidence()``, ``cell_ids()``) list the live cells in id order.

The maps of any dimension D = 1 to 4 are :func:`CMapN` and :func:`GMapN`
(instances of ``CMapN1`` ... ``GMapN4``, all :class:`NMap`), made by the
generators (:func:`simplex`, :func:`cube`, :func:`cube_grid`,
:func:`freudenthal_grid`), the builders (:func:`simplicial_complex`,
:func:`cubical_complex`) or ``load`` of a ``.nmap`` file; their cells are
named by dimension k = 0 ... D.
"""

from ._cgogn import (
    CMap2,
    CMap3,
    CMapN1,
    CMapN2,
    CMapN3,
    CMapN4,
    Error,
    GMap2,
    GMap3,
    GMapN1,
    GMapN2,
    GMapN3,
    GMapN4,
    Graph,
    IncidenceGraph,
    IOError,
    MRMap2,
    MRMap3,
    NMap,
    RenderError,
    load,
    map_from_bytes,
    nb_workers,
    set_nb_workers,
)
from ._arrays import laplacian
from ._interop import from_meshio, to_meshio, to_pyvista, to_trimesh
from ._nmaps import (
    CMapN,
    GMapN,
    cube,
    cube_grid,
    cubical_complex,
    freudenthal_grid,
    incidence as _nmap_incidence,
    simplex,
    simplicial_complex,
)

__all__ = [
    "CMap2",
    "CMap3",
    "GMap2",
    "GMap3",
    "Graph",
    "IncidenceGraph",
    "MRMap2",
    "MRMap3",
    "CMapN",
    "GMapN",
    "NMap",
    "CMapN1",
    "CMapN2",
    "CMapN3",
    "CMapN4",
    "GMapN1",
    "GMapN2",
    "GMapN3",
    "GMapN4",
    "simplex",
    "cube",
    "cube_grid",
    "freudenthal_grid",
    "simplicial_complex",
    "cubical_complex",
    "Error",
    "IOError",
    "RenderError",
    "load",
    "map_from_bytes",
    "laplacian",
    "set_nb_workers",
    "nb_workers",
    "to_meshio",
    "from_meshio",
    "to_pyvista",
    "to_trimesh",
]


def _from_bytes(data):
    """Rebuilds a pickled map: the maps' ``__reduce__`` names this function
    (a compiled function cannot be pickled by name)."""
    return map_from_bytes(data)


def _laplacian_method(self, kind="cotan"):
    return laplacian(self, kind)


CMap2.laplacian = _laplacian_method
CMap2.laplacian.__doc__ = laplacian.__doc__
NMap.incidence = _nmap_incidence
