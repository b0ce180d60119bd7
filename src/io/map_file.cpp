// SPDX-License-Identifier: MIT
// The .cgmap binary format: whole maps, exactly (docs/map_file_format.md).
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/mrmap2_attributes.h>
#include <cgogn/core/map/mrmap3_attributes.h>
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/properties/integrity.h>
#include <cgogn/io/map_file.h>

#include "file_io.h"
#include "map_file_values.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>

namespace cgogn::io
{

namespace
{

constexpr std::string_view MAGIC = "CGOGNMAP";
constexpr uint32 VERSION = 1;

// ---------------------------------------------------------------- the map type

// What a map type is made of, as far as the file is concerned.
struct MapKind
{
	bool gmap = false;
	bool hierarchy = false;    // a multiresolution map: a hierarchy block, then its finest map's containers
	std::vector<Orbit> orbits; // the orbits whose cells the type can index
};

MapKind map_kind(std::string_view type)
{
	using enum Orbit;
	if (type == "MRMap2" || type == "MRMap3")
	{
		MapKind k = map_kind(type == "MRMap2" ? "CMap2" : "CMap3");
		k.hierarchy = true;
		return k;
	}
	MapKind k;
	k.gmap = type.starts_with("GMap");
	if (type == "CMap1")
		k.orbits = {PHI1};
	else if (type == "CMap2")
		k.orbits = {PHI1, PHI2, PHI21, PHI1_PHI2};
	else if (type == "CMap3")
		k.orbits = {PHI1, PHI2, PHI21, PHI1_PHI2, PHI1_PHI3, PHI2_PHI3, PHI21_PHI31, PHI1_PHI2_PHI3};
	else if (type == "GMap1")
		k.orbits = {BETA0, BETA1, BETA0_BETA1};
	else if (type == "GMap2")
		k.orbits = {BETA0, BETA1, BETA0_BETA1, BETA0_BETA2, BETA1_BETA2, BETA0_BETA1_BETA2};
	else if (type == "GMap3")
		k.orbits = {BETA0,
					BETA1,
					BETA0_BETA1,
					BETA0_BETA2,
					BETA1_BETA2,
					BETA0_BETA1_BETA2,
					BETA0_BETA1_BETA3,
					BETA0_BETA2_BETA3,
					BETA1_BETA2_BETA3,
					BETA0_BETA1_BETA2_BETA3};
	else if (type == "Graph")
		k.orbits = {ALPHA0, ALPHA1};
	else // CMapN<D>, GMapN<D>
	{
		const uint32 d = uint32(std::stoul(std::string(type.substr(6))));
		for (uint32 i = 0; i <= d; ++i)
			k.orbits.push_back(Orbit(orbit_index(CELL0) + i));
	}
	return k;
}

// The orbit named `name`, or NB_ORBITS.
Orbit orbit_named(std::string_view name)
{
	for (uint32 o = 0; o < uint32(Orbit::NB_ORBITS); ++o)
		if (orbit_name(Orbit(o)) == name)
			return Orbit(o);
	return Orbit::NB_ORBITS;
}

// ---------------------------------------------------------------- writing

void write_container(detail::ByteSink& out, std::string_view orbit, const AttributeContainer& c,
					 const MarkAttribute* marks, MapFileReport& report)
{
	detail::put_string(out, orbit);
	const uint32 end = c.end_index();
	detail::put_scalar<uint32>(out, end);
	detail::put_scalar<uint32>(out, uint32(c.free_lines().size()));
	for (uint32 i : c.free_lines())
		detail::put_scalar<uint32>(out, i);

	// each attribute is written when its type is one of the format's
	using Writer = void (*)(detail::ByteSink&, const AttributeBase&, uint32);
	std::vector<std::pair<const AttributeBase*, Writer>> written;
	for (const auto& a : c.attributes())
	{
		Writer w = detail::AttributeValues<detail::ScalarValueTypes>::writer(*a);
		if (w == nullptr)
			w = detail::AttributeValues<detail::VectorValueTypes>::writer(*a);
		if (w != nullptr)
			written.emplace_back(a.get(), w);
		else
			report.skipped.push_back({std::string(orbit), a->name(), "its value type has no encoding in the format"});
	}
	detail::put_scalar<uint32>(out, uint32(written.size()));
	for (const auto& [a, write] : written)
	{
		detail::put_string(out, a->name());
		write(out, *a, end);
	}
	report.nb_attributes_written += uint32(written.size());

	if (marks != nullptr)
	{
		std::string bits((end + 7) / 8, '\0');
		for (uint32 i = 0; i < end; ++i)
			if (marks->test(i))
				bits[i / 8] = char(uint8(bits[i / 8]) | uint8(1u << (i % 8)));
		out.append(bits);
	}
}

void write_header(detail::ByteSink& out, const std::string& type)
{
	out.append(MAGIC);
	detail::put_scalar<uint32>(out, VERSION);
	detail::put_string(out, type);
}

void write_containers(detail::ByteSink& out, const CMapBase& m, MapFileReport& report)
{
	const cgogn::detail::MapState& s = cgogn::detail::state_of(m);
	std::vector<uint32> cells; // the cell containers holding something
	for (uint32 o = 1; o < uint32(Orbit::NB_ORBITS); ++o)
		if (s.cells[o]->end_index() > 0 || s.cells[o]->attributes().size() > 1)
			cells.push_back(o);
	detail::put_scalar<uint32>(out, uint32(cells.size()) + 1);
	write_container(out, orbit_name(Orbit::DART), *s.darts, s.boundary, report);
	for (uint32 o : cells)
		write_container(out, orbit_name(Orbit(o)), *s.cells[o], nullptr, report);
}

// The block that follows the header of a multiresolution map's file: its
// number of levels, the darts made at each level, its current level.
struct HierarchyBlock
{
	std::vector<uint32> darts_per_level;
	uint32 current_level = 0;
	std::size_t offset = 0; // where the block starts in the file
};

void write_hierarchy_block(detail::ByteSink& out, const std::vector<uint32>& darts_per_level, uint32 current_level)
{
	detail::put_scalar<uint32>(out, uint32(darts_per_level.size()));
	for (uint32 n : darts_per_level)
		detail::put_scalar<uint32>(out, n);
	detail::put_scalar<uint32>(out, current_level);
}

template <typename MAP>
void write_map(detail::ByteSink& out, const MAP& m, MapFileReport& report)
{
	write_header(out, map_type_name<MAP>());
	if constexpr (MultiresolutionMapFileType<MAP>)
	{
		// the finest map holds the rest: labels, indices and per-level lines
		// are attributes of its containers
		const auto& s = cgogn::detail::mr_state_of(m);
		write_hierarchy_block(out, s.darts_per_level, s.current_level);
		write_containers(out, s.map, report);
	}
	else
		write_containers(out, m, report);
	out.flush();
}

// ---------------------------------------------------------------- reading

// What a multiresolution map keeps besides what its finest map holds, as the
// reader sees it: attributes of reserved names in the finest map's
// containers (labels, indices, per-level lines), which it creates when the
// file lists them. One implementation per multiresolution type; the
// hierarchy block and the finest map's containers are read by MapReader.
class HierarchyReader
{
public:
	virtual ~HierarchyReader() = default;
	// The hierarchy's attribute that receives the file's attribute `name` of
	// container c (of orbit o), whose payload starts at byte `offset`:
	// created; nullptr when the name is not one of the hierarchy's.
	virtual std::shared_ptr<AttributeBase> attribute(const detail::ByteReader& in, AttributeContainer& c, Orbit o,
													 const std::string& name, std::size_t offset) = 0;
	// The index attribute of orbit o (nullptr: not indexed).
	virtual const AttributeArray<uint32>* cell_index(Orbit o) const = 0;
	// The attributes of the container of orbit o whose values are lines of
	// that container (INVALID_INDEX: none).
	virtual std::vector<const AttributeArray<uint32>*> line_links(Orbit o) const = 0;
};

class MapReader
{
public:
	MapReader(CMapBase& m, std::string_view bytes, const std::string& name, HierarchyReader* hierarchy = nullptr)
		: m_(m), s_(cgogn::detail::state_of(m)), in_(bytes, 0, name, false), hierarchy_(hierarchy)
	{
	}

