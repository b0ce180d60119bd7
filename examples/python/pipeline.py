# SPDX-License-Identifier: MIT
"""Load a surface, subdivide it, colour it by curvature, decimate it, save it
and draw it: python3 examples/python/pipeline.py [IN] [OUT_PREFIX]."""
import pathlib
import sys

import numpy as np

import cgogn

here = pathlib.Path(__file__).resolve().parent
src = sys.argv[1] if len(sys.argv) > 1 else str(here.parents[1] / "tests" / "data" / "surface" / "hemisphere.off")
out = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else "cgogn-pipeline")

m = cgogn.load(src)
print(f"loaded {src}: {m.nb_cells('vertex')} vertices, {m.nb_cells('face')} faces, chi = {m.euler_characteristic()}")

m.subdivide("loop", 2)
print(f"after 2 Loop steps: {m.nb_cells('face')} faces")

h = m.mean_curvature()
curv = m.add_attribute("mean_curvature", "vertex")
curv[:] = h
print(f"mean curvature: median {np.median(h):.3f}, range [{h.min():.3f}, {h.max():.3f}]")

result = m.decimate(target_faces=m.nb_cells("face") // 4)
print(f"decimated to {result['faces']} faces ({result['collapses']} collapses, max error {result['max_error']:.2e})")
report = m.check_integrity()
assert report["ok"], report["messages"]

m.save(str(out.with_suffix(".ply")), binary=True)
m.render(str(out.with_suffix(".png")), size=(640, 480), color="curvature")
print(f"wrote {out.with_suffix('.ply')} and {out.with_suffix('.png')}")
