// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/build/generators.h>
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/operators/incidence_graph.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/local_gmap2.h>
#include <cgogn/core/traversals/local_gmap3.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/error.h>

#include "map_transfer.h"

#include <algorithm>
#include <unordered_map>

namespace cgogn::io::detail
{

namespace
{

template <typename CELL, typename MAP>
void check_free_name(const MAP& m, const std::string& name, std::type_index type, const std::string& path)
{
	auto a = container_of<CELL::ORBIT>(m).find(name);
	if (a != nullptr && a->type() != type)
		throw Error(path, "the map already has a " + std::string(orbit_name(CELL::ORBIT)) + " attribute '" + name +
							  "' of another type: cannot load the file's '" + name + "' into it");
}

// Calls f.template operator()<T>() with the attribute type of column c:
// the integer of its type for one integer component, else double, Vec2 or
// Vec3 by its dimension.
template <typename F>
void visit_attribute_type(const Column& c, const F& f)
{
	if (c.dim == 1)
		visit_value_type(c.type, f);
	else if (c.dim == 2)
		f.template operator()<Vec2>();
	else
		f.template operator()<Vec3>();
}

std::type_index column_type(const Column& c)
{
	std::type_index t = typeid(double);
	visit_attribute_type(c, [&]<typename T>() { t = typeid(T); });
	return t;
}

// Columns that become attributes. Vertex data named `position` is not
// skipped here but refused by check_names (data_name_conflict), like any
// other collision; a face or volume column of that name is ordinary data.
bool usable(const Column& c)
{
	return c.dim >= 1 && c.dim <= 3 && !c.name.empty() && c.name.rfind("__", 0) != 0;
}

// What the columns of d lose on their way into the map: columns that no
// attribute holds, and integer columns of several components, held as
// vectors of double (LoadReport::dropped).
void column_notes(const MeshData& d, const char* cell, std::vector<std::string>& notes)
{
	auto note = [&](const std::vector<Column>& columns, const std::string& of) {
		for (const auto& c : columns)
			if (c.name.empty() || c.name.rfind("__", 0) == 0)
				notes.push_back(of + " data " + (c.name.empty() ? "without a name" : "'" + c.name + "'") +
								": names starting with __ are the library's own, and data needs a name");
			else if (c.dim < 1 || c.dim > 3)
				notes.push_back(of + " data '" + c.name + "' of " + std::to_string(c.dim) +
								" components: attributes are loaded from data of 1, 2 or 3 components");
			else if (c.dim > 1 && is_integer_type(c.type))
				notes.push_back(of + " data '" + c.name + "' as integers: its " + std::to_string(c.dim) +
								" components are held as a vector of double (an integer attribute has one component)");
	};
	note(d.vertex_columns, "vertex");
	note(d.cell_columns, cell);
	note(d.face_columns, "listed face");
	note(d.corner_columns, "corner");
	note(d.segment_columns, "listed edge");
}

// Everything about names that could make the build fail, checked before the
// map is touched: the file's names must not clash with each other (the
// readers refuse that already; this keeps build_map safe on any MeshData) nor
// with an attribute of another type in m.
template <typename Vertex, typename Top, typename MAP>
void check_names(const MAP& m, const MeshData& d, const std::string& path)
{
	check_free_name<Vertex>(m, "position", typeid(Vec3), path);
	check_free_name<Vertex>(m, "original_vertex", typeid(uint32), path);
	auto check = [&]<typename CELL>(const std::vector<Column>& columns, CELL*) {
		std::vector<std::string> names;
		for (const auto& c : columns)
			if (usable(c))
			{
				if (std::string why = data_name_conflict(names, c.name, std::is_same_v<CELL, Vertex>); !why.empty())
					throw Error(path, why);
				names.push_back(c.name);
				check_free_name<CELL>(m, c.name, column_type(c), path);
			}
	};
	check(d.vertex_columns, static_cast<Vertex*>(nullptr));
	check(d.cell_columns, static_cast<Top*>(nullptr));
	if constexpr (MAP::dimension == 2 && !std::is_same_v<MAP, IncidenceGraph>)
	{
		using Edge = typename mesh_traits<MAP>::Edge;
		check(d.corner_columns, static_cast<Cell<Orbit::DART>*>(nullptr));
		check(d.segment_columns, static_cast<Edge*>(nullptr));
		if (!d.physical_names.empty())
		{
			check_free_name<Top>(m, "gmsh:physical_name", typeid(std::string), path);
			check_free_name<Edge>(m, "gmsh:physical_name", typeid(std::string), path);
		}
	}
	if constexpr (MAP::dimension == 3)
	{
		check(d.face_columns, static_cast<typename mesh_traits<MAP>::Face*>(nullptr));
		if (!d.physical_names.empty())
		{
			check_free_name<Top>(m, "gmsh:physical_name", typeid(std::string), path);
			check_free_name<typename mesh_traits<MAP>::Face>(m, "gmsh:physical_name", typeid(std::string), path);
		}
	}
}

// The attribute to load into. check_names has ruled out every case where
// neither get_attribute nor add_attribute gives one; the throw keeps a broken
// caller from dereferencing nullptr.
template <typename T, typename CELL, typename MAP>
std::shared_ptr<AttributeArray<T>> get_or_add(MAP& m, const std::string& name, const std::string& path)
{
	auto a = get_attribute<T, CELL>(m, name);
	if (!a)
		a = add_attribute<T, CELL>(m, name);
	if (!a)
		throw Error(path,
					"cannot load the data '" + name + "': the map has an attribute of this name and another type");
	return a;
}

// (line, row) pairs: the line of a cell in its container, and the row of
// the file's data that goes there.
using Rows = std::vector<std::pair<uint32, std::size_t>>;

// The attribute of CELL that holds column c (see get_or_add), of the
// column's type.
template <typename CELL, typename MAP>
std::shared_ptr<AttributeBase> column_attribute(MAP& m, const Column& c, const std::string& path)
{
	std::shared_ptr<AttributeBase> a;
	visit_attribute_type(c, [&]<typename T>() { a = get_or_add<T, CELL>(m, c.name, path); });
	return a;
}

// Writes column c into attribute a, of the column's type: row `row` into
// line `line` for each (line, row) of `rows`. Depends on neither the map
// nor the cell: its loops are compiled once per value type.
void write_column(AttributeBase& a, const Column& c, const Rows& rows)
{
	visit_attribute_type(c, [&]<typename T>() {
		auto& values = static_cast<AttributeArray<T>&>(a);
		for (const auto& [line, row] : rows)
		{
			const double* v = &c.values[row * c.dim];
			if constexpr (std::is_same_v<T, Vec2>)
				values[line] = Vec2(v[0], v[1]);
			else if constexpr (std::is_same_v<T, Vec3>)
				values[line] = Vec3(v[0], v[1], v[2]);
			else
				values[line] = T(v[0]); // exact: see Column
		}
	});
}

// Writes column c into the attribute of CELL (see write_column).
template <typename CELL, typename MAP>
void fill_rows(MAP& m, const Column& c, const Rows& rows, const std::string& path)
{
	write_column(*column_attribute<CELL>(m, c, path), c, rows);
}

// Whether a column of `columns` becomes an attribute.
bool any_usable(const std::vector<Column>& columns)
{
	return std::any_of(columns.begin(), columns.end(), [](const Column& c) { return usable(c); });
}

// The dart ids add_dart will hand out next: free lines last-in first-out, then new ones.
class DartPredictor
{
public:
	explicit DartPredictor(const CMapBase& m)
		: free_(container_of<Orbit::DART>(m).free_lines()), end_(container_of<Orbit::DART>(m).end_index())
	{
	}
	Dart operator()(uint64 k) const
	{
		if (k < free_.size())
			return Dart(free_[free_.size() - 1 - k]);
		return Dart(uint32(end_ + (k - free_.size())));
	}

private:
	std::vector<uint32> free_;
	uint64 end_;
};

// The darts the builder gives a cell of `size` vertices: one per edge of a
// CMap2 face, two per edge of a GMap2 face, those of a CMap3 volume's faces,
// twice those for a GMap3.
uint32 darts_of_cell(uint32 size, uint32 dimension, bool gmap)
{
	if (dimension == 2)
		return gmap ? 2 * size : size;
	const uint32 factor = gmap ? 2 : 1;
	switch (size)
	{
	case 4:
		return 12 * factor;
	case 5:
		return 16 * factor;
	case 6:
		return 18 * factor;
	case 8:
		return 24 * factor;
	default:
		return 0;
	}
}

// Builds d's cells, standard ones and polyhedra, into m through
// build_polyhedra, in their order.
template <typename MAP>
BuildReport build_polyhedra_of(MAP& m, const MeshData& d)
{
	if constexpr (MAP::dimension == 3)
		return build_polyhedra(m, cells_as_polyhedra(d));
	else
	{
		(void)m;
		(void)d;
		return BuildReport{};
	}
}

// Gives the cells of the lines of `rows` ((line, row) pairs) whose int32
// attribute `gmsh:physical` has a name of dimension `dim` in
// d.physical_names that name, in the string attribute `gmsh:physical_name`.
// O(rows).
template <typename CELL, typename MAP>
void name_physical_groups(MAP& m, const MeshData& d, int32 dim, const Rows& rows, const std::string& path)
{
	std::unordered_map<int32, const std::string*> name_of;
	for (const auto& p : d.physical_names)
		if (p.dim == dim)
			name_of.try_emplace(p.tag, &p.name);
	auto tag = get_attribute<int32, CELL>(m, "gmsh:physical");
	if (name_of.empty() || tag == nullptr)
		return;
	auto name = get_or_add<std::string, CELL>(m, "gmsh:physical_name", path);
	for (const auto& row : rows)
		if (const auto it = name_of.find((*tag)[row.first]); it != name_of.end())
			(*name)[row.first] = *it->second;
}

// The file's id of the vertex lines a load made (split copies included),
// INVALID_INDEX for the others.
class FileVertexIds
{
public:
	FileVertexIds(const BuildReport& br, uint32 nb_vertices)
		: offset_(br.vertex_offset), nb_vertices_(nb_vertices),
		  copy_of_(br.split_vertices.begin(), br.split_vertices.end())
	{
	}
	uint32 operator()(uint32 line) const
	{
		if (line >= offset_ && line - offset_ < nb_vertices_)
			return line - offset_;
		const auto it = copy_of_.find(line);
		return it == copy_of_.end() ? INVALID_INDEX : it->second;
	}

private:
	uint32 offset_;
	uint32 nb_vertices_;
	std::unordered_map<uint32, uint32> copy_of_;
};

// Puts the corner columns of d on the darts of the faces just built: each
// dart of face `cell` (reached from its first dart) gets the row of the
// corner of that cell at the dart's vertex. O(corners).
template <typename MAP>
void fill_corners(MAP& m, const MeshData& d, const std::vector<std::pair<Dart, uint32>>& firsts,
				  const FileVertexIds& file_id, const std::string& path)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Face = typename mesh_traits<MAP>::Face;
	using HalfEdge = Cell<Orbit::DART>;
	std::vector<std::size_t> first_corner(d.nb_cells() + 1, 0);
	for (uint32 c = 0; c < d.nb_cells(); ++c)
		first_corner[c + 1] = first_corner[c] + d.cell_sizes[c];
	Rows rows; // (dart, corner)
	for (const auto& first : firsts)
	{
		const uint32 cell = first.second; // not a structured binding: a lambda captures it
		foreach_dart_of_orbit(m, Face(first.first), [&](Dart x) {
			const uint32 v = file_id(index_of(m, Vertex(x)));
			for (std::size_t k = first_corner[cell]; k < first_corner[cell + 1]; ++k)
				if (d.cell_vertices[k] == v)
				{
					rows.emplace_back(x.index, k);
					break;
				}
		});
	}
	for (const auto& c : d.corner_columns)
		if (usable(c))
			fill_rows<HalfEdge>(m, c, rows, path);
}

// The listed faces of d by their lowest vertex, each with its vertex ids
// sorted, to find the listed face of a given vertex set without a key per
// face. O(listed corners).
class ListedFaces
{
public:
	explicit ListedFaces(const MeshData& d) : first_(d.nb_faces() + 1, 0), sorted_(d.face_vertices)
	{
		for (uint32 f = 0; f < d.nb_faces(); ++f)
			first_[f + 1] = first_[f] + d.face_sizes[f];
		std::vector<uint32> count(std::size_t(d.nb_vertices()) + 1, 0);
		for (uint32 f = 0; f < d.nb_faces(); ++f)
		{
			std::sort(sorted_.begin() + std::ptrdiff_t(first_[f]), sorted_.begin() + std::ptrdiff_t(first_[f + 1]));
			if (first_[f + 1] > first_[f])
				++count[sorted_[first_[f]] + 1];
		}
		for (std::size_t v = 1; v < count.size(); ++v)
			count[v] += count[v - 1];
		at_vertex_first_ = count;
		at_vertex_.resize(count.back());
		for (uint32 f = 0; f < d.nb_faces(); ++f)
			if (first_[f + 1] > first_[f])
				at_vertex_[count[sorted_[first_[f]]]++] = f;
	}
	/// The listed face whose vertices are `ids` (sorted), or INVALID_INDEX.
	uint32 find(const std::vector<uint32>& ids) const
	{
		const uint32 v = ids.front();
		for (uint32 k = at_vertex_first_[v]; k < at_vertex_first_[v + 1]; ++k)
		{
			const uint32 f = at_vertex_[k];
			if (first_[f + 1] - first_[f] == ids.size() &&
				std::equal(ids.begin(), ids.end(), sorted_.begin() + std::ptrdiff_t(first_[f])))
				return f;
		}
		return INVALID_INDEX;
	}

private:
	std::vector<std::size_t> first_;                  // where each listed face's ids start in sorted_
	std::vector<uint32> sorted_;                      // each listed face's ids, sorted
	std::vector<uint32> at_vertex_first_, at_vertex_; // the listed faces by lowest vertex (CSR)
};

template <typename MAP>
void fill_listed_faces(MAP& m, const MeshData& d, const BuildReport& br, const std::string& path, LoadReport& rep)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Face = typename mesh_traits<MAP>::Face;
	if (!any_usable(d.face_columns))
		return;
	const ListedFaces listed(d);
	std::vector<uint32> ids;
	const FileVertexIds file_id(br, d.nb_vertices());
	Rows found; // (face line, listed face)
	std::vector<uint8> matched(d.nb_faces(), 0);
	index_cells<Face>(m);
	foreach_cell(m, [&](Face f) {
		ids.clear();
		bool ours = true;
		foreach_incident_vertex(m, f, [&](Vertex v) {
			const uint32 id = file_id(index_of(m, v));
			ours = ours && id != INVALID_INDEX;
			ids.push_back(id);
		});
		if (!ours)
			return;
		std::sort(ids.begin(), ids.end());
		if (const uint32 listed_face = listed.find(ids); listed_face != INVALID_INDEX)
		{
			found.emplace_back(index_of(m, f), listed_face);
			matched[listed_face] = 1;
		}
	});
	for (const auto& c : d.face_columns)
		if (usable(c))
			fill_rows<Face>(m, c, found, path);
	name_physical_groups<Face>(m, d, 2, found, path);
	const auto unmatched = std::count(matched.begin(), matched.end(), uint8(0));
	if (unmatched > 0)
		rep.dropped.push_back(std::to_string(unmatched) +
							  " listed face(s) with their data: no face of the volumes has their vertices");
}

