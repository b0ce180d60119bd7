# SPDX-License-Identifier: MIT
"""Cost of the Python bindings against the C++ calls, and against NumPy.

python3 bench/python/python_bench.py [BUILD_DIR] [MESH]

Makes a mesh of about a million triangles (4 Loop steps of hemisphere.off)
unless MESH is given, times the bulk operations from Python and from C++
(BUILD_DIR/bench/bench_python_reference, median of 5 runs each) and prints
the ratios, then the array accessors and a pure-NumPy face-normal
computation. Run it with PYTHONPATH=BUILD_DIR/python (or an installed
cgogn)."""
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

root = pathlib.Path(__file__).resolve().parents[2]
build = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else root / "build" / "release"
sys.path.insert(0, str(build / "python"))
import cgogn  # noqa: E402


def median_ms(run, setup=lambda: None, repeats=5):
    times = []
    for _ in range(repeats):
        setup()
        start = time.perf_counter()
        run()
        times.append((time.perf_counter() - start) * 1000)
    return statistics.median(times)


def main():
    tmp = tempfile.TemporaryDirectory()
    if len(sys.argv) > 2:
        mesh = sys.argv[2]
    else:
        m = cgogn.load(str(root / "tests" / "data" / "surface" / "hemisphere.off"))
        m.subdivide("loop", 4)
        mesh = os.path.join(tmp.name, "big.ply")
        m.save(mesh, binary=True)
    big = cgogn.load(mesh)
    print(f"mesh: {mesh} ({big.nb_cells('face')} faces, {big.nb_cells('vertex')} vertices)")

    state = {}

    def fresh():
        state["m"] = cgogn.load(mesh)

    py = {
        "load": median_ms(lambda: cgogn.load(mesh)),
        "vertex_normals": median_ms(lambda: big.vertex_normals()),
        "subdivide_loop": median_ms(lambda: state["m"].subdivide("loop", 1), fresh),
        "decimate_quarter": median_ms(
            lambda: state["m"].decimate(target_faces=state["m"].nb_cells("face") // 4), fresh
        ),
    }
    ref = subprocess.run(
        [str(build / "bench" / "bench_python_reference"), mesh, "5"], check=True, capture_output=True, text=True
    ).stdout
    cpp = {name: float(ms) for name, ms in (line.split() for line in ref.splitlines())}
    print(f"{'operation':<18} {'Python ms':>10} {'C++ ms':>10} {'ratio':>7}")
    for name, ms in py.items():
        print(f"{name:<18} {ms:10.1f} {cpp[name]:10.1f} {ms / cpp[name]:7.2f}")

    positions = median_ms(lambda: big.positions, repeats=21)
    faces = median_ms(lambda: big.faces(), repeats=21)
    print(f"positions view: {positions:.3f} ms, faces array: {faces:.2f} ms, both: {positions + faces:.2f} ms")

    p, f = big.positions, big.faces().astype(np.int64)

    def numpy_normals():
        n = np.cross(p[f[:, 1]] - p[f[:, 0]], p[f[:, 2]] - p[f[:, 0]])
        return n / np.linalg.norm(n, axis=1)[:, None]

    print(f"face normals: cgogn {median_ms(lambda: big.face_normals()):.1f} ms, "
          f"pure NumPy {median_ms(numpy_normals):.1f} ms")


if __name__ == "__main__":
    main()
