# SPDX-License-Identifier: MIT
"""Partitioning with METIS (the distributed layer; skipped when the module was
built without it)."""
import numpy as np
import pytest

import cgogn

pytestmark = pytest.mark.skipif(not hasattr(cgogn.CMap3, "partition"),
                                reason="built without the distributed layer (MPI and METIS)")


def test_volume_parts_match_the_report(data):
    m = cgogn.load(str(data / "volume" / "armadillo_tet_4k.mesh"))
    r = m.partition(3, seed=1)
    parts = m.attribute("part", "volume")
    ids = m.cell_ids("volume")
    counts = np.bincount(parts[ids], minlength=3)
    assert list(counts) == r["part_sizes"]
    assert r["imbalance"] <= 1.05
    assert r["parts_connected"]
    assert 0 < r["cut_facets"] < r["interior_facets"]
    assert r["cut_ratio"] == pytest.approx(r["cut_facets"] / r["interior_facets"])


def test_surface_faces_and_bad_arguments(data):
    m = cgogn.load(str(data / "surface" / "hemisphere.off"))
    r = m.partition(2, attribute="rank")
    assert sum(r["part_sizes"]) == m.nb_cells("face")
    assert r["parts_connected"]
    with pytest.raises(ValueError):
        m.partition(0)
    with pytest.raises(ValueError):
        m.partition(m.nb_cells("face") + 1)