	// The hierarchy block of a multiresolution map's file (once read).
	const HierarchyBlock& hierarchy_block() const
	{
		return block_;
	}
	// Where the container of orbit o starts in the file (0: none).
	std::size_t container_offset(Orbit o) const
	{
		const auto it = container_offsets_.find(o);
		return it == container_offsets_.end() ? 0 : it->second;
	}

	// Reads the header; returns the map type it names.
	static MapFileHeader read_header(detail::ByteReader& in)
	{
		if (in.remaining() < MAGIC.size())
			in.fail("not a .cgmap file (too short for its header)");
		std::string magic;
		for (std::size_t i = 0; i < MAGIC.size(); ++i)
			magic.push_back(in.read<char>());
		if (magic != MAGIC)
			in.fail("not a .cgmap file (its first bytes are not CGOGNMAP)");
		MapFileHeader h;
		h.version = in.read<uint32>();
		if (h.version == 0 || h.version > VERSION)
			in.fail("format version " + std::to_string(h.version) + " (this library reads version " +
					std::to_string(VERSION) + ")");
		h.map_type = detail::get_string(in);
		return h;
	}

	void read(const std::string& expected_type)
	{
		const MapFileHeader h = read_header(in_);
		if (h.map_type != expected_type)
			in_.fail("the file holds a " + h.map_type + ", not a " + expected_type);
		kind_ = map_kind(expected_type);
		if (kind_.hierarchy != (hierarchy_ != nullptr))
			in_.fail("a " + expected_type + " is read by " +
					 (kind_.hierarchy ? "the reader of its hierarchy" : "the reader of flat maps"));
		if (kind_.hierarchy)
			read_hierarchy_block();

		const uint32 nb_containers = in_.read<uint32>();
		in_.check_count(nb_containers, 12, "containers");
		for (uint32 k = 0; k < nb_containers; ++k)
			read_container(k == 0);
		if (in_.remaining() > 0)
			in_.fail(std::to_string(in_.remaining()) + " bytes after the end of the map");
		check_references();
	}

private:
	void read_hierarchy_block()
	{
		block_.offset = in_.position();
		const uint32 nb_levels = in_.read<uint32>();
		if (nb_levels == 0 || nb_levels > 255)
			in_.fail(std::to_string(nb_levels) + " levels (a multiresolution map has 1 to 255)");
		in_.check_count(nb_levels, 4, "level dart counts");
		block_.darts_per_level.resize(nb_levels);
		for (uint32& n : block_.darts_per_level)
			n = in_.read<uint32>();
		block_.current_level = in_.read<uint32>();
		if (block_.current_level >= nb_levels)
			in_.fail("current level " + std::to_string(block_.current_level) + " above the finest level " +
					 std::to_string(nb_levels - 1));
	}