// The listed edges of a surface (MeshData::segments) on the edges of m
// between the same two vertices, with their columns and physical names;
// what matches no edge is reported. O(edges of m + listed edges).
template <typename MAP>
void fill_listed_edges(MAP& m, const MeshData& d, const BuildReport& br, const std::string& path, LoadReport& rep)
{
	using Edge = typename mesh_traits<MAP>::Edge;
	using Vertex = typename mesh_traits<MAP>::Vertex;
	if (!any_usable(d.segment_columns))
		return;
	auto key = [](uint32 a, uint32 b) { return (uint64(std::min(a, b)) << 32) | std::max(a, b); };
	std::unordered_map<uint64, uint32> listed; // (lower, higher vertex) -> first listed edge
	listed.reserve(d.segments.size());
	uint32 nb_repeated = 0;
	for (uint32 e = 0; e < uint32(d.segments.size()); ++e)
		nb_repeated += !listed.try_emplace(key(d.segments[e].first, d.segments[e].second), e).second;
	const FileVertexIds file_id(br, d.nb_vertices());
	Rows found; // (edge line, listed edge)
	std::vector<uint8> matched(d.segments.size(), 0);
	index_cells<Edge>(m);
	std::vector<uint32> ends; // the file ids of the edge's two vertices
	foreach_cell(m, [&](Edge e) {
		ends.clear();
		foreach_incident_vertex(m, e, [&](Vertex v) { ends.push_back(file_id(index_of(m, v))); });
		if (ends.size() != 2 || ends[0] == INVALID_INDEX || ends[1] == INVALID_INDEX)
			return;
		if (const auto it = listed.find(key(ends[0], ends[1])); it != listed.end())
		{
			found.emplace_back(index_of(m, e), it->second);
			matched[it->second] = 1;
		}
	});
	for (const auto& c : d.segment_columns)
		if (usable(c))
			fill_rows<Edge>(m, c, found, path);
	name_physical_groups<Edge>(m, d, 1, found, path);
	const auto unmatched = std::count(matched.begin(), matched.end(), uint8(0)) - nb_repeated;
	if (unmatched > 0)
		rep.dropped.push_back(std::to_string(unmatched) +
							  " listed edge(s) with their data: no edge of the faces has their vertices");
	if (nb_repeated > 0)
		rep.dropped.push_back(std::to_string(nb_repeated) +
							  " listed edge(s) repeating an earlier one: the edge holds the first one's data");
}

