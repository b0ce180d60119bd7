// SPDX-License-Identifier: MIT
// gmsh .msh versions 2.2 and 4.1, ascii and binary. Volume elements
// (tetrahedron 4, hexahedron 5, prism 6, pyramid 7, and the corner nodes of
// second-order ones) are kept, lower-dimensional elements ignored; other
// sections ($PhysicalNames, $Entities, $NodeData, ...) are skipped.
#include "byte_reader.h"
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace cgogn::io::detail
{

namespace
{

// Number of nodes of a gmsh element type (0: unknown), and how many of them
// are the corners of a volume cell (0: not a volume cell).
struct ElementType
{
	uint32 nodes;
	uint32 corners;
};
ElementType element_type(int64 t)
{
	switch (t)
	{
	case 1:
		return {2, 0};
	case 2:
		return {3, 0};
	case 3:
		return {4, 0};
	case 4:
		return {4, 4};
	case 5:
		return {8, 8};
	case 6:
		return {6, 6};
	case 7:
		return {5, 5};
	case 8:
		return {3, 0};
	case 9:
		return {6, 0};
	case 10:
		return {9, 0};
	case 11:
		return {10, 4};
	case 12:
		return {27, 8};
	case 13:
		return {18, 6};
	case 14:
		return {14, 5};
	case 15:
		return {1, 0};
	case 16:
		return {8, 0};
	case 17:
		return {20, 8};
	case 18:
		return {15, 6};
	case 19:
		return {13, 5};
	default:
		return {0, 0};
	}
}

class GmshReader
{
public:
	GmshReader(std::string_view data, const std::string& path) : data_(data), t_(data, path, '\0'), path_(path)
	{
	}

	MeshData read()
	{
		if (t_.token() != "$MeshFormat")
			t_.fail("not a gmsh file: it does not start with $MeshFormat");
		const std::string_view version = t_.token();
		if (version == "2.2" || version == "2.1" || version == "2")
			v4_ = false;
		else if (version == "4.1")
			v4_ = true;
		else
			t_.fail("gmsh format version " + TextReader::printable(version) + " is not read (2.2 and 4.1 are)");
		binary_ = t_.read_int("the file type") == 1;
		const int64 size_t_size = t_.read_int("the data size");
		if (size_t_size != 8 && size_t_size != 4)
			t_.fail("unsupported data size " + std::to_string(size_t_size));
		size_t_size_ = uint32(size_t_size);
		if (binary_)
		{
			t_.next_line();
			ByteReader b(data_, offset(), path_, false);
			const int32 one = b.read<int32>();
			if (one != 1)
			{
				if (one != 0x01000000)
					b.fail("bad endianness marker in $MeshFormat");
				big_endian_ = true;
			}
			t_.set_position(data_.data() + b.position());
		}
		expect("$EndMeshFormat");
		bool have_nodes = false, have_elements = false;
		while (true)
		{
			const std::string_view k = t_.token();
			if (k.empty())
				break;
			if (k == "$Nodes")
			{
				v4_ ? nodes4() : nodes2();
				expect("$EndNodes");
				have_nodes = true;
			}
			else if (k == "$Elements")
			{
				if (!have_nodes)
					t_.fail("$Elements before $Nodes");
				v4_ ? elements4() : elements2();
				expect("$EndElements");
				have_elements = true;
			}
			else if (k.size() > 1 && k[0] == '$')
			{
				// skip to the matching $End section (binary sections included)
				const std::string end = "$End" + std::string(k.substr(1));
				const std::size_t at = data_.find(end, offset());
				if (at == std::string_view::npos)
					t_.fail("section " + TextReader::printable(k) + " without " + TextReader::printable(end));
				t_.set_position(data_.data() + at + end.size());
			}
			else
				t_.fail("unexpected '" + TextReader::printable(k) + "' between sections");
		}
		if (!have_nodes || !have_elements)
			t_.fail("no $Nodes or $Elements section");
		return std::move(d_);
	}

private:
	std::size_t offset() const
	{
		return std::size_t(t_.position() - data_.data());
	}
	void expect(std::string_view w)
	{
		const std::string_view k = t_.token();
		if (k != w)
			t_.fail("expected " + std::string(w) + ", found '" + TextReader::printable(k) + "'");
	}
	uint64 read_size(ByteReader& b)
	{
		return size_t_size_ == 8 ? b.read<uint64>() : b.read<uint32>();
	}
	void add_node(uint64 tag, double x, double y, double z, auto& reader)
	{
		if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
			reader.fail("node coordinate is not finite: NaN and infinite values are rejected");
		if (!index_.try_emplace(tag, d_.nb_vertices()).second)
			reader.fail("node tag " + std::to_string(tag) + " defined twice");
		d_.positions.insert(d_.positions.end(), {x, y, z});
	}
	template <typename READER>
	void add_element(int64 type, const uint64* nodes, READER& reader)
	{
		const ElementType et = element_type(type);
		if (et.nodes == 0)
			reader.fail("unsupported gmsh element type " + std::to_string(type));
		if (et.corners == 0)
			return;
		for (uint32 i = 0; i < et.corners; ++i)
		{
			auto it = index_.find(nodes[i]);
			if (it == index_.end())
				reader.fail("element refers to node " + std::to_string(nodes[i]) + ", which is not defined");
			d_.cell_vertices.push_back(it->second);
		}
		d_.cell_sizes.push_back(et.corners);
	}

	void nodes2()
	{
		const uint32 n = t_.read_uint("a node count");
		if (binary_)
		{
			t_.next_line();
			ByteReader b(data_, offset(), path_, big_endian_);
			b.check_count(n, 28, "nodes");
			index_.reserve(n);
			for (uint32 i = 0; i < n; ++i)
			{
				const uint64 tag = uint32(b.read<int32>());
				const double x = b.read<double>(), y = b.read<double>(), z = b.read<double>();
				add_node(tag, x, y, z, b);
			}
			t_.set_position(data_.data() + b.position());
			return;
		}
		t_.check_count(n, 8, "nodes");
		index_.reserve(n);
		for (uint32 i = 0; i < n; ++i)
		{
			const uint64 tag = t_.read_uint("a node tag");
			const double x = t_.read_double("a coordinate"), y = t_.read_double("a coordinate"),
						 z = t_.read_double("a coordinate");
			add_node(tag, x, y, z, t_);
		}
	}

	void elements2()
	{
		const uint32 n = t_.read_uint("an element count");
		std::array<uint64, 27> nodes{};
		if (binary_)
		{
			t_.next_line();
			ByteReader b(data_, offset(), path_, big_endian_);
			b.check_count(n, 8, "elements");
			uint32 done = 0;
			while (done < n)
			{
				const int32 type = b.read<int32>();
				const int32 count = b.read<int32>();
				const int32 ntags = b.read<int32>();
				const ElementType et = element_type(type);
				if (et.nodes == 0)
					b.fail("unsupported gmsh element type " + std::to_string(type));
				if (count <= 0 || uint32(count) > n - done || ntags < 0 || ntags > 1000)
					b.fail("bad element block header");
				for (int32 e = 0; e < count; ++e)
				{
					b.skip(4 * (1 + std::size_t(ntags)));
					for (uint32 i = 0; i < et.nodes; ++i)
						nodes[i] = uint32(b.read<int32>());
					add_element(type, nodes.data(), b);
				}
				done += uint32(count);
			}
			t_.set_position(data_.data() + b.position());
			return;
		}
		t_.check_count(n, 8, "elements");
		for (uint32 e = 0; e < n; ++e)
		{
			t_.read_uint("an element tag");
			const int64 type = t_.read_int("an element type");
			const ElementType et = element_type(type);
			if (et.nodes == 0)
				t_.fail("unsupported gmsh element type " + std::to_string(type));
			const uint32 ntags = t_.read_uint("a tag count");
			for (uint32 i = 0; i < ntags; ++i)
				t_.read_int("a tag");
			for (uint32 i = 0; i < et.nodes; ++i)
				nodes[i] = t_.read_uint("a node tag");
			add_element(type, nodes.data(), t_);
		}
	}

	void nodes4()
	{
		if (binary_)
		{
			t_.next_line();
			ByteReader b(data_, offset(), path_, big_endian_);
			const uint64 blocks = read_size(b), n = read_size(b);
			read_size(b);
			read_size(b);
			b.check_count(n, 32, "nodes");
			b.check_count(blocks, 16, "node blocks");
			index_.reserve(n);
			std::vector<uint64> tags;
			for (uint64 k = 0; k < blocks; ++k)
			{
				b.read<int32>();
				b.read<int32>();
				const int32 parametric = b.read<int32>();
				const uint64 m = read_size(b);
				b.check_count(m, size_t_size_ + 24, "nodes");
				tags.resize(m);
				for (auto& t : tags)
					t = read_size(b);
				for (uint64 i = 0; i < m; ++i)
				{
					const double x = b.read<double>(), y = b.read<double>(), z = b.read<double>();
					if (parametric)
						b.skip(24);
					add_node(tags[i], x, y, z, b);
				}
			}
			t_.set_position(data_.data() + b.position());
			return;
		}
		const uint64 blocks = t_.read_uint("a block count"), n = t_.read_uint("a node count");
		t_.read_uint("a node tag");
		t_.read_uint("a node tag");
		t_.check_count(n, 8, "nodes");
		t_.check_count(blocks, 8, "node blocks");
		index_.reserve(n);
		std::vector<uint64> tags;
		for (uint64 k = 0; k < blocks; ++k)
		{
			t_.read_int("an entity dimension");
			t_.read_int("an entity tag");
			const int64 parametric = t_.read_int("the parametric flag");
			const uint32 m = t_.read_uint("a node count");
			t_.check_count(m, 8, "nodes");
			tags.resize(m);
			for (auto& t : tags)
				t = t_.read_uint("a node tag");
			for (uint32 i = 0; i < m; ++i)
			{
				const double x = t_.read_double("a coordinate"), y = t_.read_double("a coordinate"),
							 z = t_.read_double("a coordinate");
				if (parametric)
					for (int j = 0; j < 3; ++j)
						t_.read_double("a parametric coordinate");
				add_node(tags[i], x, y, z, t_);
			}
		}
	}

	void elements4()
	{
		std::array<uint64, 27> nodes{};
		if (binary_)
		{
			t_.next_line();
			ByteReader b(data_, offset(), path_, big_endian_);
			const uint64 blocks = read_size(b);
			read_size(b);
			read_size(b);
			read_size(b);
			b.check_count(blocks, 20, "element blocks");
			for (uint64 k = 0; k < blocks; ++k)
			{
				b.read<int32>();
				b.read<int32>();
				const int32 type = b.read<int32>();
				const uint64 m = read_size(b);
				const ElementType et = element_type(type);
				if (et.nodes == 0)
					b.fail("unsupported gmsh element type " + std::to_string(type));
				b.check_count(m, uint64(size_t_size_) * (1 + et.nodes), "elements");
				for (uint64 e = 0; e < m; ++e)
				{
					read_size(b);
					for (uint32 i = 0; i < et.nodes; ++i)
						nodes[i] = read_size(b);
					add_element(type, nodes.data(), b);
				}
			}
			t_.set_position(data_.data() + b.position());
			return;
		}
		const uint64 blocks = t_.read_uint("a block count");
		t_.read_uint("an element count");
		t_.read_uint("an element tag");
		t_.read_uint("an element tag");
		t_.check_count(blocks, 8, "element blocks");
		for (uint64 k = 0; k < blocks; ++k)
		{
			t_.read_int("an entity dimension");
			t_.read_int("an entity tag");
			const int64 type = t_.read_int("an element type");
			const uint32 m = t_.read_uint("an element count");
			const ElementType et = element_type(type);
			if (et.nodes == 0)
				t_.fail("unsupported gmsh element type " + std::to_string(type));
			t_.check_count(m, 2 * (1 + et.nodes), "elements");
			for (uint32 e = 0; e < m; ++e)
			{
				t_.read_uint("an element tag");
				for (uint32 i = 0; i < et.nodes; ++i)
					nodes[i] = t_.read_uint("a node tag");
				add_element(type, nodes.data(), t_);
			}
		}
	}

	std::string_view data_;
	TextReader t_;
	const std::string& path_;
	bool v4_ = true;
	bool binary_ = false;
	bool big_endian_ = false;
	uint32 size_t_size_ = 8;
	MeshData d_;
	std::unordered_map<uint64, uint32> index_;
};

} // namespace

MeshData read_gmsh(std::string_view data, const std::string& path)
{
	return GmshReader(data, path).read();
}

std::string write_gmsh(const MeshData& d, bool binary)
{
	std::string s = binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n";
	if (binary)
	{
		append_raw(s, int32(1));
		s += '\n';
	}
	s += "$EndMeshFormat\n$Nodes\n";
	const uint64 nv = d.nb_vertices();
	if (binary)
	{
		for (uint64 v : {uint64(1), nv, uint64(1), nv})
			append_raw(s, v);
		append_raw(s, int32(3));
		append_raw(s, int32(1));
		append_raw(s, int32(0));
		append_raw(s, nv);
		for (uint64 i = 1; i <= nv; ++i)
			append_raw(s, i);
		for (double x : d.positions)
			append_raw(s, x);
		s += '\n';
	}
	else
	{
		s += "1 " + std::to_string(nv) + " 1 " + std::to_string(nv) + "\n3 1 0 " + std::to_string(nv) + "\n";
		for (uint64 i = 1; i <= nv; ++i)
		{
			append_uint(s, i);
			s += '\n';
		}
		for (std::size_t i = 0; i < d.positions.size(); ++i)
		{
			append_double(s, d.positions[i]);
			s += i % 3 == 2 ? '\n' : ' ';
		}
	}
	s += "$EndNodes\n$Elements\n";
	std::vector<std::size_t> first(d.nb_cells());
	std::size_t k = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		first[c] = k;
		k += d.cell_sizes[c];
	}
	const std::array<std::pair<uint32, int32>, 4> kinds = {{{4, 4}, {8, 5}, {6, 6}, {5, 7}}};
	uint64 blocks = 0;
	for (const auto& [size, type] : kinds)
		blocks += std::count(d.cell_sizes.begin(), d.cell_sizes.end(), size) > 0;
	const uint64 ne = d.nb_cells();
	if (binary)
		for (uint64 v : {blocks, ne, uint64(1), ne})
			append_raw(s, v);
	else
		s += std::to_string(blocks) + " " + std::to_string(ne) + " 1 " + std::to_string(ne) + "\n";
	uint64 tag = 1;
	for (const auto& [size, type] : kinds)
	{
		const uint64 count = uint64(std::count(d.cell_sizes.begin(), d.cell_sizes.end(), size));
		if (count == 0)
			continue;
		if (binary)
		{
			append_raw(s, int32(3));
			append_raw(s, int32(1));
			append_raw(s, type);
			append_raw(s, count);
		}
		else
			s += "3 1 " + std::to_string(type) + " " + std::to_string(count) + "\n";
		for (uint32 c = 0; c < d.nb_cells(); ++c)
		{
			if (d.cell_sizes[c] != size)
				continue;
			if (binary)
			{
				append_raw(s, tag++);
				for (uint32 i = 0; i < size; ++i)
					append_raw(s, uint64(d.cell_vertices[first[c] + i]) + 1);
			}
			else
			{
				append_uint(s, tag++);
				for (uint32 i = 0; i < size; ++i)
				{
					s += ' ';
					append_uint(s, uint64(d.cell_vertices[first[c] + i]) + 1);
				}
				s += '\n';
			}
		}
	}
	if (binary)
		s += '\n';
	s += "$EndElements\n";
	return s;
}

} // namespace cgogn::io::detail