	void read_container(bool first)
	{
		const std::size_t offset = in_.position();
		const std::string orbit_text = detail::get_string(in_);
		const Orbit o = orbit_named(orbit_text);
		if (first != (o == Orbit::DART))
			in_.fail(first ? "the first container is '" + orbit_text + "', not the darts (DART)"
						   : "a second dart container");
		if (o != Orbit::DART && std::find(kind_.orbits.begin(), kind_.orbits.end(), o) == kind_.orbits.end())
			in_.fail("container of orbit '" + orbit_text + "', which a " + map_kind_name() + " does not have");
		AttributeContainer& c = o == Orbit::DART ? *s_.darts : *s_.cells[orbit_index(o)];
		if (o != Orbit::DART && !seen_orbits_.insert(o).second)
			in_.fail("a second container of orbit " + orbit_text);
		container_offsets_[o] = offset;

		const uint32 end = in_.read<uint32>();
		in_.check_count(end, 4, "lines"); // each has at least its key
		const uint32 nb_free = in_.read<uint32>();
		in_.check_count(nb_free, 4, "free lines");
		if (nb_free > end)
			in_.fail(std::to_string(nb_free) + " free lines in a container of " + std::to_string(end));
		std::vector<uint32> free_lines(nb_free);
		std::vector<bool> is_free(end, false);
		for (uint32& f : free_lines)
		{
			f = in_.read<uint32>();
			if (f >= end || is_free[f])
				in_.fail(f >= end ? "free line " + std::to_string(f) + " out of the " + std::to_string(end) + " lines"
								  : "free line " + std::to_string(f) + " listed twice");
			is_free[f] = true;
		}
		c.restore_lines(end, std::move(free_lines));

		const uint32 nb_attributes = in_.read<uint32>();
		in_.check_count(nb_attributes, 16, "attributes");
		std::set<std::string> names;
		for (uint32 k = 0; k < nb_attributes; ++k)
			read_attribute(c, o, end, names);

		for (uint32 i = 0; i < end; ++i)
			if ((c.key()[i] == INVALID_INDEX) != is_free[i])
				in_.fail("container " + orbit_text + ": line " + std::to_string(i) +
						 (is_free[i] ? " is listed free but has a key" : " has no key but is not listed free"));
		if (o == Orbit::DART)
		{
			if (kind_.gmap)
			{
				if (end % 2 != 0)
					in_.fail("a G-map of an odd number of dart lines (" + std::to_string(end) + ")");
				for (uint32 i = 0; i < end; i += 2)
					if (is_free[i] != is_free[i + 1])
						in_.fail("dart " + std::to_string(is_free[i] ? i + 1 : i) +
								 " is live but its beta0 partner is free");
			}
			read_boundary(end, is_free);
		}
	}

