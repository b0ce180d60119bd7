// SPDX-License-Identifier: MIT
#include "vtk_cells.h"

#include <algorithm>
#include <array>

namespace cgogn::io::detail
{

void vtk_cells_to_mesh(MeshData& d, const std::vector<int64>& offsets, const std::vector<int64>& connectivity,
					   const std::vector<int64>& types, const std::vector<Column>& cell_data,
					   const std::function<void(const std::string&)>& fail, const std::vector<int64>& faces,
					   const std::vector<int64>& face_offsets)
{
	if (types.size() + 1 != offsets.size())
		fail("the cell types and the cell list do not have the same number of cells");
	const bool vtu_faces = !face_offsets.empty();
	if (vtu_faces && face_offsets.size() != types.size())
		fail("the faceoffsets array does not have one entry per cell");
	const uint32 nv = d.nb_vertices();
	std::vector<uint32> kept, kept_faces, kept_segments; // the cells kept as volumes, listed faces, segments
	uint32 nb_ignored = 0;                               // vertex cells and triangle strips
	int64 stream_start = 0;                              // where the next polyhedron's faces start in `faces`
	std::vector<uint32> face_sizes, face_ids;            // one polyhedron's
	// A polyhedron's face stream: its number of faces, then each face's
	// number of points and point ids, exactly.
	auto add_polyhedron = [&](std::size_t c, const int64* stream, int64 length) {
		const std::string cell = "cell " + std::to_string(c) + " (a polyhedron)";
		if (length < 1 || stream[0] < 1 || stream[0] > length)
			fail(cell + ": its face stream does not start with a number of faces");
		face_sizes.clear();
		face_ids.clear();
		int64 k = 1;
		for (int64 f = 0; f < stream[0]; ++f)
		{
			if (k >= length || stream[k] < 0 || stream[k] > length - k - 1)
				fail(cell + ": face " + std::to_string(f) + " runs past the end of its face stream");
			const int64 n = stream[k++];
			face_sizes.push_back(uint32(n));
			for (int64 i = 0; i < n; ++i, ++k)
			{
				if (stream[k] < 0 || stream[k] >= int64(nv))
					fail(cell + ": point index " + std::to_string(stream[k]) + " out of range (the file has " +
						 std::to_string(nv) + " points)");
				face_ids.push_back(uint32(stream[k]));
			}
		}
		if (k != length)
			fail(cell + ": its face stream has " + std::to_string(length - k) + " values after its faces");
		d.add_polyhedron(uint32(stream[0]), face_sizes, face_ids);
		kept.push_back(uint32(c));
	};
	for (std::size_t c = 0; c < types.size(); ++c)
	{
		const int64 b = offsets[c], e = offsets[c + 1];
		if (b < 0 || e < b || e > int64(connectivity.size()))
			fail("inconsistent cell offsets");
		const int64* ids = connectivity.data() + b;
		const int64 n = e - b;
		if (types[c] == 42)
		{
			if (!vtu_faces) // the connectivity is the face stream
				add_polyhedron(c, ids, n);
			else
			{
				const int64 end = face_offsets[c];
				if (end < stream_start || end > int64(faces.size()))
					fail("cell " + std::to_string(c) + " (a polyhedron): faceoffsets entry " + std::to_string(end) +
						 " out of the faces array");
				add_polyhedron(c, faces.data() + stream_start, end - stream_start);
				stream_start = end;
			}
			continue;
		}
		if ((types[c] == 15 || types[c] == 16) && n >= 2 * (types[c] - 10))
		{
			// pentagonal and hexagonal prisms: a polyhedron of two k-gons and
			// k quads (turned outward on load)
			const int64 k = types[c] - 10;
			std::vector<int64> stream{k + 2, k};
			for (int64 i = 0; i < k; ++i)
				stream.push_back(ids[i]);
			stream.push_back(k);
			for (int64 i = 0; i < k; ++i)
				stream.push_back(ids[k + i]);
			for (int64 i = 0; i < k; ++i)
				stream.insert(stream.end(), {4, ids[i], ids[(i + 1) % k], ids[k + (i + 1) % k], ids[k + i]});
			add_polyhedron(c, stream.data(), int64(stream.size()));
			continue;
		}
		for (int64 i = 0; i < n; ++i)
			if (ids[i] < 0 || ids[i] >= int64(nv))
				fail("cell " + std::to_string(c) + ": point index " + std::to_string(ids[i]) +
					 " out of range (the file has " + std::to_string(nv) + " points)");
		std::array<uint32, 8> v{};
		uint32 size = 0;
		auto take = [&](std::initializer_list<int> order, int64 needed) {
			if (n < needed)
				fail("cell " + std::to_string(c) + " of type " + std::to_string(types[c]) + " has only " +
					 std::to_string(n) + " points");
			for (int o : order)
				v[size++] = uint32(ids[o]);
		};
		switch (types[c])
		{
		case 10:
		case 24:
			take({0, 1, 2, 3}, types[c] == 10 ? 4 : 10);
			break;
		case 11: // voxel: lexicographic corners
			take({0, 1, 3, 2, 4, 5, 7, 6}, 8);
			break;
		case 12:
		case 25:
			take({0, 1, 2, 3, 4, 5, 6, 7}, types[c] == 12 ? 8 : 20);
			break;
		case 13: // VTK's base triangle faces away from the top: ours faces it
			take({0, 2, 1, 3, 5, 4}, 6);
			break;
		case 14:
			take({0, 1, 2, 3, 4}, 5);
			break;
		case 3: // line
		case 4: // polyline
			if (n < 2)
				fail("cell " + std::to_string(c) + " of type " + std::to_string(types[c]) + " has " +
					 std::to_string(n) + " point(s) (a line has 2 or more)");
			for (int64 i = 0; i + 1 < (types[c] == 3 ? 2 : n); ++i)
			{
				d.segments.emplace_back(uint32(ids[i]), uint32(ids[i + 1]));
				kept_segments.push_back(uint32(c));
			}
			continue; // segments, not volume cells
		case 5:       // triangle
		case 22:      // quadratic triangle: its corners
		case 9:       // quad
		case 23:      // quadratic quad: its corners
		case 8:       // pixel: lexicographic corners
		case 7:       // polygon
		{
			const int64 corners = types[c] == 5 || types[c] == 22 ? 3 : types[c] == 7 ? n : 4;
			if (n < std::max<int64>(corners, 3))
				fail("cell " + std::to_string(c) + " of type " + std::to_string(types[c]) + " has only " +
					 std::to_string(n) + " points");
			for (int64 i = 0; i < corners; ++i)
				d.face_vertices.push_back(uint32(ids[types[c] == 8 && i >= 2 ? 5 - i : i]));
			d.face_sizes.push_back(uint32(corners));
			kept_faces.push_back(uint32(c));
			continue; // listed faces, not volume cells
		}
		case 1:
		case 2:
		case 6:
		case 21:
			++nb_ignored;
			continue; // not volume cells
		default:
			fail("cell " + std::to_string(c) + ": unsupported VTK cell type " + std::to_string(types[c]));
		}
		d.cell_sizes.push_back(size);
		d.cell_vertices.insert(d.cell_vertices.end(), v.begin(), v.begin() + size);
		kept.push_back(uint32(c));
	}
	d.finish_polyhedra();
	auto rows = [](const Column& col, const std::vector<uint32>& cells) {
		Column k{col.name, col.dim, {}, col.type};
		for (uint32 c : cells)
			k.values.insert(k.values.end(), col.values.begin() + std::ptrdiff_t(c) * col.dim,
							col.values.begin() + std::ptrdiff_t(c + 1) * col.dim);
		return k;
	};
	for (const auto& col : cell_data)
	{
		if (col.values.size() != types.size() * col.dim)
			fail("cell data '" + col.name + "' does not have one value per cell");
		d.cell_columns.push_back(rows(col, kept));
		if (!kept_faces.empty())
			d.face_columns.push_back(rows(col, kept_faces));
		if (!kept_segments.empty())
			d.segment_columns.push_back(rows(col, kept_segments));
	}
	if (nb_ignored > 0)
		d.dropped.push_back(std::to_string(nb_ignored) +
							" vertex, polyvertex, triangle strip or quadratic edge cell(s): a map holds volumes, "
							"faces and edges");
}

std::vector<Column> vtk_cell_data(const MeshData& d)
{
	// rows: the cells, the listed faces, then the segments; a column of one
	// kind is 0 on the rows of the others
	const std::size_t nc = d.nb_cells(), nf = d.nb_faces(), ns = d.segments.size(), rows = nc + nf + ns;
	auto usable = [](const Column& c) { return c.dim >= 1 && c.dim <= 3; };
	std::vector<Column> out;
	auto add = [&](const std::vector<Column>& columns, std::size_t first) {
		for (const Column& c : columns)
		{
			if (!usable(c))
				continue;
			auto same = std::find_if(out.begin(), out.end(), [&](const Column& k) { return k.name == c.name; });
			if (same == out.end())
			{
				out.push_back(Column{c.name, c.dim, std::vector<double>(rows * c.dim, 0.0), c.type});
				same = out.end() - 1;
			}
			else if (same->dim != c.dim)
				continue;
			else if (same->type != c.type)
				same->type = ValueType::Float64;
			std::copy(c.values.begin(), c.values.end(), same->values.begin() + std::ptrdiff_t(first * c.dim));
		}
	};
	add(d.cell_columns, 0);
	add(d.face_columns, nc);
	add(d.segment_columns, nc + nf);
	return out;
}

std::vector<std::vector<uint32>> polyhedron_streams(const MeshData& d)
{
	std::vector<std::vector<uint32>> streams(d.nb_cells());
	std::size_t face = 0, first = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
		if (d.is_polyhedron(c))
		{
			std::vector<uint32>& s = streams[c];
			s.push_back(d.cell_nb_faces[c]);
			for (uint32 f = 0; f < d.cell_nb_faces[c]; ++f)
			{
				const uint32 n = d.polyhedron_face_sizes[face++];
				s.push_back(n);
				s.insert(s.end(), d.polyhedron_face_vertices.begin() + std::ptrdiff_t(first),
						 d.polyhedron_face_vertices.begin() + std::ptrdiff_t(first + n));
				first += n;
			}
		}
	return streams;
}

} // namespace cgogn::io::detail
