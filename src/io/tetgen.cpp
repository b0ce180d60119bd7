// SPDX-License-Identifier: MIT
// TetGen .node/.ele: tetrahedra (the 4 corners of 10-node ones), node ids
// starting at the first id of the .node file (0 or 1), comments with '#'.
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"

#include <unordered_map>

namespace cgogn::io::detail
{

MeshData read_tetgen(std::string_view node, const std::string& node_path, std::string_view ele,
					 const std::string& ele_path)
{
	MeshData d;
	TextReader r(node, node_path);
	const uint32 n = r.read_uint("a node count");
	const uint32 dim = r.read_uint("the dimension");
	if (dim != 3)
		r.fail("dimension " + std::to_string(dim) + " (3 expected)");
	const uint32 nattr = r.read_uint("an attribute count");
	const uint32 nbm = r.read_uint("a boundary marker count");
	if (nbm > 1)
		r.fail("at most one boundary marker per node");
	r.check_count(n, 8, "nodes");
	d.positions.reserve(3 * std::size_t(n));
	int64 first_id = 0;
	for (uint32 i = 0; i < n; ++i)
	{
		const int64 id = r.read_int("a node id");
		if (i == 0)
			first_id = id;
		if (id != first_id + int64(i))
			r.fail("node ids must be consecutive (found " + std::to_string(id) + ", expected " +
				   std::to_string(first_id + int64(i)) + ")");
		for (int k = 0; k < 3; ++k)
			d.positions.push_back(r.read_double("a coordinate"));
		for (uint32 k = 0; k < nattr + nbm; ++k)
			r.read_double("a node attribute");
	}
	if (!r.at_end())
		r.fail("unexpected content after the declared nodes");

	TextReader e(ele, ele_path);
	const uint32 nt = e.read_uint("a tetrahedron count");
	const uint32 per = e.read_uint("the nodes per tetrahedron");
	if (per != 4 && per != 10)
		e.fail("tetrahedra of " + std::to_string(per) + " nodes (4 or 10 expected)");
	const uint32 eattr = e.read_uint("a region attribute count");
	e.check_count(nt, 2 * (per + 1), "tetrahedra");
	d.cell_sizes.assign(nt, 4);
	d.cell_vertices.reserve(4 * std::size_t(nt));
	for (uint32 t = 0; t < nt; ++t)
	{
		e.read_int("a tetrahedron id");
		for (uint32 k = 0; k < per; ++k)
		{
			const int64 id = e.read_int("a node id");
			if (id < first_id || id >= first_id + int64(n))
				e.fail("node id " + std::to_string(id) + " out of range (nodes are " + std::to_string(first_id) + ".." +
					   std::to_string(first_id + int64(n) - 1) + ")");
			if (k < 4)
				d.cell_vertices.push_back(uint32(id - first_id));
		}
		for (uint32 k = 0; k < eattr; ++k)
			e.read_double("a region attribute");
	}
	if (!e.at_end())
		e.fail("unexpected content after the declared tetrahedra");
	return d;
}

std::pair<std::string, std::string> write_tetgen(const MeshData& d)
{
	std::string node, ele;
	node = std::to_string(d.nb_vertices()) + " 3 0 0\n";
	for (uint32 v = 0; v < d.nb_vertices(); ++v)
	{
		append_uint(node, uint64(v) + 1);
		for (uint32 k = 0; k < 3; ++k)
		{
			node += ' ';
			append_double(node, d.positions[3 * std::size_t(v) + k]);
		}
		node += '\n';
	}
	ele = std::to_string(d.nb_cells()) + " 4 0\n";
	std::size_t k = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		append_uint(ele, uint64(c) + 1);
		for (uint32 i = 0; i < 4; ++i)
		{
			ele += ' ';
			append_uint(ele, uint64(d.cell_vertices[k + i]) + 1);
		}
		k += d.cell_sizes[c];
		ele += '\n';
	}
	return {node, ele};
}

} // namespace cgogn::io::detail
