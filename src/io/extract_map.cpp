// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/traversals/local_gmap2.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/error.h>

#include "map_transfer.h"

#include <set>

namespace cgogn::io::detail
{

namespace
{

// The column of attribute a when its type is T: its values in the order of
// `lines`; false when a is not of type T. A 64-bit integer attribute whose
// values a double does not hold exactly is refused (io::Error naming path).
template <typename T>
bool gather_column(const AttributeBase& a, const std::vector<uint32>& lines, Column& c, const std::string& path)
{
	if (a.type() != typeid(T))
		return false;
	const auto& at = static_cast<const AttributeArray<T>&>(a);
	if constexpr (std::is_same_v<T, double>)
	{
		c.dim = 1;
		for (uint32 l : lines)
			c.values.push_back(at[l]);
	}
	else if constexpr (std::is_same_v<T, Vec2> || std::is_same_v<T, Vec3>)
	{
		c.dim = uint32(T::RowsAtCompileTime);
		for (uint32 l : lines)
			for (uint32 k = 0; k < c.dim; ++k)
				c.values.push_back(at[l][k]);
	}
	else
	{
		c.dim = 1;
		c.type = value_type_of<T>();
		for (uint32 l : lines)
		{
			const double v = double(at[l]);
			if constexpr (sizeof(T) == 8)
				if (std::abs(v) > MAX_EXACT_INTEGER)
					throw Error(path, "the attribute '" + c.name + "' holds " + std::to_string(at[l]) +
										  ": 64-bit integer values are written below 2^53 in magnitude");
			c.values.push_back(v);
		}
	}
	return true;
}

// The columns of the attributes a file can hold (double, Vec2, Vec3, the
// integers of 8 to 64 bits) of a container, gathered in the order of
// `lines`; `skip_position` for the vertices.
void gather_columns(const AttributeContainer& cont, const std::vector<uint32>& lines, std::vector<Column>& out,
					bool skip_position, const std::string& path)
{
	for (const auto& a : cont.attributes())
	{
		const std::string& name = a->name();
		// position is written apart; original_vertex (uint32) is a load's own
		// record of the file it read, which a file of this map must not carry
		if (name.rfind("__", 0) == 0 || (skip_position && name == "position") ||
			(skip_position && name == "original_vertex" && a->type() == typeid(uint32)))
			continue;
		if (name.find_first_of(" \t\r\n") != std::string::npos)
			continue;
		Column c{name, 0, {}};
		const bool held =
			[&]<typename... T>(std::tuple<T...>*) {
				return (gather_column<T>(*a, lines, c, path) || ...);
			}(static_cast<
				std::tuple<double, Vec2, Vec3, int8, uint8, std::int16_t, uint16, int32, uint32, int64, uint64>*>(
				nullptr));
		if (held)
			out.push_back(std::move(c));
	}
}

// Positions and a file id for every vertex line (vertices numbered in the
// order of the vertex container).
template <typename MAP>
std::vector<uint32> number_vertices(const MAP& m, MeshData& d, const std::string& path, bool attributes)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	if (!pos)
		throw Error(path, "the map has no Vec3 vertex attribute 'position' to write");
	const AttributeContainer& vc = container_of<Vertex::ORBIT>(m);
	std::vector<uint32> id(vc.end_index(), INVALID_INDEX);
	std::vector<uint32> lines;
	lines.reserve(vc.nb_lines());
	d.positions.reserve(3 * std::size_t(vc.nb_lines()));
	foreach_cell(m, [&](Vertex v) {
		const uint32 l = index_of(m, v);
		id[l] = uint32(lines.size());
		lines.push_back(l);
		const Vec3& p = (*pos)[l];
		d.positions.insert(d.positions.end(), {p[0], p[1], p[2]});
	});
	if (attributes)
		gather_columns(vc, lines, d.vertex_columns, true, path);
	return id;
}

// The vertex a face's dart starts at (an incidence graph's use: its origin).
template <typename MAP>
typename mesh_traits<MAP>::Vertex vertex_of_dart(const MAP& m, Dart x)
{
	if constexpr (std::is_same_v<MAP, IncidenceGraph>)
		return use_origin(m, x);
	else
		return typename mesh_traits<MAP>::Vertex(x);
}

// Adds to d.physical_names the names of the physical groups of dimension
// `dim` that the cells of `lines` carry: the string attribute
// `gmsh:physical_name` beside the int32 `gmsh:physical` (see
// MeshData::physical_names), each (dim, tag) once. Names a .msh file
// cannot quote (with a quote or a line break) are left out. O(lines).
template <typename CELL, typename MAP>
void collect_physical_names(const MAP& m, const std::vector<uint32>& lines, int32 dim, MeshData& d)
{
	auto name = get_attribute<std::string, CELL>(m, "gmsh:physical_name");
	auto tag = get_attribute<int32, CELL>(m, "gmsh:physical");
	if (name == nullptr || tag == nullptr)
		return;
	std::set<int32> named;
	for (const auto& p : d.physical_names)
		if (p.dim == dim)
			named.insert(p.tag);
	for (uint32 l : lines)
	{
		const std::string& n = (*name)[l];
		if (!n.empty() && n.find_first_of("\"\r\n") == std::string::npos && named.insert((*tag)[l]).second)
			d.physical_names.push_back({dim, (*tag)[l], n});
	}
}

template <typename MAP>
MeshData extract_faces(const MAP& m, const std::string& path, bool attributes)
{
	using Face = typename mesh_traits<MAP>::Face;
	// a G-map face's darts alternate beta0 and beta1: every other one starts
	// an edge, in the order of the polygon
	constexpr uint32 step = is_gmap_v<MAP> ? 2 : 1;
	MeshData d;
	const std::vector<uint32> id = number_vertices(m, d, path, attributes);
	std::vector<uint32> face_lines;
	std::vector<uint32> corner_darts; // the dart of each corner, in the order of cell_vertices
	const bool faces_indexed = is_indexed<Face>(m);
	foreach_cell(m, [&](Face f) {
		uint32 n = 0;
		foreach_dart_of_orbit(m, f, [&](Dart x) {
			if (n++ % step == 0)
			{
				d.cell_vertices.push_back(id[index_of(m, vertex_of_dart(m, x))]);
				corner_darts.push_back(x.index);
			}
		});
		d.cell_sizes.push_back(n / step);
		if (faces_indexed)
			face_lines.push_back(index_of(m, f));
	});
	if (attributes && faces_indexed)
	{
		gather_columns(container_of<Face::ORBIT>(m), face_lines, d.cell_columns, false, path);
		collect_physical_names<Face>(m, face_lines, 2, d);
	}
	// the dart attributes, as per-corner data (an incidence graph's uses are
	// not corners of the files' faces)
	if (attributes && !std::is_same_v<MAP, IncidenceGraph>)
		gather_columns(container_of<Orbit::DART>(m), corner_darts, d.corner_columns, false, path);
	return d;
}

// Rows i of `columns` (of `nb_rows` rows) with a nonzero value in one of
// them; the columns keep those rows only. O(size of the columns).
std::vector<uint32> keep_nonzero_rows(std::vector<Column>& columns, uint32 nb_rows)
{
	std::vector<uint32> kept;
	for (uint32 i = 0; i < nb_rows; ++i)
		if (std::any_of(columns.begin(), columns.end(), [&](const Column& c) {
				return std::any_of(c.values.begin() + std::ptrdiff_t(i) * c.dim,
								   c.values.begin() + std::ptrdiff_t(i + 1) * c.dim, [](double v) { return v != 0.0; });
			}))
			kept.push_back(i);
	for (Column& c : columns)
	{
		std::vector<double> values;
		values.reserve(kept.size() * c.dim);
		for (uint32 i : kept)
			values.insert(values.end(), c.values.begin() + std::ptrdiff_t(i) * c.dim,
						  c.values.begin() + std::ptrdiff_t(i + 1) * c.dim);
		c.values = std::move(values);
	}
	return kept;
}

// The columns of the attributes of the cells CELL of `lines` that a file
// can hold, reduced to the rows of the cells with a nonzero value, with the
// names of those cells' physical groups (dimension dim) added to d. Returns
// the kept positions in `lines` (none when no attribute is held).
template <typename CELL, typename MAP>
std::vector<uint32> cells_with_data(const MAP& m, const std::vector<uint32>& lines, int32 dim,
									std::vector<Column>& columns, MeshData& d, const std::string& path)
{
	gather_columns(container_of<CELL::ORBIT>(m), lines, columns, false, path);
	if (columns.empty())
		return {};
	std::vector<uint32> kept = keep_nonzero_rows(columns, uint32(lines.size()));
	std::vector<uint32> kept_lines;
	for (uint32 i : kept)
		kept_lines.push_back(lines[i]);
	collect_physical_names<CELL>(m, kept_lines, dim, d);
	return kept;
}

// The faces of a volume map with a nonzero value in one of their attributes
// a file can hold, as listed faces with those columns (MeshData::face_sizes),
// each seen from a volume that is not a boundary one (on a 3-map,
// counterclockwise seen from outside that volume). O(faces of m).
template <typename MAP, typename ORIGIN, typename NEXT>
void list_faces_with_data(const MAP& m, MeshData& d, const std::string& path, const ORIGIN& origin, const NEXT& next)
{
	using Face = typename mesh_traits<MAP>::Face;
	if (!is_indexed<Face>(m))
		return;
	std::vector<uint32> lines;
	std::vector<Dart> darts;
	foreach_cell(m, [&](Face f) {
		lines.push_back(index_of(m, f));
		darts.push_back(f.dart);
	});
	std::vector<Column> columns;
	const std::vector<uint32> kept = cells_with_data<Face>(m, lines, 2, columns, d, path);
	if (columns.empty())
		return;
	for (uint32 i : kept)
	{
		Dart x = darts[i];
		if (is_boundary(m, x))
		{
			if constexpr (is_gmap_v<MAP>)
				x = beta3(m, x);
			else
				x = phi3(m, x);
		}
		uint32 n = 0;
		Dart it = x;
		do
		{
			d.face_vertices.push_back(origin(it));
			++n;
			it = next(it);
		} while (it != x);
		d.face_sizes.push_back(n);
	}
	d.face_columns = std::move(columns);
}

// The volumes of a 3-map, or of a 3-G-map: each volume in the orientation
// of the dart it is reached by (on a G-map, the darts reached from it by
// phi1 = beta1 o beta0 and phi2 = beta0 o beta2), classified by its faces and
// written bottom face first (reversed), then the vertices above the bottom.
template <typename MAP>
MeshData extract_volumes(const MAP& m, const std::string& path, bool attributes)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Volume = typename mesh_traits<MAP>::Volume;
	MeshData d;
	const std::vector<uint32> id = number_vertices(m, d, path, attributes);
	auto origin = [&](Dart x) { return id[index_of(m, Vertex(x))]; };
	auto next = [&](Dart x) {
		if constexpr (is_gmap_v<MAP>)
			return beta1(m, beta0(m, x));
		else
			return phi1(m, x);
	};
	auto previous = [&](Dart x) {
		if constexpr (is_gmap_v<MAP>)
			return beta0(m, beta1(m, x));
		else
			return phi_1(m, x);
	};
	auto across = [&](Dart x) {
		if constexpr (is_gmap_v<MAP>)
			return beta0(m, beta2(m, x));
		else
			return phi2(m, x);
	};
	std::vector<uint32> volume_lines;
	const bool volumes_indexed = is_indexed<Volume>(m);
	DartMarker<MAP> seen(m);
	std::vector<std::pair<Dart, uint32>> faces; // (dart, degree) of one volume
	std::vector<Dart> work;
	std::vector<uint32> face_sizes, face_ids; // a polyhedron's
	foreach_cell(m, [&](Volume w) {
		faces.clear();
		auto add_face = [&](Dart x) {
			uint32 n = 0;
			Dart it = x;
			do
			{
				seen.mark(it);
				++n;
				if constexpr (is_gmap_v<MAP>)
					work.push_back(across(it));
				it = next(it);
			} while (it != x);
			faces.emplace_back(x, n);
		};
		if constexpr (is_gmap_v<MAP>)
		{
			// the faces of the darts of w.dart's colour only
			work.assign(1, w.dart);
			while (!work.empty())
			{
				const Dart x = work.back();
				work.pop_back();
				if (!seen.is_marked(x))
					add_face(x);
			}
		}
		else
			foreach_dart_of_orbit(m, w, [&](Dart x) {
				if (!seen.is_marked(x))
					add_face(x);
			});
		uint32 tri = 0, quad = 0;
		for (const auto& f : faces)
		{
			tri += f.second == 3;
			quad += f.second == 4;
		}
		const std::size_t nf = faces.size();
		uint32 bottom_degree = 0, size = 0;
		if (nf == 4 && tri == 4)
			bottom_degree = 3, size = 4;
		else if (nf == 5 && tri == 4 && quad == 1)
			bottom_degree = 4, size = 5;
		else if (nf == 5 && tri == 2 && quad == 3)
			bottom_degree = 3, size = 6;
		else if (nf == 6 && quad == 6)
			bottom_degree = 4, size = 8;
		else
		{
			// any other polyhedron: its faces, counterclockwise seen from outside
			face_sizes.clear();
			face_ids.clear();
			for (const auto& [x, n] : faces)
			{
				face_sizes.push_back(n);
				Dart it = x;
				for (uint32 i = 0; i < n; ++i, it = next(it))
					face_ids.push_back(origin(it));
			}
			d.add_polyhedron(uint32(nf), face_sizes, face_ids);
			if (volumes_indexed)
				volume_lines.push_back(index_of(m, w));
			return;
		}
		Dart b;
		for (const auto& f : faces)
			if (f.second == bottom_degree)
			{
				b = f.first;
				break;
			}
		// bottom in reverse phi1 order, then the vertex above each bottom vertex
		std::array<Dart, 4> x;
		Dart it = b;
		for (uint32 i = 0; i < bottom_degree; ++i)
		{
			x[i] = it;
			d.cell_vertices.push_back(origin(it));
			it = previous(it);
		}
		const uint32 tops = size == 4 || size == 5 ? 1 : bottom_degree;
		for (uint32 i = 0; i < tops; ++i)
			d.cell_vertices.push_back(origin(next(next(across(x[i])))));
		d.cell_sizes.push_back(size);
		if (volumes_indexed)
			volume_lines.push_back(index_of(m, w));
	});
	d.finish_polyhedra();
	if (attributes && volumes_indexed)
	{
		gather_columns(container_of<Volume::ORBIT>(m), volume_lines, d.cell_columns, false, path);
		collect_physical_names<Volume>(m, volume_lines, 3, d);
	}
	if (attributes)
		list_faces_with_data(m, d, path, origin, next);
	return d;
}