	void read_attribute(AttributeContainer& c, Orbit o, uint32 end, std::set<std::string>& names)
	{
		const std::string name = detail::get_string(in_);
		const std::string type = detail::get_string(in_);
		const uint64 payload = in_.read<uint64>();
		in_.check_count(payload, 1, "payload bytes");
		const std::size_t start = in_.position();
		if (!names.insert(name).second)
			in_.fail("attribute '" + name + "' listed twice in container " + std::string(orbit_name(o)));
		detail::AttributeRead r{in_, c, o, name, existing_attribute(c, o, name, start), end};
		const bool known = detail::AttributeValues<detail::ScalarValueTypes>::read(r, type) ||
						   detail::AttributeValues<detail::VectorValueTypes>::read(r, type);
		if (!known)
			in_.fail("attribute '" + name + "' of unknown value type '" + type + "'");
		if (in_.position() - start != payload)
			in_.fail("attribute '" + name + "' declares " + std::to_string(payload) + " bytes of values but holds " +
					 std::to_string(in_.position() - start));
	}

	// The map's own attribute that receives the file's attribute `name`
	// (its relations, the keys, an orbit's index); nullptr for an attribute
	// of the program's, which the typed reader creates.
	std::shared_ptr<AttributeBase> existing_attribute(AttributeContainer& c, Orbit o, const std::string& name,
													  std::size_t offset)
	{
		std::shared_ptr<AttributeBase> a = c.find(name);
		// a multiresolution map indexes its orbits itself: its finest map has no index
		if (a == nullptr && hierarchy_ != nullptr)
			a = hierarchy_->attribute(in_, c, o, name, offset);
		if (a == nullptr && hierarchy_ == nullptr && o == Orbit::DART && name.starts_with("__index_"))
		{
			const Orbit indexed = orbit_named(std::string_view(name).substr(8));
			if (std::find(kind_.orbits.begin(), kind_.orbits.end(), indexed) == kind_.orbits.end())
				in_.fail("index attribute '" + name + "' of an orbit a " + map_kind_name() + " does not have");
			a = c.find(cgogn::detail::index_attribute(m_, indexed).name());
		}
		else if (a == nullptr && cgogn::detail::is_reserved_name(name))
			in_.fail("attribute '" + name + "': a reserved name that a " + map_kind_name() + " does not use");
		return a;
	}

	void read_boundary(uint32 end, const std::vector<bool>& is_free)
	{
		const uint32 nb_bytes = (end + 7) / 8;
		in_.check_count(nb_bytes, 1, "bytes of boundary marks");
		uint32 nb_marked = 0;
		for (uint32 b = 0; b < nb_bytes; ++b)
		{
			const uint8 bits = in_.read<uint8>();
			for (uint32 j = 0; j < 8; ++j)
				if ((bits >> j) & 1u)
				{
					const uint32 i = 8 * b + j;
					if (i >= end || is_free[i])
						in_.fail("boundary mark on dart " + std::to_string(i) + ", which is not live");
					s_.boundary->set(i);
					++nb_marked;
				}
		}
		s_.nb_boundary_darts = nb_marked;
	}

