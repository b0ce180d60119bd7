# SPDX-License-Identifier: MIT
"""The geometry and modeling layers on real meshes, and the pictures."""
import struct
import zlib

import numpy as np
import pytest

import cgogn


def ok(m):
    r = m.check_integrity()
    assert r["ok"], r["messages"]


def sphere(n=24):
    """A UV sphere of radius 1 as arrays (independent of the library)."""
    pts = [[0, 0, 1]]
    for i in range(1, n):
        t = np.pi * i / n
        for j in range(2 * n):
            p = 2 * np.pi * j / (2 * n)
            pts.append([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)])
    pts.append([0, 0, -1])
    ring = lambda i, j: 1 + (i - 1) * 2 * n + j % (2 * n)
    tris = []
    for j in range(2 * n):
        tris.append([0, ring(1, j), ring(1, j + 1)])
        tris.append([len(pts) - 1, ring(n - 1, j + 1), ring(n - 1, j)])
    for i in range(1, n - 1):
        for j in range(2 * n):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)
            tris += [[a, d, c], [a, c, b]]
    return np.array(pts, dtype=float), np.array(tris)


def test_geometry_on_a_sphere():
    m = cgogn.CMap2.from_arrays(*sphere())
    ok(m)
    n = m.vertex_normals()
    assert np.allclose(np.linalg.norm(n, axis=1), 1)
    assert np.mean(np.sum(n * m.positions, axis=1)) > 0.99  # outward
    assert m.face_areas().sum() == pytest.approx(4 * np.pi, rel=0.01)
    h = m.mean_curvature()
    assert np.median(np.abs(h)) == pytest.approx(1.0, rel=0.02)
    k = m.gaussian_curvature()
    assert np.median(k) == pytest.approx(1.0, rel=0.03)
    assert m.gaussian_curvature(integrated=True).sum() == pytest.approx(4 * np.pi)  # Gauss-Bonnet
    fn = m.face_normals()
    assert np.allclose(np.linalg.norm(fn, axis=1), 1)
    L = m.laplacian("cotan")
    assert L.shape == (m.nb_cells("vertex"),) * 2
    assert np.abs(L @ np.ones(L.shape[0])).max() < 1e-9  # rows sum to zero
    assert np.abs((L - L.T)).max() < 1e-12


def test_subdivide_decimate_remesh(data):
    m = cgogn.load(str(data / "surface" / "hemisphere.off"))
    f0 = m.nb_cells("face")
    m.subdivide("loop", 1)
    assert m.nb_cells("face") == 4 * f0
    ok(m)
    r = m.decimate(target_faces=f0 // 2)
    assert r["faces"] == m.nb_cells("face") <= f0 // 2 + 1
    ok(m)
    r = m.remesh(iterations=3)
    assert r["iterations"] == 3 and r["target_edge_length"] > 0
    ok(m)
    q = cgogn.load(str(data / "surface" / "cube_quad.off"))
    q.subdivide("catmull-clark", 2)
    assert q.nb_cells("face") == 6 * 16
    with pytest.raises(cgogn.Error):
        cgogn.load(str(data / "surface" / "cube_quad.off")).subdivide("loop")


def test_fill_holes_smooth_triangulate_dual(data):
    m = cgogn.load(str(data / "surface" / "elephant-with-holes.off"))
    assert m.euler_characteristic() == -110  # genus 3, 106 holes: 2 - 2 g - b
    r = m.fill_holes()
    assert r["holes_found"] == r["holes_filled"] == 106
    ok(m)
    assert m.euler_characteristic() == -4  # closed, genus 3
    before = m.positions.copy()
    m.smooth("taubin", 5)
    assert not np.allclose(before, m.positions)
    q = cgogn.load(str(data / "surface" / "cube_quad.off"))
    assert q.triangulate() == 6 and q.nb_cells("face") == 12
    c = cgogn.load(str(data / "surface" / "cube_quad.off"))
    d = c.dual()
    assert (d.nb_cells("vertex"), d.nb_cells("face")) == (6, 8)
    ok(d)


def test_volume_subdivision(data):
    m = cgogn.load(str(data / "volume" / "liver_hex_624.mesh"))
    m.subdivide(1)
    assert m.nb_cells("volume") == 8 * 624
    ok(m)


def read_png_size_and_pixels(path):
    raw = open(path, "rb").read()
    assert raw[:8] == b"\x89PNG\r\n\x1a\n"
    w, h = struct.unpack(">II", raw[16:24])
    return w, h


def test_render(data, tmp_path):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    out = tmp_path / "spot.png"
    m.render(str(out), size=(320, 240), edges=True, color="area")
    assert read_png_size_and_pixels(out) == (320, 240)
    v = cgogn.load(str(data / "volume" / "liver_hex_624.mesh"))
    v.render(str(tmp_path / "liver.png"), size=(100, 80))
    assert read_png_size_and_pixels(tmp_path / "liver.png") == (100, 80)
    with pytest.raises(cgogn.RenderError):
        cgogn.CMap2().render(str(tmp_path / "empty.png"))
    assert not (tmp_path / "empty.png").exists()
    with pytest.raises(TypeError):
        m.render(str(out), colour="area")


def test_workers():
    n = cgogn.nb_workers()
    cgogn.set_nb_workers(1)
    assert cgogn.nb_workers() == 1
    cgogn.set_nb_workers(n)


def test_view_writes_a_self_contained_page(data, tmp_path):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    out = tmp_path / "spot.html"
    m.view(str(out), color="curvature", edges=True, title="spot")
    page = out.read_text()
    assert page.startswith("<!DOCTYPE html>") or page.lstrip().lower().startswith("<!doctype html>")
    assert "https://" not in page and "spot" in page
    v = cgogn.load(str(data / "volume" / "liver_hex_624.mesh"))
    v.view(str(tmp_path / "liver.html"))
    assert (tmp_path / "liver.html").stat().st_size > 100000
    with pytest.raises(cgogn.RenderError):
        cgogn.CMap2().view(str(tmp_path / "empty.html"))
    assert not (tmp_path / "empty.html").exists()


def test_render_range(data, tmp_path):
    m = cgogn.load(str(data / "surface" / "spot_control_mesh.obj"))
    m.render(str(tmp_path / "a.png"), size=(64, 48), color="area", range=(0.0, 1.0))
    with pytest.raises(cgogn.RenderError):
        m.render(str(tmp_path / "b.png"), size=(64, 48), color="area", range=(1.0, 0.0))
    assert not (tmp_path / "b.png").exists()
