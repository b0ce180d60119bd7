// SPDX-License-Identifier: MIT
// Parallel VTU (.pvtu): an XML index naming one .vtu piece per rank. The
// pieces are read and merged into one mesh: vertices by their GlobalNodeIds
// point array (when every piece has one), ghost cells and ghost listed
// faces (vtkGhostType != 0) dropped, both ordered by their GlobalCellIds
// when every piece has them.
#include <cgogn/io/error.h>

#include "file_io.h"
#include "formats.h"

#include <algorithm>
#include <filesystem>
#include <map>

namespace cgogn::io::detail
{

namespace
{

constexpr const char* GHOST = "vtkGhostType";
constexpr const char* NODE_IDS = "GlobalNodeIds";
constexpr const char* CELL_IDS = "GlobalCellIds";

// The values of the attribute `name` of every tag `tag` of an XML text, in order.
std::vector<std::string> attribute_values(std::string_view text, const std::string& tag, const std::string& name,
										  const std::string& path)
{
	std::vector<std::string> values;
	const std::string open = "<" + tag;
	for (std::size_t at = text.find(open); at != std::string_view::npos; at = text.find(open, at + 1))
	{
		const std::size_t end = text.find('>', at);
		if (end == std::string_view::npos)
			throw Error(path, Error::Where::Byte, at, "unterminated <" + tag + "> tag");
		const std::string_view t = text.substr(at, end - at);
		const std::size_t key = t.find(" " + name + "=\"");
		if (key == std::string_view::npos)
			throw Error(path, Error::Where::Byte, at, "<" + tag + "> without " + name);
		const std::size_t first = key + name.size() + 3, last = t.find('"', first);
		if (last == std::string_view::npos)
			throw Error(path, Error::Where::Byte, at, "unterminated " + name + " attribute");
		values.emplace_back(t.substr(first, last - first));
	}
	return values;
}

const Column* find_column(const std::vector<Column>& cols, const char* name)
{
	for (const Column& c : cols)
		if (c.name == name)
			return &c;
	return nullptr;
}

// The columns of the first piece, which every other piece must have too
// (same name, components and type), without the ghost flags.
std::vector<Column> shared_columns(const std::vector<MeshData>& pieces, const std::vector<std::string>& paths,
								   std::vector<Column> MeshData::*columns, const char* what)
{
	std::vector<Column> out;
	for (const Column& c : pieces[0].*columns)
		if (c.name != GHOST)
			out.push_back({c.name, c.dim, {}, c.type});
	for (std::size_t p = 0; p < pieces.size(); ++p)
	{
		std::size_t n = 0;
		for (const Column& c : pieces[p].*columns)
			if (c.name != GHOST)
			{
				++n;
				const Column* first = find_column(out, c.name.c_str());
				if (first == nullptr || first->dim != c.dim || first->type != c.type)
					throw Error(paths[p], std::string("the ") + what + " array '" + c.name +
											  "' differs from the first piece's arrays");
			}
		if (n != out.size())
			throw Error(paths[p], std::string("the piece lacks ") + what + " arrays of the first piece");
	}
	return out;
}

void append_row(Column& to, const Column& from, std::size_t row)
{
	to.values.insert(to.values.end(), from.values.begin() + std::ptrdiff_t(row * from.dim),
					 from.values.begin() + std::ptrdiff_t((row + 1) * from.dim));
}

// Where each element's entries start in a list of sizes, element after element.
std::vector<uint32> starts_of(const std::vector<uint32>& sizes)
{
	std::vector<uint32> starts(sizes.size());
	uint32 at = 0;
	for (std::size_t i = 0; i < sizes.size(); ++i)
	{
		starts[i] = at;
		at += sizes[i];
	}
	return starts;
}

// An element of a piece: (its global id, or the order it was met; piece; row).
using Row = std::tuple<double, std::size_t, uint32>;

// The elements of the pieces whose vtkGhostType in `columns` is 0 (all of
// them without the array), in increasing global id (the `ids` array) when
// `by_ids`, else piece after piece.
std::vector<Row> owned_rows(const std::vector<MeshData>& pieces, std::vector<Column> MeshData::*columns,
							uint32 (MeshData::*count)() const, bool by_ids)
{
	std::vector<Row> rows;
	for (std::size_t p = 0; p < pieces.size(); ++p)
	{
		const Column* ghost = find_column(pieces[p].*columns, GHOST);
		const Column* ids = by_ids ? find_column(pieces[p].*columns, CELL_IDS) : nullptr;
		for (uint32 r = 0, n = (pieces[p].*count)(); r < n; ++r)
			if (ghost == nullptr || ghost->values[r * ghost->dim] == 0)
				rows.emplace_back(ids != nullptr ? ids->values[r * ids->dim] : double(rows.size()), p, r);
	}
	std::sort(rows.begin(), rows.end());
	return rows;
}

// Listed faces or segments: the same element on both sides of a cut comes
// once, the first time it is met (keyed by its sorted merged vertices).
struct ElementMerge
{
	std::map<std::vector<uint32>, bool> seen;
	bool first(std::vector<uint32> vertices)
	{
		std::sort(vertices.begin(), vertices.end());
		return seen.emplace(std::move(vertices), true).second;
	}
};

} // namespace

MeshData read_pvtu(const std::string& path)
{
	const std::string index = read_file(path);
	if (index.find("PUnstructuredGrid") == std::string::npos)
		throw Error(path, "not a parallel unstructured grid (no PUnstructuredGrid element)");
	const std::vector<std::string> sources = attribute_values(index, "Piece", "Source", path);
	if (sources.empty())
		throw Error(path, "the index names no piece");
	const std::filesystem::path dir = std::filesystem::path(path).parent_path();
	std::vector<MeshData> pieces;
	std::vector<std::string> paths;
	for (const std::string& s : sources)
	{
		paths.push_back((dir / s).string());
		pieces.push_back(read_vtu(read_file(paths.back()), paths.back()));
		validate(pieces.back(), paths.back());
		if (!pieces.back().corner_columns.empty())
			throw Error(paths.back(), "per-corner data in a piece");
	}

	MeshData out;
	out.vertex_columns = shared_columns(pieces, paths, &MeshData::vertex_columns, "point");
	out.cell_columns = shared_columns(pieces, paths, &MeshData::cell_columns, "cell");
	out.face_columns = shared_columns(pieces, paths, &MeshData::face_columns, "face");
	out.segment_columns = shared_columns(pieces, paths, &MeshData::segment_columns, "edge");
	const bool by_node_ids = find_column(out.vertex_columns, NODE_IDS) != nullptr;

	// merged vertex numbers: by global id (increasing), or piece after piece
	std::vector<std::vector<uint32>> merged(pieces.size());
	std::vector<std::pair<std::size_t, uint32>> origin; // (piece, vertex) of each merged vertex
	if (by_node_ids)
	{
		std::vector<std::tuple<double, std::size_t, uint32>> all;
		for (std::size_t p = 0; p < pieces.size(); ++p)
		{
			const Column& ids = *find_column(pieces[p].vertex_columns, NODE_IDS);
			for (uint32 v = 0; v < pieces[p].nb_vertices(); ++v)
				all.emplace_back(ids.values[v * ids.dim], p, v);
			merged[p].resize(pieces[p].nb_vertices());
		}
		std::sort(all.begin(), all.end());
		for (std::size_t i = 0; i < all.size(); ++i)
		{
			const auto& [id, p, v] = all[i];
			if (i == 0 || id != std::get<0>(all[i - 1]))
				origin.emplace_back(p, v);
			merged[p][v] = uint32(origin.size() - 1);
		}
	}
	else
		for (std::size_t p = 0; p < pieces.size(); ++p)
			for (uint32 v = 0; v < pieces[p].nb_vertices(); ++v)
			{
				merged[p].push_back(uint32(origin.size()));
				origin.emplace_back(p, v);
			}

	// the owned cells and listed faces (a surface's polygons)
	const std::vector<Row> cells = owned_rows(pieces, &MeshData::cell_columns, &MeshData::nb_cells,
											  find_column(out.cell_columns, CELL_IDS) != nullptr);
	const std::vector<Row> faces = owned_rows(pieces, &MeshData::face_columns, &MeshData::nb_faces,
											  find_column(out.face_columns, CELL_IDS) != nullptr);

	// the vertices they use, renumbered in merged order
	std::vector<std::vector<uint32>> first_corner(pieces.size()), first_face_corner(pieces.size());
	for (std::size_t p = 0; p < pieces.size(); ++p)
	{
		first_corner[p] = starts_of(pieces[p].cell_sizes);
		first_face_corner[p] = starts_of(pieces[p].face_sizes);
	}
	std::vector<uint32> used(origin.size(), INVALID_INDEX);
	for (const auto& [id, p, c] : cells)
		for (uint32 i = 0; i < pieces[p].cell_sizes[c]; ++i)
			used[merged[p][pieces[p].cell_vertices[first_corner[p][c] + i]]] = 0;
	for (const auto& [id, p, f] : faces)
		for (uint32 i = 0; i < pieces[p].face_sizes[f]; ++i)
			used[merged[p][pieces[p].face_vertices[first_face_corner[p][f] + i]]] = 0;
	uint32 nb_used = 0;
	for (uint32 v = 0; v < used.size(); ++v)
		if (used[v] == 0)
		{
			used[v] = nb_used++;
			const auto& [p, pv] = origin[v];
			out.positions.insert(out.positions.end(), pieces[p].positions.begin() + std::ptrdiff_t(3 * pv),
								 pieces[p].positions.begin() + std::ptrdiff_t(3 * pv + 3));
			for (Column& col : out.vertex_columns)
				append_row(col, *find_column(pieces[p].vertex_columns, col.name.c_str()), pv);
		}
	auto vertex_of = [&](std::size_t p, uint32 v) { return used[merged[p][v]]; };

	// polyhedra: their face streams, piece by piece
	std::vector<std::vector<uint32>> first_face(pieces.size()), first_face_vertex(pieces.size());
	for (std::size_t p = 0; p < pieces.size(); ++p)
	{
		uint32 f = 0, k = 0;
		for (uint32 c = 0; c < pieces[p].nb_cells(); ++c)
		{
			first_face[p].push_back(f);
			first_face_vertex[p].push_back(k);
			if (pieces[p].is_polyhedron(c))
				for (uint32 i = 0; i < pieces[p].cell_nb_faces[c]; ++i)
					k += pieces[p].polyhedron_face_sizes[f++];
		}
	}
	for (const auto& [id, p, c] : cells)
	{
		const MeshData& d = pieces[p];
		if (d.is_polyhedron(c))
		{
			std::vector<uint32> sizes, ids;
			uint32 k = first_face_vertex[p][c];
			for (uint32 i = 0; i < d.cell_nb_faces[c]; ++i)
			{
				const uint32 n = d.polyhedron_face_sizes[first_face[p][c] + i];
				sizes.push_back(n);
				for (uint32 j = 0; j < n; ++j)
					ids.push_back(vertex_of(p, d.polyhedron_face_vertices[k++]));
			}
			out.add_polyhedron(d.cell_nb_faces[c], sizes, ids);
		}
		else
		{
			out.cell_sizes.push_back(d.cell_sizes[c]);
			for (uint32 i = 0; i < d.cell_sizes[c]; ++i)
				out.cell_vertices.push_back(vertex_of(p, d.cell_vertices[first_corner[p][c] + i]));
		}
		for (Column& col : out.cell_columns)
			append_row(col, *find_column(d.cell_columns, col.name.c_str()), c);
	}
	out.finish_polyhedra();

	// listed faces (in order) and edges with data, the same one from two
	// pieces once
	ElementMerge merged_faces, merged_segments;
	for (const auto& [id, p, f] : faces)
	{
		const MeshData& d = pieces[p];
		std::vector<uint32> ids;
		for (uint32 i = 0; i < d.face_sizes[f]; ++i)
			ids.push_back(vertex_of(p, d.face_vertices[first_face_corner[p][f] + i]));
		if (!merged_faces.first(ids))
			continue;
		out.face_sizes.push_back(uint32(ids.size()));
		out.face_vertices.insert(out.face_vertices.end(), ids.begin(), ids.end());
		for (Column& col : out.face_columns)
			append_row(col, *find_column(d.face_columns, col.name.c_str()), f);
	}
	for (std::size_t p = 0; p < pieces.size(); ++p)
	{
		const MeshData& d = pieces[p];
		for (std::size_t s = 0; s < d.segments.size(); ++s)
		{
			const uint32 a = vertex_of(p, d.segments[s].first), b = vertex_of(p, d.segments[s].second);
			if (a == INVALID_INDEX || b == INVALID_INDEX || !merged_segments.first({a, b}))
				continue;
			out.segments.emplace_back(a, b);
			for (Column& col : out.segment_columns)
				append_row(col, *find_column(d.segment_columns, col.name.c_str()), s);
		}
	}
	for (const MeshData& d : pieces)
		out.dropped.insert(out.dropped.end(), d.dropped.begin(), d.dropped.end());
	return out;
}

} // namespace cgogn::io::detail
