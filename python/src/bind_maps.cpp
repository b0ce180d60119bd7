// SPDX-License-Identifier: MIT
// The map classes: construction, files, counts, positions, faces and cells,
// incidence relations as CSR arrays, compaction and integrity.
#include <cgogn/io.h>

#include "py_map.h"
#include "py_nmap.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <numeric>
#include <optional>
#include <pybind11/stl.h>

namespace cgogn::python
{

Kind kind_of(const std::string& name)
{
	if (name == "vertex" || name == "vertices")
		return Kind::Vertex;
	if (name == "edge" || name == "edges")
		return Kind::Edge;
	if (name == "face" || name == "faces")
		return Kind::Face;
	if (name == "volume" || name == "volumes")
		return Kind::Volume;
	if (name == "corner" || name == "corners")
		return Kind::Corner;
	throw py::value_error("unknown cell kind '" + name +
						  "': use \"vertex\", \"edge\", \"face\", \"volume\" or \"corner\"");
}

const char* kind_name(Kind k)
{
	switch (k)
	{
	case Kind::Vertex:
		return "vertex";
	case Kind::Edge:
		return "edge";
	case Kind::Face:
		return "face";
	case Kind::Corner:
		return "corner";
	default:
		return "volume";
	}
}

py::tuple csr(std::vector<uint32>&& offsets, std::vector<uint32>&& indices)
{
	return py::make_tuple(to_numpy(std::move(offsets)), to_numpy(std::move(indices)));
}

namespace
{

// ---- reading arrays

std::vector<std::array<double, 3>> read_points(const py::array& points)
{
	auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
	if (!p || p.ndim() != 2 || p.shape(1) != 3)
		throw py::value_error("points must be an (N, 3) array of numbers");
	std::vector<std::array<double, 3>> out(std::size_t(p.shape(0)));
	const double* d = p.data();
	for (std::size_t i = 0; i < out.size(); ++i)
	{
		out[i] = {d[3 * i], d[3 * i + 1], d[3 * i + 2]};
		if (!std::isfinite(out[i][0]) || !std::isfinite(out[i][1]) || !std::isfinite(out[i][2]))
			throw py::value_error("point " + std::to_string(i) + " is not finite");
	}
	return out;
}

std::vector<uint32> read_ids(const py::array& a, const char* what)
{
	auto v = py::array_t<int64, py::array::c_style | py::array::forcecast>::ensure(a);
	if (!v)
		throw py::value_error(std::string(what) + " must be an integer array");
	std::vector<uint32> out(std::size_t(v.size()));
	const int64* d = v.data();
	for (std::size_t i = 0; i < out.size(); ++i)
	{
		if (d[i] < 0 || d[i] >= int64(INVALID_INDEX))
			throw py::value_error(std::string(what) + " holds the id " + std::to_string(d[i]) + ", out of range");
		out[i] = uint32(d[i]);
	}
	return out;
}

// Cells given as an (F, k) array or an (offsets, indices) pair: sizes and ids.
void read_cells(const py::object& cells, std::vector<uint32>& sizes, std::vector<uint32>& ids)
{
	if (py::isinstance<py::tuple>(cells) || py::isinstance<py::list>(cells))
	{
		py::sequence s = cells;
		if (py::len(s) != 2)
			throw py::value_error("cells must be an (F, k) array or an (offsets, indices) pair");
		const std::vector<uint32> offsets = read_ids(py::array::ensure(s[0]), "offsets");
		ids = read_ids(py::array::ensure(s[1]), "indices");
		if (offsets.empty() || offsets.front() != 0 || offsets.back() != ids.size())
			throw py::value_error("offsets must start at 0 and end at len(indices)");
		for (std::size_t i = 0; i + 1 < offsets.size(); ++i)
		{
			if (offsets[i + 1] < offsets[i])
				throw py::value_error("offsets must not decrease");
			sizes.push_back(offsets[i + 1] - offsets[i]);
		}
		return;
	}
	py::array a = py::array::ensure(cells);
	if (!a || a.ndim() != 2)
		throw py::value_error("cells must be an (F, k) array or an (offsets, indices) pair");
	ids = read_ids(a, "cells");
	sizes.assign(std::size_t(a.shape(0)), uint32(a.shape(1)));
}

// ---- what both map types offer

template <typename MAP>
uint32 count(const MAP& m, Kind k)
{
	return with_kind<MAP>(k, [&]<typename CELL>() { return nb_cells<CELL>(m); });
}

// The ids of the live cells of kind k, in traversal order.
template <typename MAP>
py::array_t<uint32> cell_ids(MAP& m, Kind k)
{
	ensure_indexed(m, k);
	return with_kind<MAP>(k, [&]<typename CELL>() {
		std::vector<uint32> ids;
		ids.reserve(nb_cells<CELL>(m));
		foreach_cell(m, [&](CELL c) { ids.push_back(index_of(m, c)); });
		return to_numpy(std::move(ids));
	});
}

// Calls f(TO) for each cell of type TO incident to (or, for the same type,
// adjacent to) c: the map's local traversals.
template <typename TO, typename MAP, typename FROM, typename F>
void foreach_related(const MAP& m, FROM c, const F& f)
{
	using T = mesh_traits<MAP>;
	if constexpr (std::is_same_v<TO, typename T::Vertex>)
	{
		if constexpr (std::is_same_v<FROM, TO>)
			foreach_adjacent_vertex_through_edge(m, c, f);
		else
			foreach_incident_vertex(m, c, f);
	}
	else if constexpr (std::is_same_v<TO, typename T::Edge>)
	{
		if constexpr (std::is_same_v<FROM, TO>)
			foreach_adjacent_edge_through_vertex(m, c, f);
		else
			foreach_incident_edge(m, c, f);
	}
	else if constexpr (std::is_same_v<TO, typename T::Face>)
	{
		if constexpr (std::is_same_v<FROM, TO>)
			foreach_adjacent_face_through_edge(m, c, f);
		else
			foreach_incident_face(m, c, f);
	}
	else
	{
		if constexpr (std::is_same_v<FROM, TO>)
			foreach_adjacent_volume_through_face(m, c, f);
		else
			foreach_incident_volume(m, c, f);
	}
}

// CSR of the relation from -> to: one row per live `from` cell in traversal
// order, holding the ids of the related `to` cells in the map's local order.
/// ValueError for relations with corners (see corners_csr).
inline void refuse_corner_relations(Kind from, Kind to)
{
	if (from == Kind::Corner || to == Kind::Corner)
		throw py::value_error("corners have no incidence relations: corners_csr() gives the corners of each face");
}

template <typename MAP>
py::tuple incidence(MAP& m, Kind from, Kind to)
{
	if (MAP::dimension == 2 && (from == Kind::Volume || to == Kind::Volume))
		throw py::value_error("a surface has no volume relations");
	refuse_corner_relations(from, to);
	ensure_indexed(m, from);
	ensure_indexed(m, to);
	return with_kind<MAP>(from, [&]<typename FROM>() {
		std::vector<uint32> offsets{0}, indices;
		offsets.reserve(nb_cells<FROM>(m) + 1);
		with_kind<MAP>(to, [&]<typename TO>() {
			if constexpr (FROM::ORBIT != Orbit::DART && TO::ORBIT != Orbit::DART &&
						  (MAP::dimension == 3 || (!std::is_same_v<FROM, typename mesh_traits<MAP>::Volume> &&
												   !std::is_same_v<TO, typename mesh_traits<MAP>::Volume>)))
				foreach_cell(m, [&](FROM c) {
					foreach_related<TO>(m, c, [&](TO x) { indices.push_back(index_of(m, x)); });
					offsets.push_back(uint32(indices.size()));
				});
		});
		return csr(std::move(offsets), std::move(indices));
	});
}

// A face is walked by the geometry layer's oriented step (phi1; beta1 o beta0
// on a G-map, in the orientation of the face's dart), which serves both models.
using geometry::oriented_phi1;

// Calls f(dart) on one dart of every face (boundary faces excluded), in
// traversal order (see foreach_cell): the face container's line order when
// faces are indexed (always on a G-map); otherwise the order of the smallest
// dart of each face,
// found without the marks foreach_cell needs (a face starts at a dart whose
// phi1 cycle holds no smaller dart), which is several times faster on a
// freshly loaded surface.
template <typename MAP, typename F>
void foreach_face_dart(const MAP& m, const F& f)
{
	using Face = typename mesh_traits<MAP>::Face;
	if constexpr (MAP::dimension == 3 || is_gmap_v<MAP>)
		foreach_cell(m, [&](Face x) { return f(x.dart); });
	else
	{
		if (is_indexed<Face>(m))
		{
			foreach_cell(m, [&](Face x) { return f(x.dart); });
			return;
		}
		foreach_dart(m, [&](Dart d) {
			if (is_boundary(m, d))
				return true;
			for (Dart x = phi1(m, d); x != d; x = phi1(m, x))
				if (x.index < d.index)
					return true;
			return f(d);
		});
	}
}

// The vertex ids of the faces (surfaces) or of the boundary faces (volumes).
template <typename MAP>
py::tuple faces_csr(MAP& m, bool corners = false)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	std::vector<uint32> offsets{0}, indices;
	indices.reserve(nb_darts(m));
	foreach_face_dart(m, [&](const Dart first) {
		if constexpr (MAP::dimension == 3)
		{
			if (!is_incident_to_boundary(m, typename mesh_traits<MAP>::Face(first)))
				return true; // an inner face
		}
		Dart d = first;
		do
		{
			indices.push_back(corners ? d.index : index_of(m, Vertex(d)));
			d = oriented_phi1(m, d);
		} while (d != first);
		offsets.push_back(uint32(indices.size()));
		return true;
	});
	return csr(std::move(offsets), std::move(indices));
}

// What triangle_rows returns when a face of its range is not a triangle, and
// when the rows of its range do not fit in the room given.
constexpr uint32 NOT_A_TRIANGLE = INVALID_INDEX;
constexpr uint32 NO_ROOM = INVALID_INDEX - 1;

// Counts (out == nullptr) or writes to `out` the rows of the triangles whose
// smallest dart lies in [begin, end), in dart order: each triangle once, found
// at its smallest dart without marks (the order foreach_cell uses when faces
// are not indexed). Returns the number of rows, or NOT_A_TRIANGLE, or NO_ROOM
// when writing and there are more than `room` rows. Precondition: vertices
// are indexed.
// phi1 and the vertex indices are read through views, which keep their
// addresses in registers for the whole loop (see LineStorage::View): through
// phi1(m, d) and index_of the compiler reloads them at every dart, since the
// rows written may alias them as far as it knows.
uint32 triangle_rows(const CMap2& m, uint32 begin, uint32 end, uint32* out, uint32 room)
{
	const AttributeContainer& darts = container_of<Orbit::DART>(m);
	const auto phi1_of = darts.key().view(); // phi1 is the key of the darts
	const auto vertex_of = container_of<CMap2::Vertex::ORBIT>(m).cell_index()->view();
	const uint32 lines = darts.end_index();
	uint32 rows = 0;
	for (uint32 i = begin; i < end; ++i)
	{
		const uint32 d = i;
		uint32 e = d + 1, g = d + 2;
		// The builder gives each face consecutive darts: that case is tested
		// first, and steps over the whole triangle (d is then its smallest
		// dart, and the other two are the smallest of no face).
		if (g < lines && phi1_of[d] == e && phi1_of[e] == g && phi1_of[g] == d)
		{
			i = g;
			if (is_boundary(m, Dart(d)))
				continue;
		}
		else
		{
			e = phi1_of[d];
			if (e == INVALID_INDEX || e < d) // a free line, or not the smallest dart of its face
				continue;
			g = phi1_of[e];
			if (g < d || is_boundary(m, Dart(d)))
				continue;
			if (e == d || phi1_of[g] != d) // a face of 1, 2 or more than 3 edges
				return NOT_A_TRIANGLE;
		}
		if (out != nullptr)
		{
			if (rows == room)
				return NO_ROOM;
			uint32* row = out + 3 * std::size_t(rows);
			row[0] = vertex_of[d];
			row[1] = vertex_of[e];
			row[2] = vertex_of[g];
		}
		++rows;
	}
	return rows;
}

// The (F, 3) rows of a surface whose faces are not indexed and whose vertices
// are, or nothing when a face is not a triangle.
//
// The dart lines are cut into one range per worker of the pool, at multiples
// of 3, and the ranges are scanned in parallel without the GIL, each writing
// its rows into its own part of one buffer of 1 value per dart line (3 values
// per triangle of 3 darts: all the rows fit): range [b, e) gets the values
// [b, e). The parts are then moved together and the buffer shrunk in place.
// The darts of a loaded surface are the faces' darts in file order, so every
// range's rows fit its part. When they do not (an edited map whose faces
// reach beyond their range), a second try counts each range's rows first and
// writes them at their exact offsets.
std::optional<py::array_t<uint32>> unindexed_triangles(const CMap2& m)
{
	const uint32 end = container_of<Orbit::DART>(m).end_index();
	const uint32 parts = end < (1u << 16) || detail::run_sequentially() ? 1u : thread_pool()->nb_workers();
	const auto cut = [&](uint32 k) { return k == parts ? end : uint32(uint64(end) * k / parts / 3 * 3); };
	const auto for_each_range = [&](const auto& body) {
		py::gil_scoped_release release;
		if (parts == 1)
			body(0u);
		else
			detail::parallel_for_chunks(parts, 1, detail::ChunkBody([&](uint32 kb, uint32 ke) {
											for (uint32 k = kb; k < ke; ++k)
												body(k);
										}));
	};
	const auto has = [](const std::vector<uint32>& rows, uint32 v) {
		return std::find(rows.begin(), rows.end(), v) != rows.end();
	};

	std::vector<uint32> rows(parts + 1, 0); // rows[k + 1]: the rows of range k
	std::unique_ptr<uint32, decltype(&std::free)> buffer(
		static_cast<uint32*>(std::malloc(std::max<std::size_t>(end, 1) * sizeof(uint32))), &std::free);
	if (!buffer)
		throw std::bad_alloc();
	for_each_range([&](uint32 k) {
		const uint32 b = cut(k), e = cut(k + 1);
		rows[k + 1] = triangle_rows(m, b, e, buffer.get() + b, (e - b) / 3);
	});
	if (has(rows, NOT_A_TRIANGLE))
		return std::nullopt;
	if (!has(rows, NO_ROOM))
	{
		std::size_t size = 0;
		for (uint32 k = 0; k < parts; ++k)
		{
			const std::size_t values = 3 * std::size_t(rows[k + 1]);
			std::memmove(buffer.get() + size, buffer.get() + cut(k), values * sizeof(uint32));
			size += values;
		}
		// realloc shrinks a large block where it is, giving the tail back
		if (auto* shrunk =
				static_cast<uint32*>(std::realloc(buffer.get(), std::max<std::size_t>(size, 1) * sizeof(uint32))))
		{
			(void)buffer.release();
			buffer.reset(shrunk);
		}
		uint32* const data = buffer.get();
		py::capsule owner(data, [](void* p) { std::free(p); });
		(void)buffer.release(); // the capsule owns it now
		return py::array_t<uint32>({py::ssize_t(size / 3), py::ssize_t(3)},
								   {py::ssize_t(3 * sizeof(uint32)), py::ssize_t(sizeof(uint32))}, data, owner);
	}
	buffer.reset();

	for_each_range([&](uint32 k) { rows[k + 1] = triangle_rows(m, cut(k), cut(k + 1), nullptr, 0); });
	std::partial_sum(rows.begin(), rows.end(), rows.begin());
	py::array_t<uint32> result({py::ssize_t(rows[parts]), py::ssize_t(3)});
	uint32* const out = result.mutable_data();
	for_each_range(
		[&](uint32 k) { triangle_rows(m, cut(k), cut(k + 1), out + 3 * std::size_t(rows[k]), rows[k + 1] - rows[k]); });
	return result;
}

// The triangle rows of the faces foreach_face_dart visits (surfaces), or of
// the boundary faces (volumes), or nothing when one of them is not a triangle.
template <typename MAP>
std::optional<std::vector<uint32>> walked_triangles(const MAP& m)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	std::vector<uint32> out;
	out.reserve(nb_darts(m));
	bool polygons = false;
	foreach_face_dart(m, [&](const Dart d) {
		const Dart e = oriented_phi1(m, d), g = oriented_phi1(m, e);
		if (e == d || oriented_phi1(m, g) != d)
		{
			polygons = true;
			return false;
		}
		if constexpr (MAP::dimension == 3)
			if (!is_incident_to_boundary(m, typename mesh_traits<MAP>::Face(d)))
				return true;
		out.insert(out.end(), {index_of(m, Vertex(d)), index_of(m, Vertex(e)), index_of(m, Vertex(g))});
		return true;
	});
	if (polygons)
		return std::nullopt;
	return out;
}

