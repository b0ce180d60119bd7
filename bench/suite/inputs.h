// SPDX-License-Identifier: MIT
#pragma once

// The inputs every library builds from: one surface soup and one tet soup,
// the same in-memory arrays (same vertex and face order) for all libraries.
//
// --input=data (default when CGOGN_LARGE_DATA_DIR holds the files): nefertiti.obj
//   refined twice by 1-to-4 midpoint subdivision (1,599,008 triangles) and
//   armadillo_tet_461k.mesh (tets re-oriented to positive volume).
// --input=data-unrefined: nefertiti.obj as it is (99,938 triangles) and
//   armadillo_tet_461k.mesh.
// --input=generated: torus_soup(1000, 800, true) (1,600,000 triangles) and
//   tet_grid_soup(55, 55, 55) (998,250 tets): runs without the data folder.
// --input=small: a small torus and tet grid (smoke test of the check values).

#include <cgogn/core/build/generators.h>

#include <string>
#include <vector>

namespace cgogn_bench
{

/// Selects the input ("data", "data-unrefined", "generated", "small"); call before the benchmarks run.
void set_input(const std::string& kind);
/// --permute=SEED: the soups' vertex ids and face (cell) order are randomly
/// permuted (std::mt19937 with this seed) before any library builds from it:
/// badly ordered files are what users load, and order dominates traversal cost.
void set_permutation_seed(uint32_t seed);
/// --reorder: cgogn's maps are reordered after building (core reorder() with
/// Morton keys, see cgogn_reorder.h); the peers are not affected.
void set_reorder(bool on);

/// Applies the input options of the benchmark programs (--input=,
/// --reorder, --permute=) and returns the other arguments, argv[0] first,
/// for benchmark::Initialize. Throws std::runtime_error on a bad value.
std::vector<char*> take_input_options(int argc, char** argv);
bool reorder_requested();
/// Returns s with vertex ids and face order permuted (same mesh).
cgogn::SurfaceSoup permute_soup(const cgogn::SurfaceSoup& s, uint32_t seed);
/// Returns s with vertex ids and cell order permuted (same mesh).
cgogn::VolumeSoup permute_soup(const cgogn::VolumeSoup& s, uint32_t seed);
/// The input order variant, for the benchmark context "order": "file",
/// "permuted (seed N)", each followed by ", cgogn reordered (morton)" with --reorder.
std::string order_description();
/// What the inputs are, for the benchmark context (e.g. "nefertiti.obj x2 refined: V=..., F=...").
std::string input_description();

/// The surface soup (closed triangle mesh), loaded or generated once.
const cgogn::SurfaceSoup& surface_soup();
/// The tet soup, loaded or generated once; every tet positively oriented.
const cgogn::VolumeSoup& volume_soup();

/// 1-to-4 midpoint subdivision of a triangle soup: vertices first, then one
/// new vertex per edge in order of first appearance.
cgogn::SurfaceSoup refine_1_to_4(const cgogn::SurfaceSoup& s);
/// Swaps two vertices of every tet of negative signed volume.
void orient_tets_positive(cgogn::VolumeSoup& s);

/// The polygon soup of a surface file: read once by cgogn::io::load_surface
/// into a CMap2, then extracted (vertices in file order, faces in file order,
/// each from its first vertex). Throws cgogn::io::Error when the file cannot be
/// read.
cgogn::SurfaceSoup load_surface_soup(const std::string& path);
/// The tets of a volume file: read by cgogn::io::load_volume into a CMap3 (which
/// turns negatively oriented cells over), then extracted in the builder's
/// vertex order. Throws on cells that are not tetrahedra.
cgogn::VolumeSoup load_volume_soup(const std::string& path);

} // namespace cgogn_bench
