// SPDX-License-Identifier: MIT
// The .cgmap binary format: whole maps, exactly (docs/map_file_format.md).
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/properties/integrity.h>
#include <cgogn/io/map_file.h>

#include "file_io.h"
#include "map_file_values.h"

#include <algorithm>
#include <fstream>
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
	std::vector<Orbit> orbits; // the orbits whose cells the type can index
};

MapKind map_kind(std::string_view type)
{
	using enum Orbit;
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

void write_map(detail::ByteSink& out, const CMapBase& m, const std::string& type, MapFileReport& report)
{
	const cgogn::detail::MapState& s = cgogn::detail::state_of(m);
	out.append(MAGIC);
	detail::put_scalar<uint32>(out, VERSION);
	detail::put_string(out, type);

	std::vector<uint32> cells; // the cell containers holding something
	for (uint32 o = 1; o < uint32(Orbit::NB_ORBITS); ++o)
		if (s.cells[o]->end_index() > 0 || s.cells[o]->attributes().size() > 1)
			cells.push_back(o);
	detail::put_scalar<uint32>(out, uint32(cells.size()) + 1);
	write_container(out, orbit_name(Orbit::DART), *s.darts, s.boundary, report);
	for (uint32 o : cells)
		write_container(out, orbit_name(Orbit(o)), *s.cells[o], nullptr, report);
	out.flush();
}

// ---------------------------------------------------------------- reading

class MapReader
{
public:
	MapReader(CMapBase& m, std::string_view bytes, const std::string& name)
		: m_(m), s_(cgogn::detail::state_of(m)), in_(bytes, 0, name, false)
	{
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

		const uint32 nb_containers = in_.read<uint32>();
		in_.check_count(nb_containers, 12, "containers");
		for (uint32 k = 0; k < nb_containers; ++k)
			read_container(k == 0);
		if (in_.remaining() > 0)
			in_.fail(std::to_string(in_.remaining()) + " bytes after the end of the map");
		check_references();
	}

private:
	void read_container(bool first)
	{
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
		detail::AttributeRead r{in_, c, o, name, existing_attribute(c, o, name), end};
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
	std::shared_ptr<AttributeBase> existing_attribute(AttributeContainer& c, Orbit o, const std::string& name)
	{
		std::shared_ptr<AttributeBase> a = c.find(name);
		if (a == nullptr && o == Orbit::DART && name.starts_with("__index_"))
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
			if (const AttributeArray<uint32>* idx = s_.cell_index[orbit_index(o)])
			{
				check(*idx, s_.cells[orbit_index(o)]->end_index(), "index");
				check(s_.cells[orbit_index(o)]->key(), nb_darts, "representative dart");
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
	MapKind kind_;
	std::set<Orbit> seen_orbits_;
};

template <typename MAP>
void read_map(MAP& m, std::string_view bytes, const std::string& name)
{
	MAP local;
	MapReader(local, bytes, name).read(map_type_name<MAP>());
	const IntegrityReport r = check_integrity(local);
	if (!r.ok())
		throw Error(name, "the file's map is not valid: " + r.errors.front().message);
	m = std::move(local);
}

} // namespace

std::vector<std::string> map_file_value_types()
{
	std::vector<std::string> names;
	detail::AttributeValues<detail::ScalarValueTypes>::names(names);
	detail::AttributeValues<detail::VectorValueTypes>::names(names);
	return names;
}

template <typename MAP>
requires MapFileType<MAP> std::string save_map_to_bytes(const MAP& m, MapFileReport* report)
{
	MapFileReport r;
	std::string bytes;
	detail::ByteSink out(bytes);
	write_map(out, m, map_type_name<MAP>(), r);
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
	write_map(out, m, map_type_name<MAP>(), r);
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
#undef CGOGN_MAP_FILE

} // namespace cgogn::io