template <typename MAP>
LoadReport build(MAP& m, const MeshData& d, const std::string& path)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Top =
		std::conditional_t<MAP::dimension == 2, typename mesh_traits<MAP>::Face, typename mesh_traits<MAP>::Volume>;
	constexpr uint32 dim = MAP::dimension;

	// 1. everything that can fail, before touching m
	check_names<Vertex, Top>(m, d, path);
	if (uint64(d.nb_vertices()) + container_of<Vertex::ORBIT>(m).end_index() >= INVALID_INDEX ||
		uint64(d.cell_vertices.size()) * (is_gmap_v<MAP> && dim == 3 ? 12 : 6) + d.polyhedron_face_vertices.size() +
				container_of<Orbit::DART>(m).end_index() >=
			INVALID_INDEX)
		throw Error(path, "the mesh is too large for 32-bit indices");

	const bool polyhedra = !d.cell_nb_faces.empty();
	if constexpr (dim == 2)
		if (polyhedra)
			throw Error(path, "the file has polyhedra (VTK cells of type 42): they load into a volume map");

	// which cells the builder will build (same rules as build_surface,
	// build_volume and build_polyhedra), and their darts
	std::vector<uint8> built(d.nb_cells(), 0);
	std::vector<uint32> nb_darts_of(d.nb_cells(), 0);
	{
		std::size_t k = 0, face = 0, first = 0;
		std::vector<uint32> tmp;
		for (uint32 c = 0; c < d.nb_cells(); ++c)
		{
			const uint32 n = d.cell_sizes[c];
			if (d.is_polyhedron(c))
			{
				k += n;
				const std::span<const uint32> sizes(d.polyhedron_face_sizes.data() + face, d.cell_nb_faces[c]);
				face += d.cell_nb_faces[c];
				std::size_t size = 0;
				for (uint32 fs : sizes)
					size += fs;
				built[c] = is_buildable_polyhedron(sizes, {d.polyhedron_face_vertices.data() + first, size});
				nb_darts_of[c] = uint32(is_gmap_v<MAP> ? 2 * size : size);
				first += size;
				continue;
			}
			tmp.assign(d.cell_vertices.begin() + std::ptrdiff_t(k), d.cell_vertices.begin() + std::ptrdiff_t(k + n));
			k += n;
			std::sort(tmp.begin(), tmp.end());
			const bool ok_size = dim == 2 ? n >= 3 : darts_of_cell(n, 3, false) != 0;
			built[c] = ok_size && std::adjacent_find(tmp.begin(), tmp.end()) == tmp.end();
			nb_darts_of[c] = darts_of_cell(n, dim, is_gmap_v<MAP>);
		}
	}
	const DartPredictor predict(m);

	// 2. build
	LoadReport rep;
	if constexpr (dim == 2)
		rep.build = build_surface(m, d.nb_vertices(), d.cell_sizes, d.cell_vertices);
	else if (polyhedra)
		rep.build = build_polyhedra_of(m, d);
	else
		rep.build = build_volume(m, d.nb_vertices(), d.cell_sizes, d.cell_vertices);
	const BuildReport& br = rep.build;

	// 3. vertex data: soup vertex i is line offset + i (when used), split copies too
	const AttributeContainer& vc = container_of<Vertex::ORBIT>(m);
	auto vertex_lines = [&](const auto& f) {
		for (uint32 i = 0; i < d.nb_vertices(); ++i)
			if (vc.is_live(br.vertex_offset + i))
				f(br.vertex_offset + i, std::size_t(i));
		for (const auto& [line, orig] : br.split_vertices)
			f(line, std::size_t(orig));
	};
	auto pos = get_or_add<Vec3, Vertex>(m, "position", path);
	vertex_lines([&](uint32 line, std::size_t i) {
		(*pos)[line] = Vec3(d.positions[3 * i], d.positions[3 * i + 1], d.positions[3 * i + 2]);
	});
	if (br.nb_nonmanifold_vertices > 0)
	{
		auto orig = get_or_add<uint32, Vertex>(m, "original_vertex", path);
		vertex_lines([&](uint32 line, std::size_t i) { (*orig)[line] = uint32(i); });
	}
	if (any_usable(d.vertex_columns))
	{
		Rows rows;
		vertex_lines([&](uint32 line, std::size_t i) { rows.emplace_back(line, i); });
		for (const auto& c : d.vertex_columns)
			if (usable(c))
				fill_rows<Vertex>(m, c, rows, path);
	}

	// 4. cell data: cell c's first dart is predictable from the dart container's state
	const bool any_cell_column = any_usable(d.cell_columns), any_corner_column = any_usable(d.corner_columns);
	std::vector<std::pair<Dart, uint32>> firsts; // (first dart, cell)
	if (any_cell_column || any_corner_column)
	{
		uint64 k = 0;
		for (uint32 c = 0; c < d.nb_cells(); ++c)
			if (built[c])
			{
				firsts.emplace_back(predict(k), c);
				k += nb_darts_of[c];
			}
	}
	if constexpr (dim == 2)
		if (any_corner_column)
			fill_corners(m, d, firsts, FileVertexIds(br, d.nb_vertices()), path);
	if (any_cell_column)
	{
		index_cells<Top>(m);
		Rows rows; // (line, cell) of the built cells
		rows.reserve(firsts.size());
		for (const auto& [dart, cell] : firsts)
		{
			assert(is_dart_valid(m, dart) && !is_boundary(m, dart));
			rows.emplace_back(index_of(m, Top(dart)), cell);
		}
		for (const auto& c : d.cell_columns)
			if (usable(c))
				fill_rows<Top>(m, c, rows, path);
		name_physical_groups<Top>(m, d, dim, rows, path);
	}

	rep.dropped = d.dropped;
	column_notes(d, dim == 2 ? "face" : "volume", rep.dropped);
	if constexpr (dim == 3)
	{
		fill_listed_faces(m, d, br, path, rep);
		if (d.nb_faces() > 0 && d.face_columns.empty())
			rep.dropped.push_back(std::to_string(d.nb_faces()) +
								  " listed face(s) without data: the volume map has its own faces");
		if (!d.segments.empty())
			rep.dropped.push_back(std::to_string(d.segments.size()) +
								  " listed edge(s) with their data: a volume map holds volumes and listed faces");
		if (std::any_of(d.physical_names.begin(), d.physical_names.end(), [](const auto& p) { return p.dim < 2; }))
			rep.dropped.push_back("the names of physical groups of points and curves: a volume map names its volumes "
								  "and listed faces");
	}
	else
	{
		fill_listed_edges(m, d, br, path, rep);
		if (!d.segments.empty() && !any_usable(d.segment_columns))
			rep.dropped.push_back(std::to_string(d.segments.size()) +
								  " listed edge(s) without data: the surface has its own edges");
		if (std::any_of(d.physical_names.begin(), d.physical_names.end(),
						[](const auto& p) { return p.dim != 1 && p.dim != 2; }))
			rep.dropped.push_back("the names of physical groups of points and volumes: a surface map names its faces "
								  "and listed edges");
	}
	rep.nb_vertices_read = d.nb_vertices();
	rep.nb_cells_read = br.nb_cells_read;
	rep.nb_cells_built = br.nb_cells_built;
	rep.nb_cells_skipped = br.nb_cells_degenerate + br.nb_cells_invalid;
	rep.nb_isolated_vertices = br.nb_isolated_vertices;
	rep.nb_nonmanifold_vertices = br.nb_nonmanifold_vertices;
	rep.nb_vertices_split = uint32(br.split_vertices.size());
	rep.nb_nonmanifold_edges = br.nb_nonmanifold_edges;
	rep.nb_nonmanifold_faces = br.nb_nonmanifold_faces;
	rep.nb_holes_closed = br.nb_boundary_cells;
	rep.nb_orientation_conflicts = br.nb_orientation_conflicts;
	rep.orientable = br.orientable;
	return rep;
}

