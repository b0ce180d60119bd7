# SPDX-License-Identifier: MIT
"""The maps of any dimension: the classes by model and dimension, the
generators, and incidence relations as scipy.sparse matrices."""

import operator

import numpy as np

from . import _cgogn

#: The dimensions of the maps of any dimension Python has.
DIMENSIONS = range(1, 5)


def _nmap_class(model, dimension):
    d = operator.index(dimension)
    if d not in DIMENSIONS:
        raise ValueError(
            f"{model}: unsupported dimension {d!r}; the supported dimensions are {DIMENSIONS.start} to {DIMENSIONS.stop - 1}"
        )
    return getattr(_cgogn, f"{model}{d}")


def _class(dimension, gmap):
    return _nmap_class("GMapN" if gmap else "CMapN", dimension)


def CMapN(dimension):
    """An empty combinatorial map of dimension 1 to 4 (an instance of
    ``CMapN1`` ... ``CMapN4``). ValueError for another dimension."""
    return _nmap_class("CMapN", dimension)()


def GMapN(dimension):
    """An empty generalized map of dimension 1 to 4 (an instance of
    ``GMapN1`` ... ``GMapN4``). ValueError for another dimension."""
    return _nmap_class("GMapN", dimension)()


def simplex(dimension, gmap=False):
    """The D-simplex of vertices the origin and the unit vectors, with
    positions: C(D + 1, k + 1) k-cells. A GMapN with ``gmap=True``."""
    return _class(dimension, gmap).simplex()


def cube(dimension, gmap=False):
    """The unit D-cube [0, 1]^D, with positions: C(D, k) 2^(D - k) k-cells."""
    return _class(dimension, gmap).cube()


def cube_grid(dimension, n, gmap=False):
    """The grid of n^D cubes filling [0, 1]^D (n >= 1), with positions:
    C(D, k) n^k (n + 1)^(D - k) k-cells."""
    return _class(dimension, gmap).cube_grid(n)


def freudenthal_grid(dimension, n, gmap=False):
    """The grid of ``cube_grid(dimension, n)``, each cube cut into the D!
    simplices around its main diagonal: (n + 1)^D vertices, n^D D! D-cells."""
    return _class(dimension, gmap).freudenthal_grid(n)


def _width_dimension(cells, widths, what):
    shape = np.shape(cells)
    if len(shape) != 2 or shape[1] not in widths:
        raise ValueError(f"{what} must be a (C, k) array with k in {sorted(widths)}")
    return widths[shape[1]]


def simplicial_complex(cells, points=None, gmap=False):
    """The map of a pure simplicial complex: cells a (C, D + 1) integer array
    of vertex ids (D = 1 to 4, read from its width), points None or an
    (N, D) array stored as the positions."""
    d = _width_dimension(cells, {k + 1: k for k in DIMENSIONS}, "cells")
    return _class(d, gmap).simplicial_complex(cells, points)


def cubical_complex(cells, points=None, gmap=False):
    """The map of a pure cubical complex: cells a (C, 2^D) integer array of
    vertex ids (D = 1 to 4, read from its width), vertex k of a cube at the
    coordinates given by the bits of k; points as in simplicial_complex."""
    d = _width_dimension(cells, {2**k: k for k in DIMENSIONS}, "cells")
    return _class(d, gmap).cubical_complex(cells, points)


def incidence(self, i, j):
    """For each i-cell, the j-cells incident to it (those sharing a dart with
    it, each once, boundary cells excluded), as a sparse matrix: row r holds
    the ids of the j-cells of the i-cell of id r (rows of ids without a cell
    are empty), shape ``(id_bound(i), id_bound(j))``, values 1 (int32).
    incidence(j, i) is its transpose; incidence(i, i) the identity on the
    live i-cells. Returns a ``scipy.sparse.csr_matrix`` when SciPy is
    installed, otherwise the tuple ``(indptr, indices, shape)`` of uint32
    arrays and a pair. Indexes both dimensions. O(darts).
    """
    indptr, indices, shape = self._incidence(i, j)
    try:
        import scipy.sparse as sp
    except ImportError:
        return indptr, indices, shape
    data = np.ones(len(indices), dtype=np.int32)
    return sp.csr_matrix((data, indices, indptr), shape=shape)
