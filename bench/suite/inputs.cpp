// SPDX-License-Identifier: MIT
#include "inputs.h"

#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/surface.h>
#include <cgogn/io/volume.h>

#include "cgogn_test_data.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <random>
#include <stdexcept>
#include <unordered_map>

namespace cgogn_bench
{

namespace
{

std::string input_kind;
uint32_t permutation_seed = 0;
bool reorder_on = false;

// vertex ids and cell order permuted: SOUP is a SurfaceSoup or a VolumeSoup
template <typename SOUP>
SOUP permute_cells(const SOUP& s, const std::vector<uint32_t>& sizes, const std::vector<uint32_t>& vertices,
				   uint32_t seed, std::vector<uint32_t>& out_sizes, std::vector<uint32_t>& out_vertices)
{
	std::mt19937 rng(seed);
	std::vector<uint32_t> new_id(s.nb_vertices);
	std::iota(new_id.begin(), new_id.end(), 0u);
	std::shuffle(new_id.begin(), new_id.end(), rng);
	std::vector<uint32_t> offset(sizes.size() + 1, 0);
	for (std::size_t f = 0; f < sizes.size(); ++f)
		offset[f + 1] = offset[f] + sizes[f];
	std::vector<uint32_t> order(sizes.size());
	std::iota(order.begin(), order.end(), 0u);
	std::shuffle(order.begin(), order.end(), rng);
	SOUP r;
	r.nb_vertices = s.nb_vertices;
	r.positions.resize(s.nb_vertices);
	for (uint32_t v = 0; v < s.nb_vertices; ++v)
		r.positions[new_id[v]] = s.positions[v];
	out_sizes.reserve(sizes.size());
	out_vertices.reserve(vertices.size());
	for (uint32_t f : order)
	{
		out_sizes.push_back(sizes[f]);
		for (uint32_t k = offset[f]; k < offset[f + 1]; ++k)
			out_vertices.push_back(new_id[vertices[k]]);
	}
	return r;
}

std::string data_path(const char* rel)
{
	return cgogn_test_data::path(rel);
}

bool data_present()
{
	return std::filesystem::exists(data_path("surface/nefertiti.obj")) &&
		   std::filesystem::exists(data_path("volume/armadillo_tet_461k.mesh"));
}

const std::string& kind()
{
	if (input_kind.empty())
		input_kind = data_present() ? "data" : "generated";
	return input_kind;
}

} // namespace

void set_input(const std::string& k)
{
	if (k != "data" && k != "data-unrefined" && k != "generated" && k != "small")
		throw std::runtime_error("--input must be data, data-unrefined, generated or small");
	if ((k == "data" || k == "data-unrefined") && !data_present())
		throw std::runtime_error("--input=data: " + cgogn_test_data::missing_large("surface/nefertiti.obj") +
								 " (and volume/armadillo_tet_461k.mesh)");
	input_kind = k;
}

void set_permutation_seed(uint32_t seed)
{
	permutation_seed = seed;
}

cgogn::SurfaceSoup permute_soup(const cgogn::SurfaceSoup& s, uint32_t seed)
{
	std::vector<uint32_t> sizes, vertices;
	cgogn::SurfaceSoup r = permute_cells(s, s.face_sizes, s.face_vertices, seed, sizes, vertices);
	r.face_sizes = std::move(sizes);
	r.face_vertices = std::move(vertices);
	return r;
}

cgogn::VolumeSoup permute_soup(const cgogn::VolumeSoup& s, uint32_t seed)
{
	std::vector<uint32_t> sizes, vertices;
	cgogn::VolumeSoup r = permute_cells(s, s.cell_sizes, s.cell_vertices, seed, sizes, vertices);
	r.cell_sizes = std::move(sizes);
	r.cell_vertices = std::move(vertices);
	return r;
}

void set_reorder(bool on)
{
	reorder_on = on;
}

bool reorder_requested()
{
	return reorder_on;
}

std::string order_description()
{
	std::string d = permutation_seed != 0 ? "permuted (seed " + std::to_string(permutation_seed) + ")" : "file";
	return reorder_on ? d + ", cgogn reordered (morton)" : d;
}

namespace
{

// Soup vertex ids in the order of the vertex container (the file's order:
// the io layer gives file vertex i the line vertex_offset + i), positions copied.
template <typename MAP, typename SOUP>
std::vector<uint32_t> number_vertices(const MAP& m, SOUP& s, const std::string& path)
{
	using Vertex = typename cgogn::mesh_traits<MAP>::Vertex;
	const auto pos = cgogn::get_attribute<cgogn::Vec3, Vertex>(m, "position");
	if (!pos)
		throw std::runtime_error(path + ": no vertex positions");
	std::vector<uint32_t> id(cgogn::container_of<Vertex::ORBIT>(m).end_index(), cgogn::INVALID_INDEX);
	cgogn::foreach_cell(m, [&](Vertex v) {
		const cgogn::Vec3& p = cgogn::value<cgogn::Vec3>(m, *pos, v);
		id[cgogn::index_of(m, v)] = uint32_t(s.positions.size());
		s.positions.push_back({p[0], p[1], p[2]});
	});
	s.nb_vertices = uint32_t(s.positions.size());
	return id;
}

} // namespace

cgogn::SurfaceSoup load_surface_soup(const std::string& path)
{
	using Vertex = cgogn::CMap2::Vertex;
	using Face = cgogn::CMap2::Face;
	cgogn::CMap2 m;
	cgogn::io::load_surface(m, path);
	cgogn::SurfaceSoup s;
	const std::vector<uint32_t> id = number_vertices(m, s, path);
	// faces in dart order, i.e. the file's order; each from its first dart
	cgogn::foreach_cell(m, [&](Face f) {
		uint32_t n = 0;
		cgogn::foreach_incident_vertex(m, f, [&](Vertex v) {
			s.face_vertices.push_back(id[cgogn::index_of(m, v)]);
			++n;
		});
		s.face_sizes.push_back(n);
	});
	return s;
}

cgogn::VolumeSoup load_volume_soup(const std::string& path)
{
	using Vertex = cgogn::CMap3::Vertex;
	using Volume = cgogn::CMap3::Volume;
	cgogn::CMap3 m;
	cgogn::io::load_volume(m, path);
	cgogn::VolumeSoup s;
	const std::vector<uint32_t> id = number_vertices(m, s, path);
	auto vertex = [&](cgogn::Dart d) { return id[cgogn::index_of(m, Vertex(d))]; };
	cgogn::foreach_cell(m, [&](Volume w) {
		// a tet in the builder's (MEDIT) order: the face of w.dart in reverse
		// phi1 order, then the apex
		uint32_t nv = 0;
		cgogn::foreach_incident_vertex(m, w, [&](Vertex) { ++nv; });
		if (nv != 4)
			throw std::runtime_error(path + ": the benchmarks take tetrahedra only");
		const cgogn::Dart d = w.dart;
		const cgogn::Dart d1 = cgogn::phi_1(m, d), d2 = cgogn::phi_1(m, d1);
		const cgogn::Dart apex = cgogn::phi_1(m, cgogn::phi2(m, d));
		for (cgogn::Dart x : {d, d1, d2, apex})
			s.cell_vertices.push_back(vertex(x));
		s.cell_sizes.push_back(4);
	});
	return s;
}

const cgogn::SurfaceSoup& surface_soup()
{
	static const cgogn::SurfaceSoup soup = [] {
		cgogn::SurfaceSoup s;
		if (kind() == "data")
			s = refine_1_to_4(refine_1_to_4(load_surface_soup(data_path("surface/nefertiti.obj"))));
		else if (kind() == "data-unrefined")
			s = load_surface_soup(data_path("surface/nefertiti.obj"));
		else if (kind() == "small")
			s = cgogn::torus_soup(40, 30, true);
		else
			s = cgogn::torus_soup(1000, 800, true);
		return permutation_seed != 0 ? permute_soup(s, permutation_seed) : s;
	}();
	return soup;
}

const cgogn::VolumeSoup& volume_soup()
{
	static const cgogn::VolumeSoup soup = [] {
		cgogn::VolumeSoup s;
		if (kind() == "data" || kind() == "data-unrefined")
			s = load_volume_soup(data_path("volume/armadillo_tet_461k.mesh"));
		else if (kind() == "small")
			s = cgogn::tet_grid_soup(6, 5, 4);
		else
			s = cgogn::tet_grid_soup(55, 55, 55);
		orient_tets_positive(s);
		return permutation_seed != 0 ? permute_soup(s, permutation_seed) : s;
	}();
	return soup;
}

std::string input_description()
{
	const auto& s = surface_soup();
	const auto& v = volume_soup();
	std::string d = kind() == "data-unrefined" ? "surface: nefertiti.obj; volume: armadillo_tet_461k.mesh"
					: kind() == "data"
						? "surface: nefertiti.obj refined twice 1-to-4; volume: armadillo_tet_461k.mesh"
						: (kind() == "small" ? "small torus and tet grid"
											 : "surface: torus_soup(1000, 800); volume: tet_grid_soup(55, 55, 55)");
	if (permutation_seed != 0)
		d += "; vertex ids and cell order permuted with seed " + std::to_string(permutation_seed);
	if (reorder_on)
		d += "; cgogn maps reordered by reorder() with Morton keys";
	return d + " (surface V=" + std::to_string(s.nb_vertices) + " F=" + std::to_string(s.face_sizes.size()) +
		   "; volume V=" + std::to_string(v.nb_vertices) + " T=" + std::to_string(v.cell_sizes.size()) + ")";
}

cgogn::SurfaceSoup refine_1_to_4(const cgogn::SurfaceSoup& s)
{
	cgogn::SurfaceSoup r;
	r.positions = s.positions;
	std::unordered_map<uint64_t, uint32_t> mid;
	mid.reserve(s.face_vertices.size());
	auto midpoint = [&](uint32_t a, uint32_t b) {
		const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
		auto [it, inserted] = mid.try_emplace(key, uint32_t(r.positions.size()));
		if (inserted)
		{
			const auto& p = s.positions[a];
			const auto& q = s.positions[b];
			r.positions.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
		}
		return it->second;
	};
	std::size_t k = 0;
	for (uint32_t n : s.face_sizes)
	{
		if (n != 3)
			throw std::runtime_error("refine_1_to_4: triangles only");
		const uint32_t a = s.face_vertices[k], b = s.face_vertices[k + 1], c = s.face_vertices[k + 2];
		k += 3;
		const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
		for (uint32_t v : {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca})
			r.face_vertices.push_back(v);
		r.face_sizes.insert(r.face_sizes.end(), 4, 3u);
	}
	r.nb_vertices = uint32_t(r.positions.size());
	return r;
}

void orient_tets_positive(cgogn::VolumeSoup& s)
{
	std::size_t k = 0;
	for (uint32_t n : s.cell_sizes)
	{
		if (n == 4)
		{
			uint32_t* t = &s.cell_vertices[k];
			const auto& a = s.positions[t[0]];
			const auto& b = s.positions[t[1]];
			const auto& c = s.positions[t[2]];
			const auto& d = s.positions[t[3]];
			const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
			const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
			const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
			const double det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
							   u[2] * (v[0] * w[1] - v[1] * w[0]);
			if (det < 0)
				std::swap(t[1], t[2]);
		}
		k += n;
	}
}

std::vector<char*> take_input_options(int argc, char** argv)
{
	std::vector<char*> rest;
	for (int i = 0; i < argc; ++i)
	{
		if (std::strncmp(argv[i], "--input=", 8) == 0)
			set_input(argv[i] + 8);
		else if (std::strcmp(argv[i], "--reorder") == 0)
			set_reorder(true);
		else if (std::strncmp(argv[i], "--permute=", 10) == 0)
			set_permutation_seed(uint32_t(std::strtoul(argv[i] + 10, nullptr, 10)));
		else
			rest.push_back(argv[i]);
	}
	return rest;
}

} // namespace cgogn_bench