// The incidence graph of the soup, exactly: every vertex (used or not) in
// the file's order, every face through its vertices in the file's order,
// edges shared by their faces whatever their number and directions. Only
// faces that no complex holds (fewer than 3 vertices, a repeated vertex)
// are skipped and counted.
LoadReport build_complex(IncidenceGraph& ig, const MeshData& d, const std::string& path)
{
	using Vertex = IncidenceGraph::Vertex;
	using Face = IncidenceGraph::Face;
	check_names<Vertex, Face>(ig, d, path);
	if (uint64(d.nb_vertices()) + container_of<Vertex::ORBIT>(ig).end_index() >= INVALID_INDEX - 1 ||
		uint64(d.cell_vertices.size()) + container_of<Orbit::DART>(ig).end_index() >= INVALID_INDEX)
		throw Error(path, "the mesh is too large for 32-bit indices");

	LoadReport rep;
	const bool any_cell_column = any_usable(d.cell_columns);
	if (any_cell_column)
		index_cells<Face>(ig);
	std::vector<Vertex> vertex(d.nb_vertices());
	for (uint32 i = 0; i < d.nb_vertices(); ++i)
		vertex[i] = add_vertex(ig);
	Rows faces; // (face line, cell) when faces are indexed
	std::vector<Vertex> fv, sorted;
	std::size_t k = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		const uint32 n = d.cell_sizes[c];
		fv.clear();
		for (uint32 i = 0; i < n; ++i)
			fv.push_back(vertex[d.cell_vertices[k + i]]);
		k += n;
		sorted = fv;
		std::sort(sorted.begin(), sorted.end(), [](Vertex a, Vertex b) { return a.dart.index < b.dart.index; });
		if (n < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
		{
			++rep.build.nb_cells_degenerate;
			continue;
		}
		const Face f = add_face_through_vertices(ig, fv);
		++rep.build.nb_cells_built;
		if (any_cell_column)
			faces.emplace_back(index_of(ig, f), c);
	}

	auto vertex_lines = [&](const auto& f) {
		for (uint32 i = 0; i < d.nb_vertices(); ++i)
			f(vertex[i].dart.index, std::size_t(i));
	};
	auto pos = get_or_add<Vec3, Vertex>(ig, "position", path);
	vertex_lines([&](uint32 line, std::size_t i) {
		(*pos)[line] = Vec3(d.positions[3 * i], d.positions[3 * i + 1], d.positions[3 * i + 2]);
	});
	if (any_usable(d.vertex_columns))
	{
		Rows rows;
		vertex_lines([&](uint32 line, std::size_t i) { rows.emplace_back(line, i); });
		for (const auto& c : d.vertex_columns)
			if (usable(c))
				fill_rows<Vertex>(ig, c, rows, path);
	}
	for (const auto& c : d.cell_columns)
		if (usable(c))
			fill_rows<Face>(ig, c, faces, path);

	rep.dropped = d.dropped;
	column_notes(d, "face", rep.dropped);
	for (const auto& c : d.corner_columns)
		rep.dropped.push_back("corner data '" + c.name + "': an incidence graph holds no per-corner data");
	if (!d.segments.empty())
		rep.dropped.push_back(std::to_string(d.segments.size()) +
							  " listed edge(s) with their data: an incidence graph holds faces and their edges");
	rep.build.nb_cells_read = d.nb_cells();
	rep.build.vertex_offset = vertex.empty() ? 0 : vertex[0].dart.index;
	rep.nb_vertices_read = d.nb_vertices();
	rep.nb_cells_read = d.nb_cells();
	rep.nb_cells_built = rep.build.nb_cells_built;
	rep.nb_cells_skipped = rep.build.nb_cells_degenerate;
	return rep;
}

} // namespace