constexpr const char* NOT_TRIANGLES = "the mesh has faces that are not triangles: use faces_csr()";

// (F, 3) array when every face is a triangle.
template <typename MAP>
py::array_t<uint32> triangles(MAP& m)
{
	if constexpr (MAP::dimension == 2 && !is_gmap_v<MAP>)
	{
		using Face = typename mesh_traits<MAP>::Face;
		using Vertex = typename mesh_traits<MAP>::Vertex;
		if (!is_indexed<Face>(m) && is_indexed<Vertex>(m))
		{
			if (auto rows = unindexed_triangles(m))
				return *std::move(rows);
			throw py::value_error(NOT_TRIANGLES);
		}
	}
	std::optional<std::vector<uint32>> rows = walked_triangles(m);
	if (!rows)
		throw py::value_error(NOT_TRIANGLES);
	const py::ssize_t nb_rows = py::ssize_t(rows->size() / 3);
	auto* heap = new std::vector<uint32>(std::move(*rows));
	py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<uint32>*>(p); });
	return py::array_t<uint32>({nb_rows, py::ssize_t(3)},
							   {py::ssize_t(3 * sizeof(uint32)), py::ssize_t(sizeof(uint32))}, heap->data(), owner);
}

template <typename MAP>
void bind_common(py::class_<PyMap<MAP>>& c)
{
	using W = PyMap<MAP>;
	c.def(py::init<>(), "An empty map (with a `position` vertex attribute).")
		.def_property_readonly_static("dimension", [](py::object) { return MAP::dimension; })
		.def(
			"nb_cells", [](W& w, const std::string& kind) { return count(w.m, kind_of(kind)); }, py::arg("kind"),
			"Number of cells of a kind (\"vertex\", \"edge\", \"face\", \"volume\"), boundary cells excluded. "
			"O(1) when the kind is indexed, O(darts) otherwise.")
		.def(
			"nb_darts", [](W& w) { return nb_darts(w.m); }, "Number of darts, boundary darts included.")
		.def(
			"euler_characteristic",
			[](W& w) {
				int64 chi =
					int64(count(w.m, Kind::Vertex)) - int64(count(w.m, Kind::Edge)) + int64(count(w.m, Kind::Face));
				if constexpr (MAP::dimension == 3)
					chi -= int64(count(w.m, Kind::Volume));
				return chi;
			},
			"V - E + F (- W for volumes), boundary cells excluded. O(darts).")
		.def(
			"nb_connected_components", [](W& w) { return nb_connected_components(w.m); },
			"Number of connected components. O(darts).")
		.def(
			"cell_ids", [](W& w, const std::string& kind) { return cell_ids(w.m, kind_of(kind)); }, py::arg("kind"),
			"The ids of the live cells of a kind, in traversal order (0..n-1 on a compact map). Indexes the kind "
			"if it is not.")
		.def(
			"id_bound", [](W& w, const std::string& kind) { return id_bound(w.m, kind_of(kind)); }, py::arg("kind"),
			"One past the largest cell id of a kind: the number of rows of its attribute arrays.")
		.def(
			"is_compact",
			[](W& w, const std::string& kind) {
				const Kind k = kind_of(kind);
				ensure_indexed(w.m, k);
				return count(w.m, k) == id_bound(w.m, k);
			},
			py::arg("kind"), "True when the ids of a kind are exactly 0..nb_cells-1.")
		.def_property(
			"positions",
			[](W& w) {
				return attribute_array(w.pos, container_of<mesh_traits<MAP>::Vertex::ORBIT>(w.m).end_index(), w.views);
			},
			[](W& w, const py::array& values) {
				assign_attribute(*w.pos, container_of<mesh_traits<MAP>::Vertex::ORBIT>(w.m).end_index(), values);
			},
			"Vertex positions, an (id_bound('vertex'), 3) float64 array indexed by vertex id. It aliases the "
			"map's memory (writes are seen by every algorithm) unless the map has more than 2^28 vertex ids, "
			"where it is a read-only copy. Rows of removed vertices hold stale values. Assigning an array "
			"copies it in.")
		.def(
			"faces_csr", [](W& w) { return faces_csr(w.m); },
			MAP::dimension == 2 ? "(offsets, indices): the vertex ids of every face, in traversal order (face k is "
								  "face id k on a compact map). O(darts)."
								: "(offsets, indices): the vertex ids of every boundary face, seen from outside.")
		.def(
			"corners_csr", [](W& w) { return faces_csr(w.m, true); },
			"(offsets, indices): the corner ids of every face, in the order of faces_csr() (corner k of face f "
			"is at vertex k of face f): the rows of 'corner' attributes such as texture coordinates. O(darts).")
		.def(
			"faces", [](W& w) { return triangles(w.m); },
			MAP::dimension == 2 ? "(F, 3) uint32 array of the vertex ids of the triangles; ValueError when a face "
								  "is not a triangle."
								: "(F, 3) vertex ids of the boundary triangles; ValueError when a face is not a "
								  "triangle.")
		.def(
			"incidence",
			[](W& w, const std::string& from, const std::string& to) {
				return incidence(w.m, kind_of(from), kind_of(to));
			},
			py::arg("source"), py::arg("target"),
			"(offsets, indices): for each live cell of kind `source`, in traversal order (see cell_ids), the ids "
			"of the cells of kind `target` incident to it, or adjacent to it when both kinds are the same "
			"(vertices through edges, edges through vertices, faces through edges, volumes through faces). "
			"Indexes both kinds. O(darts).")
		.def(
			"incident",
			[](W& w, const std::string& source, int64 id, const std::string& target) {
				const Kind from = kind_of(source), to = kind_of(target);
				if (MAP::dimension == 2 && (from == Kind::Volume || to == Kind::Volume))
					throw py::value_error("a surface has no volume relations");
				refuse_corner_relations(from, to);
				ensure_indexed(w.m, from);
				ensure_indexed(w.m, to);
				std::vector<uint32> out;
				with_kind<MAP>(from, [&]<typename FROM>() {
					const AttributeContainer& c = container_of<FROM::ORBIT>(w.m);
					if (id < 0 || id >= int64(c.end_index()) || !c.is_live(uint32(id)))
						throw py::index_error("no live " + std::string(kind_name(from)) + " with id " +
											  std::to_string(id));
					const FROM cell{Dart(c.key()[uint32(id)])};
					with_kind<MAP>(to, [&]<typename TO>() {
						if constexpr (FROM::ORBIT != Orbit::DART && TO::ORBIT != Orbit::DART &&
									  (MAP::dimension == 3 ||
									   (!std::is_same_v<FROM, typename mesh_traits<MAP>::Volume> &&
										!std::is_same_v<TO, typename mesh_traits<MAP>::Volume>)))
							foreach_related<TO>(w.m, cell, [&](TO x) { out.push_back(index_of(w.m, x)); });
					});
				});
				return out;
			},
			py::arg("source"), py::arg("id"), py::arg("target"),
			"The ids of the cells of kind `target` incident to (or adjacent to, for the same kind) the cell `id` "
			"of kind `source`, as a list: one row of incidence(), for walking a small mesh cell by cell. "
			"O(size of the neighbourhood).")
		.def(
			"compact",
			[](W& w) {
				w.refuse_while_aliased("compact");
				compact(w.m);
			},
			"Renumbers darts and the cells of every indexed kind densely (ids 0..n-1, order kept). Refused "
			"(RuntimeError) while a NumPy array aliases the map's attributes. O(darts + cells x attributes).")
		.def(
			"check_integrity", [](W& w) { return integrity_report(check_integrity(w.m)); },
			"Checks every invariant of the map; returns {'ok': bool, 'nb_errors': int, 'messages': [str]}.")
		.def("__repr__", [](W& w) {
			std::string s =
				std::string("<cgogn.") + (is_gmap_v<MAP> ? "GMap" : "CMap") + (MAP::dimension == 2 ? "2" : "3");
			s += " vertices=" + std::to_string(count(w.m, Kind::Vertex));
			s += " edges=" + std::to_string(count(w.m, Kind::Edge));
			s += " faces=" + std::to_string(count(w.m, Kind::Face));
			if constexpr (MAP::dimension == 3)
				s += " volumes=" + std::to_string(count(w.m, Kind::Volume));
			return s + ">";
		});
}

