// SPDX-License-Identifier: MIT
#include "vtk_cells.h"

#include <array>

namespace cgogn::io::detail
{

void vtk_cells_to_mesh(MeshData& d, const std::vector<int64>& offsets, const std::vector<int64>& connectivity,
					   const std::vector<int64>& types, const std::vector<Column>& cell_data,
					   const std::function<void(const std::string&)>& fail)
{
	if (types.size() + 1 != offsets.size())
		fail("the cell types and the cell list do not have the same number of cells");
	const uint32 nv = d.nb_vertices();
	std::vector<uint32> kept;
	for (std::size_t c = 0; c < types.size(); ++c)
	{
		const int64 b = offsets[c], e = offsets[c + 1];
		if (b < 0 || e < b || e > int64(connectivity.size()))
			fail("inconsistent cell offsets");
		const int64* ids = connectivity.data() + b;
		const int64 n = e - b;
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
				d.segments.emplace_back(uint32(ids[i]), uint32(ids[i + 1]));
			continue; // segments, not volume cells
		case 1:
		case 2:
		case 5:
		case 6:
		case 7:
		case 8:
		case 9:
		case 21:
		case 22:
		case 23:
			continue; // not volume cells
		default:
			fail("cell " + std::to_string(c) + ": unsupported VTK cell type " + std::to_string(types[c]));
		}
		d.cell_sizes.push_back(size);
		d.cell_vertices.insert(d.cell_vertices.end(), v.begin(), v.begin() + size);
		kept.push_back(uint32(c));
	}
	for (const auto& col : cell_data)
	{
		if (col.values.size() != types.size() * col.dim)
			fail("cell data '" + col.name + "' does not have one value per cell");
		Column k{col.name, col.dim, {}};
		for (uint32 c : kept)
			k.values.insert(k.values.end(), col.values.begin() + std::ptrdiff_t(c) * col.dim,
							col.values.begin() + std::ptrdiff_t(c + 1) * col.dim);
		d.cell_columns.push_back(std::move(k));
	}
}

} // namespace cgogn::io::detail