	// Every relation, index and key designates a line of its container (or
	// nothing), so that check_integrity may follow them.
	void check_references()
	{
		const uint32 nb_darts = s_.darts->end_index();
		auto check = [&](const AttributeArray<uint32>& a, uint32 end, const std::string& what) {
			// run by run through pointers: this walks every relation and index
			const uint32 n = a.container()->end_index();
			for (uint32 i = 0; i < n;)
			{
				const uint32 run = std::min(a.run_end(i), n);
				const uint32* values = &a[i];
				for (uint32 k = 0; k < run - i; ++k)
					if (values[k] != INVALID_INDEX && values[k] >= end)
						in_.fail(what + " " + a.name() + " of line " + std::to_string(i + k) + " is " +
								 std::to_string(values[k]) + ", out of the " + std::to_string(end) +
								 " lines it refers to");
				i = run;
			}
		};
		for (const AttributeArray<uint32>* r : s_.relations)
			check(*r, nb_darts, "relation");
		for (Orbit o : kind_.orbits)
			if (const AttributeArray<uint32>* idx =
					hierarchy_ != nullptr ? hierarchy_->cell_index(o) : s_.cell_index[orbit_index(o)])
			{
				const uint32 end = s_.cells[orbit_index(o)]->end_index();
				check(*idx, end, "index");
				check(s_.cells[orbit_index(o)]->key(), nb_darts, "representative dart");
				if (hierarchy_ != nullptr)
					for (const AttributeArray<uint32>* link : hierarchy_->line_links(o))
						check(*link, end, "line link");
			}
			else if (s_.cells[orbit_index(o)]->end_index() > 0 || s_.cells[orbit_index(o)]->attributes().size() > 1)
				in_.fail("orbit " + std::string(orbit_name(o)) +
						 " has cell lines or attributes but no index attribute");
	}

	std::string map_kind_name() const
	{
		return std::string(kind_.gmap ? "G-map" : "map") + " of this type";
	}

	CMapBase& m_;
	cgogn::detail::MapState& s_;
	detail::ByteReader in_;
	HierarchyReader* hierarchy_;
	MapKind kind_;
	HierarchyBlock block_;
	std::set<Orbit> seen_orbits_;
	std::map<Orbit, std::size_t> container_offsets_;
};

// The hierarchy of a multiresolution map (detail::MRState2 or MRState3):
// its darts' labels (__mr_level, __mr_edge_id, and __mr_face_id in 3-D),
// the index of each indexed orbit
// (__mr_index_<orbit>, or __index_<orbit> for an orbit the map indexed
// before it became level 0) and the lines' links, levels and replacing
// levels (__mr_down, __mr_level, __mr_replaced in the orbit's container).
template <typename S>
class MRHierarchyReader final : public HierarchyReader
{
public:
	using D = cgogn::detail::MRDim<S>;
	static constexpr bool has_face_id = std::same_as<S, cgogn::detail::MRState3>;

	explicit MRHierarchyReader(S& s) : s_(s)
	{
	}

	std::shared_ptr<AttributeBase> attribute(const detail::ByteReader& in, AttributeContainer& c, Orbit o,
											 const std::string& name, std::size_t offset) override
	{
		if (o == Orbit::DART)
		{
			if (std::shared_ptr<AttributeArray<uint8>>* label = label_of(name))
			{
				*label = c.add_attribute<uint8>(name, 0);
				label_offset_[name] = offset + 1; // after the default value
				return *label;
			}
			for (uint32 slot = 0; slot < D::orbits.size(); ++slot)
			{
				const std::string orbit(orbit_name(D::orbits[slot]));
				if (name != "__mr_index_" + orbit && name != "__index_" + orbit)
					continue;
				if (s_.cells[slot].index != nullptr)
					in.fail("attribute '" + name + "': a second index of orbit " + orbit);
				auto a = c.add_attribute<uint32>(name, INVALID_INDEX);
				s_.cells[slot].index = a.get();
				cgogn::detail::state_of(s_.map).cells[orbit_index(D::orbits[slot])]->set_cell_index(a.get());
				return a;
			}
			return nullptr;
		}
		if (!has_slot(o))
			return nullptr;
		cgogn::detail::MRCellIndex& ci = s_.cells[D::slot(o)];
		if (name == "__mr_down")
			return ci.down = c.add_attribute<uint32>(name, INVALID_INDEX);
		if (name == "__mr_level")
			return ci.level = c.add_attribute<uint8>(name, 0);
		if (name == "__mr_replaced")
			return ci.replaced = c.add_attribute<uint8>(name, cgogn::detail::MR_NOT_REPLACED);
		return nullptr;
	}

	const AttributeArray<uint32>* cell_index(Orbit o) const override
	{
		return has_slot(o) ? s_.cells[D::slot(o)].index : nullptr;
	}