template <typename MAP>
std::unique_ptr<PyMap<MAP>> from_arrays(const py::array& points, const py::object& cells)
{
	const auto p = read_points(points);
	std::vector<uint32> sizes, ids;
	read_cells(cells, sizes, ids);
	for (uint32 id : ids)
		if (id >= p.size())
			throw py::value_error("a cell refers to point " + std::to_string(id) + ", but there are " +
								  std::to_string(p.size()) + " points");
	auto w = std::make_unique<PyMap<MAP>>();
	BuildReport r;
	{
		py::gil_scoped_release release;
		if constexpr (MAP::dimension == 2)
			r = build_surface(w->m, uint32(p.size()), sizes, ids);
		else
			r = build_volume(w->m, uint32(p.size()), sizes, ids);
		for (std::size_t i = 0; i < p.size(); ++i)
			if (container_of<mesh_traits<MAP>::Vertex::ORBIT>(w->m).is_live(r.vertex_offset + uint32(i)))
				(*w->pos)[r.vertex_offset + uint32(i)] = Vec3(p[i][0], p[i][1], p[i][2]);
		for (auto [line, original] : r.split_vertices)
			(*w->pos)[line] = Vec3(p[original][0], p[original][1], p[original][2]);
	}
	if (r.nb_cells_invalid > 0)
		throw py::value_error(std::to_string(r.nb_cells_invalid) + " cell(s) are of a size the map cannot build");
	return w;
}