// See list_edges_with_data in map_transfer.h.
template <typename MAP>
void list_edges_of(const MAP& m, MeshData& d, const std::string& path)
{
	using Edge = typename mesh_traits<MAP>::Edge;
	using Vertex = typename mesh_traits<MAP>::Vertex;
	if (!is_indexed<Edge>(m))
		return;
	const AttributeContainer& vc = container_of<Vertex::ORBIT>(m);
	std::vector<uint32> id(vc.end_index(), INVALID_INDEX);
	uint32 next_id = 0;
	foreach_cell(m, [&](Vertex v) { id[index_of(m, v)] = next_id++; }); // as number_vertices
	std::vector<uint32> lines, ends;                                    // two vertex ids per edge
	foreach_cell(m, [&](Edge e) {
		lines.push_back(index_of(m, e));
		foreach_incident_vertex(m, e, [&](Vertex v) { ends.push_back(id[index_of(m, v)]); });
	});
	std::vector<Column> columns;
	for (uint32 i : cells_with_data<Edge>(m, lines, 1, columns, d, path))
		d.segments.emplace_back(ends[2 * i], ends[2 * i + 1]);
	d.segment_columns = std::move(columns);
}

} // namespace

void list_edges_with_data(const CMap2& m, MeshData& d, const std::string& path)
{
	list_edges_of(m, d, path);
}

void list_edges_with_data(const GMap2& m, MeshData& d, const std::string& path)
{
	list_edges_of(m, d, path);
}

MeshData extract_surface(const CMap2& m, const std::string& path, bool attributes)
{
	return extract_faces(m, path, attributes);
}

MeshData extract_surface(const GMap2& m, const std::string& path, bool attributes)
{
	return extract_faces(m, path, attributes);
}

MeshData extract_surface(const IncidenceGraph& ig, const std::string& path, bool attributes)
{
	return extract_faces(ig, path, attributes);
}

MeshData extract_volume(const CMap3& m, const std::string& path, bool attributes)
{
	return extract_volumes(m, path, attributes);
}

MeshData extract_volume(const GMap3& m, const std::string& path, bool attributes)
{
	// a volume reached by a dart of the inner colour comes out turned over
	MeshData d = extract_volumes(m, path, attributes);
	orient_cells(d);
	return d;
}

} // namespace cgogn::io::detail