LoadReport build_map(IncidenceGraph& ig, const MeshData& d, const std::string& path)
{
	return build_complex(ig, d, path);
}

PolyhedronSoup cells_as_polyhedra(const MeshData& d)
{
	VolumeSoup standard;
	standard.nb_vertices = d.nb_vertices();
	std::size_t k = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		if (!d.is_polyhedron(c))
		{
			standard.cell_sizes.push_back(d.cell_sizes[c]);
			standard.cell_vertices.insert(standard.cell_vertices.end(), d.cell_vertices.begin() + std::ptrdiff_t(k),
										  d.cell_vertices.begin() + std::ptrdiff_t(k + d.cell_sizes[c]));
		}
		k += d.cell_sizes[c];
	}
	const PolyhedronSoup standard_faces = polyhedra_of(standard);
	PolyhedronSoup all;
	all.nb_vertices = d.nb_vertices();
	std::size_t s_face = 0, s_first = 0, p_face = 0, p_first = 0;
	auto take = [&](const std::vector<uint32>& sizes, const std::vector<uint32>& ids, std::size_t& face,
					std::size_t& first, uint32 nf) {
		all.cell_nb_faces.push_back(nf);
		for (uint32 f = 0; f < nf; ++f)
		{
			const uint32 n = sizes[face + f];
			all.face_sizes.push_back(n);
			all.face_vertices.insert(all.face_vertices.end(), ids.begin() + std::ptrdiff_t(first),
									 ids.begin() + std::ptrdiff_t(first + n));
			first += n;
		}
		face += nf;
	};
	uint32 s_cell = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
		if (d.is_polyhedron(c))
			take(d.polyhedron_face_sizes, d.polyhedron_face_vertices, p_face, p_first, d.cell_nb_faces[c]);
		else if (s_cell < standard_faces.cell_nb_faces.size()) // cells of an unknown size have no faces
			take(standard_faces.face_sizes, standard_faces.face_vertices, s_face, s_first,
				 standard_faces.cell_nb_faces[s_cell++]);
		else
			all.cell_nb_faces.push_back(0);
	return all;
}

LoadReport build_map(CMap2& m, const MeshData& d, const std::string& path)
{
	return build(m, d, path);
}
LoadReport build_map(GMap2& m, const MeshData& d, const std::string& path)
{
	return build(m, d, path);
}
LoadReport build_map(CMap3& m, const MeshData& d, const std::string& path)
{
	return build(m, d, path);
}
LoadReport build_map(GMap3& m, const MeshData& d, const std::string& path)
{
	return build(m, d, path);
}

} // namespace cgogn::io::detail