template <typename MAP>
std::unique_ptr<PyMap<MAP>> load_into(const std::string& path, const io::LoadReport** report_out = nullptr)
{
	(void)report_out;
	auto w = std::make_unique<PyMap<MAP>>();
	{
		py::gil_scoped_release release;
		if constexpr (MAP::dimension == 2)
			io::load_surface(w->m, path);
		else
			io::load_volume(w->m, path);
	}
	w->ensure_position();
	return w;
}

// A map wrapped from a converted one: the conversion's map, its positions.
template <typename MAP>
std::unique_ptr<PyMap<MAP>> wrapped(MAP&& m)
{
	auto w = std::make_unique<PyMap<MAP>>();
	w->m = std::move(m);
	w->ensure_position();
	return w;
}

// is_orientable, to_gmap and to_cmap on a pair of map classes.
template <typename CMAP, typename GMAP>
void bind_conversions(py::class_<PyMap<CMAP>>& c, py::class_<PyMap<GMAP>>& g)
{
	c.def(
		"to_gmap", [](PyMap<CMAP>& w) { return wrapped(to_gmap(w.m)); },
		"The generalized map of this map (twice the darts), with every attribute; the same vertex ids on a "
		"compact map. O(darts x attributes).");
	g.def(
		 "is_orientable", [](PyMap<GMAP>& w) { return is_orientable(w.m); },
		 "True when every connected component can be oriented (two-colouring of the darts). O(darts).")
		.def(
			"to_cmap", [](PyMap<GMAP>& w) { return wrapped(to_cmap(w.m)); },
			"The oriented map of an orientable G-map, with every attribute; raises cgogn.Error when the map is "
			"not orientable. O(darts x attributes).");
}