	std::vector<const AttributeArray<uint32>*> line_links(Orbit o) const override
	{
		if (!has_slot(o) || s_.cells[D::slot(o)].down == nullptr)
			return {};
		return {s_.cells[D::slot(o)].down.get()};
	}

	// Completes the hierarchy read by r (the file `name`), the state of m,
	// and checks m at every level; throws io::Error at the offset of what is
	// wrong.
	void finish(const MapReader& r, const std::string& name, const typename D::Map& m)
	{
		const HierarchyBlock& b = r.hierarchy_block();
		const auto fail = [&](std::size_t offset, const std::string& cause) {
			throw Error(name, Error::Where::Byte, offset, cause);
		};
		for (const char* label : label_names())
			if (*label_of(label) == nullptr)
				fail(r.container_offset(Orbit::DART),
					 std::string("the darts have no ") + label + " label: not the finest map of a hierarchy");
		for (uint32 slot = 0; slot < D::orbits.size(); ++slot)
		{
			const cgogn::detail::MRCellIndex& ci = s_.cells[slot];
			const bool lines = ci.down != nullptr && ci.level != nullptr && ci.replaced != nullptr;
			const Orbit o = D::orbits[slot];
			if ((ci.index != nullptr) != lines)
				fail(r.container_offset(ci.index != nullptr ? o : Orbit::DART),
					 "orbit " + std::string(orbit_name(o)) +
						 (ci.index != nullptr ? " is indexed but its lines lack __mr_down, __mr_level or __mr_replaced"
											  : " has per-level lines but no index"));
		}
		// the counters against the labels, at the offset of the one that is wrong
		const uint32 nb_levels = uint32(b.darts_per_level.size());
		std::vector<uint32> count(nb_levels, 0);
		foreach_dart(s_.map, [&](Dart d) {
			const uint32 l = (*s_.level)[d.index];
			if (l >= nb_levels)
				fail(label_offset_["__mr_level"] + d.index, "dart " + std::to_string(d.index) + " has level " +
																std::to_string(l) + ", above the finest level " +
																std::to_string(nb_levels - 1));
			++count[l];
		});
		for (uint32 l = 0; l < nb_levels; ++l)
			if (count[l] != b.darts_per_level[l])
				fail(b.offset + 4 + 4 * std::size_t(l),
					 "level " + std::to_string(l) + " counts " + std::to_string(b.darts_per_level[l]) +
						 " darts, but the darts' labels give " + std::to_string(count[l]));
		s_.darts_per_level = b.darts_per_level;
		s_.current_level = b.current_level;
		// every level: relations, labels and lines
		const IntegrityReport report = check_integrity(m);
		if (!report.ok())
		{
			const IntegrityError& e = report.errors.front();
			const std::size_t labels = label_offset_[e.kind == IntegrityError::Kind::EdgeIdWrong   ? "__mr_edge_id"
													 : e.kind == IntegrityError::Kind::FaceIdWrong ? "__mr_face_id"
																								   : "__mr_level"];
			fail(e.dart != INVALID_INDEX ? labels + e.dart : b.offset,
				 "the file's hierarchy is not valid: " + e.message);
		}
	}

private:
	static bool has_slot(Orbit o)
	{
		return D::slot(o) < D::orbits.size();
	}
	static std::vector<const char*> label_names()
	{
		if constexpr (has_face_id)
			return {"__mr_level", "__mr_edge_id", "__mr_face_id"};
		else
			return {"__mr_level", "__mr_edge_id"};
	}
	// The state's label of that name, nullptr for another name.
	std::shared_ptr<AttributeArray<uint8>>* label_of(const std::string& name)
	{
		if (name == "__mr_level")
			return &s_.level;
		if (name == "__mr_edge_id")
			return &s_.edge_id;
		if constexpr (has_face_id)
			if (name == "__mr_face_id")
				return &s_.face_id;
		return nullptr;
	}

