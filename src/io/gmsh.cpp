// SPDX-License-Identifier: MIT
// gmsh .msh versions 2.2 and 4.1, ascii and binary. Volume elements
// (tetrahedron 4, hexahedron 5, prism 6, pyramid 7, and the corner nodes of
// second-order ones) are the cells; surface elements (triangle 2,
// quadrangle 3, and the corners of second-order ones) are listed faces, and
// line elements (1, and the ends of 8) listed edges (MeshData::segments);
// all keep their physical and elementary tags as the columns
// `gmsh:physical` and `gmsh:geometrical` (the names meshio gives them), the
// physical tags of a 4.1 file coming from its $Entities. Point elements are
// counted in the report; other sections ($NodeData, ...) are skipped.
#include "byte_reader.h"
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"
#include "value_type_names.h"

#include <climits>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
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
	uint32 corners;          // of a volume cell
	uint32 face_corners = 0; // of a surface element, or 2 for a line
	bool line = false;
};
ElementType element_type(int64 t)
{
	switch (t)
	{
	case 1:
		return {2, 0, 2, true};
	case 2:
		return {3, 0, 3};
	case 3:
		return {4, 0, 4};
	case 4:
		return {4, 4};
	case 5:
		return {8, 8};
	case 6:
		return {6, 6};
	case 7:
		return {5, 5};
	case 8:
		return {3, 0, 2, true};
	case 9:
		return {6, 0, 3};
	case 10:
		return {9, 0, 4};
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
		return {8, 0, 4};
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
			else if (k == "$Entities")
			{
				entities();
				expect("$EndEntities");
			}
			else if (k == "$PhysicalNames")
			{
				physical_names();
				expect("$EndPhysicalNames");
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
		finish();
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
	// Adds an element with its physical and elementary tags: a volume cell,
	// a listed face, a listed edge, or a point element (counted).
	template <typename READER>
	void add_element(int64 type, const uint64* nodes, int64 physical, int64 elementary, READER& reader)
	{
		const ElementType et = element_type(type);
		if (et.nodes == 0)
			reader.fail("unsupported gmsh element type " + std::to_string(type));
		const uint32 corners = et.corners > 0 ? et.corners : et.face_corners;
		if (corners == 0)
		{
			++nb_point_elements_;
			return;
		}
		if (physical < INT32_MIN || physical > INT32_MAX || elementary < INT32_MIN || elementary > INT32_MAX)
			reader.fail("an element tag out of the 32-bit range");
		std::array<uint32, 8> ids;
		for (uint32 i = 0; i < corners; ++i)
		{
			auto it = index_.find(nodes[i]);
			if (it == index_.end())
				reader.fail("element refers to node " + std::to_string(nodes[i]) + ", which is not defined");
			ids[i] = it->second;
		}
		const std::array<double, 2> tags = {double(physical), double(elementary)};
		if (et.line)
		{
			d_.segments.emplace_back(ids[0], ids[1]);
			segment_tags_.push_back(tags);
			return;
		}
		std::vector<uint32>& to = et.corners > 0 ? d_.cell_vertices : d_.face_vertices;
		to.insert(to.end(), ids.begin(), ids.begin() + corners);
		(et.corners > 0 ? d_.cell_sizes : d_.face_sizes).push_back(corners);
		(et.corners > 0 ? cell_tags_ : face_tags_).push_back(tags);
	}

	// The physical tag of the entity (dim, tag) of a 4.1 file: the first of
	// its physical tags, 0 when it has none.
	int64 physical_of(int64 dim, int64 tag) const
	{
		const auto it = physical_.find({dim, tag});
		return it == physical_.end() ? 0 : it->second;
	}

	// $PhysicalNames (ascii in every file): dimension, tag and quoted name
	// of each physical group.
	void physical_names()
	{
		const uint32 n = t_.read_uint("a physical name count");
		t_.check_count(n, 6, "physical names");
		for (uint32 i = 0; i < n; ++i)
		{
			const int64 dim = t_.read_int("a dimension");
			const int64 tag = t_.read_int("a physical tag");
			const std::string_view rest = t_.rest_of_line();
			const std::size_t q0 = rest.find('"'), q1 = rest.rfind('"');
			if (q0 == std::string_view::npos || q1 == q0)
				t_.fail("a physical name without its quotes");
			if (dim < 0 || dim > 3 || tag < INT32_MIN || tag > INT32_MAX)
				t_.fail("a physical name of dimension " + std::to_string(dim) + " and tag " + std::to_string(tag));
			d_.physical_names.push_back({int32(dim), int32(tag), std::string(rest.substr(q0 + 1, q1 - q0 - 1))});
			t_.next_line();
		}
	}

	// $Entities (4.1): the physical tags of the points, curves, surfaces
	// and volumes.
	void entities()
	{
		int64 counts[4];
		std::vector<int64> physicals;
		if (binary_)
		{
			t_.next_line();
			ByteReader b(data_, offset(), path_, big_endian_);
			for (int64& c : counts)
				c = int64(read_size(b));
			for (int64 dim = 0; dim < 4; ++dim)
			{
				b.check_count(uint64(counts[dim]), 16, "entities");
				for (int64 e = 0; e < counts[dim]; ++e)
				{
					const int64 tag = b.read<int32>();
					b.skip(dim == 0 ? 24 : 48); // the point, or the bounding box
					const uint64 np = read_size(b);
					b.check_count(np, 4, "physical tags");
					physicals.resize(np);
					for (int64& p : physicals)
						p = b.read<int32>();
					add_entity(dim, tag, physicals);
					if (dim > 0)
					{
						const uint64 nb = read_size(b);
						b.check_count(nb, 4, "bounding entities");
						b.skip(4 * nb);
					}
				}
			}
			t_.set_position(data_.data() + b.position());
			return;
		}
		for (int64& c : counts)
			c = int64(t_.read_uint("an entity count"));
		for (int64 dim = 0; dim < 4; ++dim)
		{
			t_.check_count(uint64(counts[dim]), 8, "entities");
			for (int64 e = 0; e < counts[dim]; ++e)
			{
				const int64 tag = t_.read_int("an entity tag");
				for (int i = 0; i < (dim == 0 ? 3 : 6); ++i)
					t_.read_double("a coordinate");
				const uint64 np = t_.read_uint("a physical tag count");
				t_.check_count(np, 2, "physical tags");
				physicals.resize(np);
				for (int64& p : physicals)
					p = t_.read_int("a physical tag");
				add_entity(dim, tag, physicals);
				if (dim > 0)
				{
					const uint64 nb = t_.read_uint("a bounding entity count");
					t_.check_count(nb, 2, "bounding entities");
					for (uint64 i = 0; i < nb; ++i)
						t_.read_int("a bounding entity");
				}
			}
		}
	}
	void add_entity(int64 dim, int64 tag, const std::vector<int64>& physicals)
	{
		if (physicals.empty())
			return;
		physical_[{dim, tag}] = physicals[0];
		nb_multi_physical_ += physicals.size() > 1;
	}

	// The tags as columns, and what was left out, in the report.
	void finish()
	{
		auto columns = [&](const std::vector<std::array<double, 2>>& tags, std::vector<Column>& out) {
			if (!has_tags_ || tags.empty())
				return;
			Column physical{"gmsh:physical", 1, {}, ValueType::Int32};
			Column elementary{"gmsh:geometrical", 1, {}, ValueType::Int32};
			for (const auto& t : tags)
			{
				physical.values.push_back(t[0]);
				elementary.values.push_back(t[1]);
			}
			out.push_back(std::move(physical));
			out.push_back(std::move(elementary));
		};
		columns(cell_tags_, d_.cell_columns);
		columns(face_tags_, d_.face_columns);
		columns(segment_tags_, d_.segment_columns);
		if (nb_point_elements_ > 0)
			d_.dropped.push_back(std::to_string(nb_point_elements_) +
								 " point element(s): a map holds volumes, faces and edges");
		if (nb_multi_physical_ > 0)
			d_.dropped.push_back(std::to_string(nb_multi_physical_) +
								 " entit(ies) of several physical groups: their elements keep the first");
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
				has_tags_ = has_tags_ || ntags > 0;
				for (int32 e = 0; e < count; ++e)
				{
					b.skip(4); // the element's number
					int64 physical = 0, elementary = 0;
					for (int32 i = 0; i < ntags; ++i)
					{
						const int32 tag = b.read<int32>();
						if (i == 0)
							physical = tag;
						else if (i == 1)
							elementary = tag;
					}
					for (uint32 i = 0; i < et.nodes; ++i)
						nodes[i] = uint32(b.read<int32>());
					add_element(type, nodes.data(), physical, elementary, b);
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
			has_tags_ = has_tags_ || ntags > 0;
			int64 physical = 0, elementary = 0;
			for (uint32 i = 0; i < ntags; ++i)
			{
				const int64 tag = t_.read_int("a tag");
				if (i == 0)
					physical = tag;
				else if (i == 1)
					elementary = tag;
			}
			for (uint32 i = 0; i < et.nodes; ++i)
				nodes[i] = t_.read_uint("a node tag");
			add_element(type, nodes.data(), physical, elementary, t_);
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
			has_tags_ = true; // every element is in an entity
			for (uint64 k = 0; k < blocks; ++k)
			{
				const int32 dim = b.read<int32>();
				const int32 entity = b.read<int32>();
				const int64 physical = physical_of(dim, entity);
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
					add_element(type, nodes.data(), physical, entity, b);
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
		has_tags_ = true; // every element is in an entity
		for (uint64 k = 0; k < blocks; ++k)
		{
			const int64 dim = t_.read_int("an entity dimension");
			const int64 entity = t_.read_int("an entity tag");
			const int64 physical = physical_of(dim, entity);
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
				add_element(type, nodes.data(), physical, entity, t_);
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
	std::map<std::pair<int64, int64>, int64> physical_;                       // (dim, entity tag) -> physical tag (4.1)
	bool has_tags_ = false;                                                   // whether the elements carry tags
	std::vector<std::array<double, 2>> cell_tags_, face_tags_, segment_tags_; // (physical, elementary) of each
	uint64 nb_point_elements_ = 0;
	uint64 nb_multi_physical_ = 0;
};

} // namespace

MeshData read_gmsh(std::string_view data, const std::string& path)
{
	return GmshReader(data, path).read();
}

namespace
{

// The element tags a gmsh file gets for the rows of `columns`: the physical
// tag from `gmsh:physical` (else `medit:ref`, else 0) and the elementary one
// from `gmsh:geometrical` (else 1).
std::vector<std::array<int32, 2>> element_tags(const std::vector<Column>& columns, std::size_t rows,
											   const std::string& path)
{
	const std::vector<int32> physical = int32_tags(columns, {"gmsh:physical", "medit:ref"}, rows, 0, path);
	const std::vector<int32> elementary = int32_tags(columns, {"gmsh:geometrical"}, rows, 1, path);
	std::vector<std::array<int32, 2>> tags(rows);
	for (std::size_t i = 0; i < rows; ++i)
		tags[i] = {physical[i], elementary[i]};
	return tags;
}

// A gmsh entity of the written file: its dimension, tag and physical tag.
struct Entity
{
	int32 dim;
	int32 tag;
	int32 physical;
};

} // namespace

std::string write_gmsh(const MeshData& d, bool binary, const std::string& path)
{
	// the entities: one per (dimension, elementary tag, physical tag); an
	// elementary tag used with several physical tags gets new tags for the
	// others
	const std::vector<std::array<int32, 2>> cell_tags = element_tags(d.cell_columns, d.nb_cells(), path);
	const std::vector<std::array<int32, 2>> face_tags = element_tags(d.face_columns, d.nb_faces(), path);
	const std::vector<std::array<int32, 2>> segment_tags = element_tags(d.segment_columns, d.segments.size(), path);
	std::vector<Entity> entities;
	std::map<std::tuple<int32, int32, int32>, uint32> entity_of; // (dim, elementary, physical) -> entity
	std::map<std::pair<int32, int32>, uint32> tag_users;         // (dim, tag) -> entities using it
	int32 next_tag = 1;
	for (const auto* tags : {&segment_tags, &face_tags, &cell_tags})
		for (const auto& t : *tags)
			next_tag = std::max(next_tag, t[1] + 1);
	auto entity = [&](int32 dim, const std::array<int32, 2>& t) {
		const auto [it, added] = entity_of.try_emplace({dim, t[1], t[0]}, uint32(entities.size()));
		if (added)
			entities.push_back({dim, tag_users[{dim, t[1]}]++ == 0 ? t[1] : next_tag++, t[0]});
		return it->second;
	};
	std::vector<uint32> cell_entity(d.nb_cells()), face_entity(d.nb_faces());
	for (uint32 f = 0; f < d.nb_faces(); ++f)
		face_entity[f] = entity(2, face_tags[f]);
	for (uint32 c = 0; c < d.nb_cells(); ++c)
		cell_entity[c] = entity(3, cell_tags[c]);
	std::vector<uint32> segment_entity(d.segments.size()), segment_ids;
	for (std::size_t e = 0; e < d.segments.size(); ++e)
	{
		segment_entity[e] = entity(1, segment_tags[e]);
		segment_ids.insert(segment_ids.end(), {d.segments[e].first, d.segments[e].second});
	}

	std::string s = binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n";
	if (binary)
	{
		append_raw(s, int32(1));
		s += '\n';
	}
	s += "$EndMeshFormat\n";
	if (!d.physical_names.empty())
	{
		s += "$PhysicalNames\n" + std::to_string(d.physical_names.size()) + "\n";
		for (const auto& p : d.physical_names)
			s += std::to_string(p.dim) + " " + std::to_string(p.tag) + " \"" + p.name + "\"\n";
		s += "$EndPhysicalNames\n";
	}
	s += "$Entities\n";
	std::array<double, 6> box = {0, 0, 0, 0, 0, 0}; // every entity's bounding box: the mesh's
	for (std::size_t i = 0; i < d.positions.size(); ++i)
	{
		const double x = d.positions[i];
		box[i % 3] = i < 3 ? x : std::min(box[i % 3], x);
		box[3 + i % 3] = i < 3 ? x : std::max(box[3 + i % 3], x);
	}
	uint64 nb_of_dim[4] = {0, 0, 0, 0};
	for (const Entity& e : entities)
		++nb_of_dim[e.dim];
	if (binary)
		for (uint64 n : nb_of_dim)
			append_raw(s, n);
	else
		s += "0 " + std::to_string(nb_of_dim[1]) + " " + std::to_string(nb_of_dim[2]) + " " +
			 std::to_string(nb_of_dim[3]) + "\n";
	for (int32 dim : {1, 2, 3})
		for (const Entity& e : entities)
		{
			if (e.dim != dim)
				continue;
			const uint64 np = e.physical != 0 ? 1 : 0;
			if (binary)
			{
				append_raw(s, e.tag);
				for (double x : box)
					append_raw(s, x);
				append_raw(s, np);
				if (np > 0)
					append_raw(s, e.physical);
				append_raw(s, uint64(0)); // no bounding entities
			}
			else
			{
				s += std::to_string(e.tag);
				for (double x : box)
				{
					s += ' ';
					append_double(s, x);
				}
				s += ' ' + std::to_string(np) + (np > 0 ? " " + std::to_string(e.physical) : "") + " 0\n";
			}
		}
	if (binary)
		s += '\n';
	s += "$EndEntities\n$Nodes\n";
	// the nodes: one block, in the first entity of the highest dimension
	const auto highest = std::max_element(entities.begin(), entities.end(),
										  [](const Entity& a, const Entity& b) { return a.dim < b.dim; });
	const Entity nodes_in = highest != entities.end() ? *highest : Entity{3, 1, 0};
	const int32 node_dim = nodes_in.dim, node_tag = nodes_in.tag;
	const uint64 nv = d.nb_vertices();
	if (binary)
	{
		for (uint64 v : {uint64(1), nv, uint64(1), nv})
			append_raw(s, v);
		append_raw(s, node_dim);
		append_raw(s, node_tag);
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
		s += "1 " + std::to_string(nv) + " 1 " + std::to_string(nv) + "\n" + std::to_string(node_dim) + " " +
			 std::to_string(node_tag) + " 0 " + std::to_string(nv) + "\n";
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
	// the elements, in blocks of one entity and one element type: the
	// listed edges (lines 1), the listed faces (triangles 2, quadrangles 3),
	// then the cells
	struct Element
	{
		uint32 entity;
		int32 type;
		const uint32* ids;
		uint32 size;
	};
	std::vector<Element> elements;
	elements.reserve(d.segments.size() + d.nb_faces() + d.nb_cells());
	for (std::size_t e = 0; e < d.segments.size(); ++e)
		elements.push_back({segment_entity[e], 1, segment_ids.data() + 2 * e, 2});
	std::size_t k = 0;
	for (uint32 f = 0; f < d.nb_faces(); ++f)
	{
		const uint32 n = d.face_sizes[f];
		if (n == 3 || n == 4) // gmsh has no polygon element
			elements.push_back({face_entity[f], n == 3 ? 2 : 3, d.face_vertices.data() + k, n});
		k += n;
	}
	k = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		const uint32 n = d.cell_sizes[c];
		const int32 type = n == 4 ? 4 : n == 8 ? 5 : n == 6 ? 6 : 7;
		elements.push_back({cell_entity[c], type, d.cell_vertices.data() + k, n});
		k += n;
	}
	std::stable_sort(elements.begin(), elements.end(), [&](const Element& a, const Element& b) {
		const Entity &ea = entities[a.entity], &eb = entities[b.entity];
		return std::tie(ea.dim, a.entity, a.type) < std::tie(eb.dim, b.entity, b.type);
	});
	uint64 blocks = 0;
	for (std::size_t i = 0; i < elements.size(); ++i)
		blocks += i == 0 || elements[i].entity != elements[i - 1].entity || elements[i].type != elements[i - 1].type;
	const uint64 ne = elements.size();
	if (binary)
		for (uint64 v : {blocks, ne, uint64(1), ne})
			append_raw(s, v);
	else
		s += std::to_string(blocks) + " " + std::to_string(ne) + " 1 " + std::to_string(ne) + "\n";
	uint64 tag = 1;
	for (std::size_t i = 0; i < elements.size();)
	{
		std::size_t j = i;
		while (j < elements.size() && elements[j].entity == elements[i].entity && elements[j].type == elements[i].type)
			++j;
		const Entity& e = entities[elements[i].entity];
		if (binary)
		{
			append_raw(s, e.dim);
			append_raw(s, e.tag);
			append_raw(s, elements[i].type);
			append_raw(s, uint64(j - i));
		}
		else
			s += std::to_string(e.dim) + " " + std::to_string(e.tag) + " " + std::to_string(elements[i].type) + " " +
				 std::to_string(j - i) + "\n";
		for (; i < j; ++i)
		{
			const Element& el = elements[i];
			if (binary)
			{
				append_raw(s, tag++);
				for (uint32 v = 0; v < el.size; ++v)
					append_raw(s, uint64(el.ids[v]) + 1);
			}
			else
			{
				append_uint(s, tag++);
				for (uint32 v = 0; v < el.size; ++v)
				{
					s += ' ';
					append_uint(s, uint64(el.ids[v]) + 1);
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