bool is_volume_format(io::Format f)
{
	return f == io::Format::Medit || f == io::Format::VtkLegacy || f == io::Format::Vtu || f == io::Format::Gmsh ||
		   f == io::Format::TetGen || f == io::Format::Ovm || f == io::Format::Pvtu;
}

// Every format but the volume-only ones (node/ele, ovm).
bool holds_surfaces(io::Format f)
{
	return f != io::Format::TetGen && f != io::Format::Ovm;
}

} // namespace

void bind_maps(py::module_& mod)
{
	py::class_<Surface> surface(mod, "CMap2", "A surface: an oriented 2-map of polygons, closed by boundary faces.");
	bind_common(surface);
	surface
		.def_static(
			"from_arrays",
			[](const py::array& points, const py::object& faces) { return from_arrays<CMap2>(points, faces); },
			py::arg("points"), py::arg("faces"),
			"A surface from (N, 3) points and faces: an (F, k) integer array or an (offsets, indices) pair. "
			"Vertex id i is point i unless the builder repaired the input (non-manifold vertices split: their "
			"copies get new ids after the others; unused points: their ids are free). O(total size).")
		.def(
			"save",
			[](Surface& w, const std::string& path, bool binary) {
				py::gil_scoped_release release;
				if (has_map_file_extension(path))
				{
					io::save_map(w.m, path);
					return;
				}
				io::SaveOptions o;
				o.binary = binary;
				io::save_surface(w.m, path, o);
			},
			py::arg("path"), py::arg("binary") = false,
			"Writes the surface in the format of the extension (off, obj, ply, stl, msh, mesh, vtk, vtu; binary "
			"for ply, stl, msh, vtk and vtu), or "
			"the whole map to a .cgmap file (every attribute; cgogn.load reads it back). Raises cgogn.IOError on "
			"failure.");

	py::class_<VolumeMesh> volume(mod, "CMap3",
								  "A volume mesh: an oriented 3-map of polyhedra, closed by boundary volumes.");
	bind_common(volume);
	volume
		.def_static(
			"from_arrays",
			[](const py::array& points, const py::object& cells) { return from_arrays<CMap3>(points, cells); },
			py::arg("points"), py::arg("cells"),
			"A volume mesh from (N, 3) points and cells: an (C, k) integer array or an (offsets, indices) pair; "
			"4 ids make a tetrahedron, 5 a pyramid, 6 a prism, 8 a hexahedron (VTK order).")
		.def(
			"cells_csr",
			[](VolumeMesh& w) {
				CMap3& m = w.m;
				std::vector<uint32> offsets{0}, indices;
				foreach_cell(m, [&](CMap3::Volume v) {
					foreach_incident_vertex(m, v, [&](CMap3::Vertex x) { indices.push_back(index_of(m, x)); });
					offsets.push_back(uint32(indices.size()));
				});
				return csr(std::move(offsets), std::move(indices));
			},
			"(offsets, indices): the vertex ids of every volume, in traversal order (the order of the map's "
			"incident-vertex traversal, not a VTK cell order).")
		.def(
			"cells",
			[](VolumeMesh& w) {
				CMap3& m = w.m;
				std::vector<uint32> out;
				bool tets = true;
				foreach_cell(m, [&](CMap3::Volume v) {
					const Dart d = v.dart;
					const Dart e = phi1(m, d), g = phi1(m, e), h = phi_1(m, phi2(m, d));
					out.insert(out.end(), {index_of(m, CMap3::Vertex(d)), index_of(m, CMap3::Vertex(g)),
										   index_of(m, CMap3::Vertex(e)), index_of(m, CMap3::Vertex(h))});
					uint32 n = 0;
					foreach_dart_of_orbit(m, v, [&](Dart) { return ++n <= 12; });
					tets = tets && n == 12 && phi1(m, g) == d;
					return tets;
				});
				if (!tets)
					throw py::value_error("the mesh has volumes that are not tetrahedra: use cells_csr()");
				const py::ssize_t rows = py::ssize_t(out.size() / 4);
				auto* heap = new std::vector<uint32>(std::move(out));
				py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<uint32>*>(p); });
				return py::array_t<uint32>({rows, py::ssize_t(4)},
										   {py::ssize_t(4 * sizeof(uint32)), py::ssize_t(sizeof(uint32))}, heap->data(),
										   owner);
			},
			"(C, 4) vertex ids of the tetrahedra (d on the side of the normal of (a, b, c), as from_arrays "
			"takes them); ValueError when a volume is not a tetrahedron.")
		.def(
			"save",
			[](VolumeMesh& w, const std::string& path, bool binary) {
				py::gil_scoped_release release;
				if (has_map_file_extension(path))
				{
					io::save_map(w.m, path);
					return;
				}
				io::SaveOptions o;
				o.binary = binary;
				io::save_volume(w.m, path, o);
			},
			py::arg("path"), py::arg("binary") = false,
			"Writes the volume mesh (mesh, vtk, vtu, msh, node/ele by extension), or the whole map to a .cgmap "
			"file. Raises cgogn.IOError on failure.");

	py::class_<GSurface> gsurface(mod, "GMap2",
								  "A surface that may not be orientable (a Moebius strip, a Klein bottle): a "
								  "generalized 2-map of polygons, closed by boundary faces. Twice the darts of a "
								  "CMap2; faces are walked in the orientation of their dart.");
	bind_common(gsurface);
	gsurface
		.def_static(
			"from_arrays",
			[](const py::array& points, const py::object& faces) { return from_arrays<GMap2>(points, faces); },
			py::arg("points"), py::arg("faces"),
			"A surface from (N, 3) points and faces, as CMap2.from_arrays; faces that cannot be oriented "
			"consistently are kept as they are. O(total size).")
		.def(
			"save",
			[](GSurface& w, const std::string& path, bool binary) {
				py::gil_scoped_release release;
				if (has_map_file_extension(path))
				{
					io::save_map(w.m, path);
					return;
				}
				io::SaveOptions o;
				o.binary = binary;
				io::save_surface(w.m, path, o);
			},
			py::arg("path"), py::arg("binary") = false,
			"Writes the surface in the format of the extension (off, obj, ply, stl), each face in the "
			"orientation of its dart, or the whole map to a .cgmap file. Raises cgogn.IOError on failure.");

	py::class_<GVolumeMesh> gvolume(mod, "GMap3",
									"A volume mesh that may not be orientable (a solid Klein bottle): a generalized "
									"3-map of polyhedra, closed by boundary volumes.");
	bind_common(gvolume);
	gvolume
		.def_static(
			"from_arrays",
			[](const py::array& points, const py::object& cells) { return from_arrays<GMap3>(points, cells); },
			py::arg("points"), py::arg("cells"), "A volume mesh from (N, 3) points and cells, as CMap3.from_arrays.")
		.def(
			"save",
			[](GVolumeMesh& w, const std::string& path, bool binary) {
				py::gil_scoped_release release;
				if (has_map_file_extension(path))
				{
					io::save_map(w.m, path);
					return;
				}
				io::SaveOptions o;
				o.binary = binary;
				io::save_volume(w.m, path, o);
			},
			py::arg("path"), py::arg("binary") = false,
			"Writes the volume mesh (mesh, vtk, vtu, msh, node/ele by extension), each cell oriented on its own, "
			"or the whole map to a .cgmap file. Raises cgogn.IOError on failure.");

	// orientability and conversions, both ways, carrying every attribute
	bind_conversions<CMap2, GMap2>(surface, gsurface);
	bind_conversions<CMap3, GMap3>(volume, gvolume);

	mod.def(
		"load",
		[](const std::string& path, bool gmap) -> py::object {
			if (has_nmap_extension(path))
				return load_nmap_file(path, gmap);
			if (has_map_file_extension(path))
			{
				if (gmap)
					throw py::value_error("gmap=True: a .cgmap file holds its own type of map");
				std::ifstream f(path, std::ios::binary);
				if (!f)
					throw io::Error(path, "cannot open the file");
				const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
				return map_from_bytes(bytes, path);
			}
			const io::Format format = io::format_from_extension(path);
			if (is_volume_format(format))
			{
				// a file of a format of both without volume cells is a surface
				auto volume = gmap ? py::cast(load_into<GMap3>(path)) : py::cast(load_into<CMap3>(path));
				if (!holds_surfaces(format) || volume.attr("nb_cells")("volume").cast<uint32>() > 0)
					return volume;
			}
			return gmap ? py::cast(load_into<GMap2>(path)) : py::cast(load_into<CMap2>(path));
		},
		py::arg("path"), py::arg("gmap") = false,
		"Loads a mesh file: a CMap2 for the surface formats (off, obj, ply, stl), a CMap3 for the volume "
		"formats (mesh, vtk, vtu, msh, node/ele, ovm), a CMap2 for a mesh, vtk, vtu or msh file without "
		"volume cells (read twice: the faces and edges keep their tags); with gmap=True a GMap2 or a GMap3, which keep "
		"a mesh that "
		"cannot be oriented whole. A .nmap file gives the map of any dimension it holds (CMapN1 ... CMapN4, "
		"GMapN1 ... GMapN4; with gmap=True a GMapN also for a CMapN file). A .cgmap file gives the map it "
		"holds, exactly as saved (CMap2, CMap3, GMap2, GMap3, Graph, CMapN, GMapN, MRMap2, MRMap3). Raises "
		"cgogn.IOError "
		"naming the file, line and problem on bad input.");
}

} // namespace cgogn::python