	S& s_;
	std::map<std::string, std::size_t> label_offset_; // where the darts' labels start in the file
};

template <typename MAP>
void read_map(MAP& m, std::string_view bytes, const std::string& name)
{
	if constexpr (MultiresolutionMapFileType<MAP>)
	{
		using S = std::remove_reference_t<decltype(cgogn::detail::mr_state_of(std::declval<MAP&>()))>;
		MAP local{decltype(S::map)()};
		S& s = cgogn::detail::mr_state_of(local);
		s = S{}; // the file gives the labels, indices and lines
		MRHierarchyReader<S> hierarchy(s);
		MapReader r(s.map, bytes, name, &hierarchy);
		r.read(map_type_name<MAP>());
		hierarchy.finish(r, name, local);
		m = std::move(local);
	}
	else
	{
		MAP local;
		MapReader(local, bytes, name).read(map_type_name<MAP>());
		const IntegrityReport r = check_integrity(local);
		if (!r.ok())
			throw Error(name, "the file's map is not valid: " + r.errors.front().message);
		m = std::move(local);
	}
}

} // namespace

std::vector<std::string> map_file_value_types()
{
	std::vector<std::string> names;
	detail::AttributeValues<detail::ScalarValueTypes>::names(names);
	detail::AttributeValues<detail::VectorValueTypes>::names(names);
	return names;
}

std::string map_file_value_type(const AttributeBase& a)
{
	std::string name = detail::AttributeValues<detail::ScalarValueTypes>::name_of(a);
	return name.empty() ? detail::AttributeValues<detail::VectorValueTypes>::name_of(a) : name;
}

template <typename MAP>
requires MapFileType<MAP> std::string save_map_to_bytes(const MAP& m, MapFileReport* report)
{
	MapFileReport r;
	std::string bytes;
	detail::ByteSink out(bytes);
	write_map(out, m, r);
	if (report != nullptr)
		*report = std::move(r);
	return bytes;
}

template <typename MAP>
requires MapFileType<MAP> MapFileReport save_map(const MAP& m, const std::string& path)
{
	MapFileReport r;
	detail::OutputFile file(path);
	detail::ByteSink out(file);
	write_map(out, m, r);
	file.close();
	return r;
}

template <typename MAP>
requires MapFileType<MAP>
void load_map(MAP& m, const std::string& path)
{
	const detail::InputFile file(path);
	read_map(m, file.bytes(), path);
}

template <typename MAP>
requires MapFileType<MAP>
void load_map_from_bytes(MAP& m, std::string_view bytes, const std::string& name)
{
	read_map(m, bytes, name);
}

MapFileHeader read_map_header_from_bytes(std::string_view bytes, const std::string& name)
{
	detail::ByteReader in(bytes, 0, name, false);
	return MapReader::read_header(in);
}

MapFileHeader read_map_header(const std::string& path)
{
	std::ifstream f(path, std::ios::binary);
	if (!f)
		throw Error(path, "cannot open the file");
	std::string head(4096, '\0'); // the magic, the version and a type name
	f.read(head.data(), std::streamsize(head.size()));
	head.resize(std::size_t(f.gcount()));
	return read_map_header_from_bytes(head, path);
}

#define CGOGN_MAP_FILE(MAP)                                                                                            \
	template MapFileReport save_map(const MAP&, const std::string&);                                                   \
	template std::string save_map_to_bytes(const MAP&, MapFileReport*);                                                \
	template void load_map(MAP&, const std::string&);                                                                  \
	template void load_map_from_bytes(MAP&, std::string_view, const std::string&);
CGOGN_MAP_FILE(CMap1)
CGOGN_MAP_FILE(CMap2)
CGOGN_MAP_FILE(CMap3)
CGOGN_MAP_FILE(GMap1)
CGOGN_MAP_FILE(GMap2)
CGOGN_MAP_FILE(GMap3)
CGOGN_MAP_FILE(Graph)
CGOGN_MAP_FILE(CMapN<1>)
CGOGN_MAP_FILE(CMapN<2>)
CGOGN_MAP_FILE(CMapN<3>)
CGOGN_MAP_FILE(CMapN<4>)
CGOGN_MAP_FILE(CMapN<5>)
CGOGN_MAP_FILE(CMapN<6>)
CGOGN_MAP_FILE(CMapN<7>)
CGOGN_MAP_FILE(GMapN<1>)
CGOGN_MAP_FILE(GMapN<2>)
CGOGN_MAP_FILE(GMapN<3>)
CGOGN_MAP_FILE(GMapN<4>)
CGOGN_MAP_FILE(GMapN<5>)
CGOGN_MAP_FILE(GMapN<6>)
CGOGN_MAP_FILE(GMapN<7>)
CGOGN_MAP_FILE(MRMap2)
CGOGN_MAP_FILE(MRMap3)
#undef CGOGN_MAP_FILE

} // namespace cgogn::io
