# SPDX-License-Identifier: MIT
"""Sparse matrices of a surface, as scipy.sparse when SciPy is installed."""

import numpy as np


def laplacian(m, kind="cotan"):
    """The Laplacian of a surface: kind "cotan" (cotangent weights), "uniform"
    or "mass" (the lumped mixed-Voronoi mass matrix).

    Rows and columns are the vertices in id order (``m.cell_ids("vertex")``;
    the identity on a compact map). Returns a ``scipy.sparse.csr_matrix`` when
    SciPy is installed, otherwise a tuple ``(rows, cols, values, shape)`` of
    COO arrays. O(darts).
    """
    rows, cols, values, n, _ids = m._laplacian(kind)
    try:
        import scipy.sparse as sp
    except ImportError:
        return rows.astype(np.int64), cols.astype(np.int64), values, (n, n)
    return sp.csr_matrix((values, (rows, cols)), shape=(n, n))
