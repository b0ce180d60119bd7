// SPDX-License-Identifier: MIT
// The .nmap text format of the maps of any dimension (docs/nmap_format.md).
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/properties/integrity.h>
#include <cgogn/io/nmap.h>

#include "file_io.h"
#include "text_writer.h"

#include <charconv>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <typeindex>

namespace cgogn::io
{

namespace
{

// The value types of the attributes the format holds, with their names.
template <typename T>
struct Scalar;
template <>
struct Scalar<double>
{
	static constexpr const char* name = "float64";
};
template <>
struct Scalar<float>
{
	static constexpr const char* name = "float32";
};
template <>
struct Scalar<int32>
{
	static constexpr const char* name = "int32";
};
template <>
struct Scalar<uint32>
{
	static constexpr const char* name = "uint32";
};
template <>
struct Scalar<int64>
{
	static constexpr const char* name = "int64";
};
template <>
struct Scalar<uint64>
{
	static constexpr const char* name = "uint64";
};

using ValueTypes = std::tuple<double, float, int32, uint32, int64, uint64, std::array<double, 1>, std::array<double, 2>,
							  std::array<double, 3>, std::array<double, 4>, std::array<double, 5>,
							  std::array<double, 6>, std::array<double, 7>, std::array<double, 8>>;

template <typename T>
std::string type_name()
{
	if constexpr (requires { Scalar<T>::name; })
		return Scalar<T>::name;
	else
		return "float64x" + std::to_string(std::tuple_size_v<T>);
}

template <typename T>
void append_value(std::string& s, const T& v)
{
	if constexpr (std::is_floating_point_v<T>)
		detail::append_double(s, double(v));
	else if constexpr (std::is_signed_v<T>)
	{
		if (v < 0)
			s.push_back('-');
		detail::append_uint(s, uint64(v < 0 ? -int64(v) : int64(v)));
	}
	else if constexpr (std::is_integral_v<T>)
		detail::append_uint(s, uint64(v));
	else
		for (std::size_t k = 0; k < v.size(); ++k)
		{
			if (k > 0)
				s.push_back(' ');
			detail::append_double(s, v[k]);
		}
}

// The lines of a text, numbered, without comments and blank lines.
class Lines
{
public:
	Lines(const std::string& path, const std::string& text) : path_(path), text_(text)
	{
	}
	// The tokens of the next line; throws at the end of the text.
	std::vector<std::string_view> next(const char* expected)
	{
		while (pos_ < text_.size())
		{
			const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
			std::string_view line(text_.data() + pos_, end - pos_);
			pos_ = end + 1;
			++number_;
			std::vector<std::string_view> tokens;
			std::size_t i = 0;
			while (i < line.size())
			{
				while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
					++i;
				std::size_t j = i;
				while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r')
					++j;
				if (j > i)
					tokens.push_back(line.substr(i, j - i));
				i = j;
			}
			if (tokens.empty() || tokens[0][0] == '#')
				continue;
			return tokens;
		}
		throw Error(path_, Error::Where::Line, number_,
					std::string("the file ends where ") + expected + " is expected");
	}
	[[noreturn]] void fail(const std::string& cause) const
	{
		fail_at(number_, cause);
	}
	[[noreturn]] void fail_at(uint64 line, const std::string& cause) const
	{
		throw Error(path_, Error::Where::Line, line, cause);
	}
	/// The number of the line read last.
	uint64 line() const
	{
		return number_;
	}
	template <typename T>
	T number(std::string_view token, const char* what) const
	{
		T v{};
		const auto r = std::from_chars(token.data(), token.data() + token.size(), v);
		if (r.ec != std::errc() || r.ptr != token.data() + token.size())
			fail(std::string(what) + ": '" + std::string(token) + "' is not a number of the expected type");
		if constexpr (std::is_floating_point_v<T>)
			if (!(v == v) || v - v != 0)
				fail(std::string(what) + " is not finite");
		return v;
	}
	// A line `keyword value`.
	std::string_view keyword(const char* key)
	{
		const auto t = next(key);
		if (t.size() != 2 || t[0] != key)
			fail(std::string("'") + key + " ...' expected");
		return t[1];
	}

private:
	const std::string& path_;
	const std::string& text_;
	std::size_t pos_ = 0;
	uint64 number_ = 0;
};

// The values of an attribute as the file gives them: each with its dart and
// its line (for the errors found once the cells are known). Depends on the
// value type only: the map and the cell dimension are handled apart.
template <typename T>
struct ParsedValues
{
	std::vector<uint32> darts;
	std::vector<T> values;
	std::vector<uint64> lines;
};

template <typename T>
ParsedValues<T> parse_values(Lines& lines, uint32 count, uint32 nb_darts)
{
	constexpr std::size_t nb = [] {
		if constexpr (requires { Scalar<T>::name; })
			return std::size_t(1);
		else
			return std::tuple_size_v<T>;
	}();
	ParsedValues<T> p;
	for (uint32 i = 0; i < count; ++i)
	{
		const auto t = lines.next("a value");
		if (t.size() != 1 + nb)
			lines.fail("a dart and " + std::to_string(nb) + " numbers expected");
		const uint32 d = lines.number<uint32>(t[0], "the dart");
		if (d >= nb_darts)
			lines.fail("dart " + std::to_string(d) + " out of range (" + std::to_string(nb_darts) + " darts)");
		T v{};
		if constexpr (requires { Scalar<T>::name; })
			v = lines.number<T>(t[1], "the value");
		else
			for (std::size_t k = 0; k < nb; ++k)
				v[k] = lines.number<double>(t[1 + k], "the value");
		p.darts.push_back(d);
		p.values.push_back(v);
		p.lines.push_back(lines.line());
	}
	return p;
}

// The container of the cells of dimension k (0 <= k <= MAX_DIMENSION).
const AttributeContainer& cells_of_dimension(const CMapBase& m, uint32 k)
{
	return *cgogn::detail::state_of(m).cells[orbit_index(cell_orbit(k))];
}

// A new attribute of type T on the cells of dimension k, of the class
// add_attribute<T, CellD<k>> makes; nullptr when the name is taken or
// reserved. The k-cells must be indexed.
template <typename T, std::size_t... K>
std::shared_ptr<AttributeArray<T>> new_cell_attribute(CMapBase& m, uint32 k, const std::string& name,
													  std::index_sequence<K...>)
{
	if (cgogn::detail::is_reserved_name(name))
		return nullptr;
	std::shared_ptr<AttributeArray<T>> attr;
	((k == K ? void(attr = container_of<cell_orbit(K)>(m).template add_attribute<T, CellAttribute<T, cell_orbit(K)>>(
						name, cgogn::detail::default_attribute_value<T>()))
			 : void()),
	 ...);
	return attr;
}

// Gives the values to the k-cells of their darts (checked: none is a
// boundary cell; the k-cells are indexed). Depends on the value type only,
// not on the map: the lines are read from the darts' cell indices.
template <typename T>
void read_attribute(CMapBase& m, Lines& lines, uint32 k, const std::string& name, const ParsedValues<T>& p)
{
	const std::shared_ptr<AttributeArray<T>> attr =
		new_cell_attribute<T>(m, k, name, std::make_index_sequence<MAX_DIMENSION + 1>{});
	if (!attr)
		lines.fail("attribute '" + name + "' is defined twice on the cells of dimension " + std::to_string(k) +
				   " (or its name is reserved)");
	const AttributeArray<uint32>& line_of = *cgogn::detail::state_of(m).cell_index[orbit_index(cell_orbit(k))];
	for (std::size_t i = 0; i < p.darts.size(); ++i)
		(*attr)[line_of[p.darts[i]]] = p.values[i];
}

// Writes attribute a of the k-cells when its values have type T.
template <typename T>
bool write_attribute_if(std::string& s, const AttributeBase& a, uint32 k, const AttributeContainer& cells,
						const std::vector<uint32>& number)
{
	const auto* typed = dynamic_cast<const AttributeArray<T>*>(&a);
	if (typed == nullptr)
		return false;
	s += "attribute " + std::to_string(k) + " " + a.name() + " " + type_name<T>() + " " +
		 std::to_string(cells.nb_lines()) + "\n";
	for (uint32 l = 0; l < cells.end_index(); ++l)
		if (cells.is_live(l))
		{
			detail::append_uint(s, number[cells.key()[l]]);
			s.push_back(' ');
			append_value(s, (*typed)[l]);
			s.push_back('\n');
		}
	return true;
}

template <typename... T>
bool write_attribute(std::string& s, const AttributeBase& a, uint32 k, const AttributeContainer& cells,
					 const std::vector<uint32>& number, std::tuple<T...>*)
{
	return (write_attribute_if<T>(s, a, k, cells, number) || ...);
}

// The attributes of the cells of each dimension k <= D (names of those not
// written in skipped).
void write_attributes(const CMapBase& m, uint32 D, std::string& s, const std::vector<uint32>& number,
					  std::vector<std::string>& skipped)
{
	for (uint32 k = 0; k <= D; ++k)
	{
		const AttributeContainer& cells = cells_of_dimension(m, k);
		for (const auto& a : cells.attributes())
			if (a.get() != &cells.key() && a->name().rfind("__", 0) != 0 &&
				!write_attribute(s, *a, k, cells, number, static_cast<ValueTypes*>(nullptr)))
				skipped.push_back(a->name());
	}
}

// Reads an attribute of the k-cells of a map of dimension D whose type is
// named `type` (false when no type has this name). The k-cells are indexed.
template <typename... T>
bool read_typed_attribute(CMapBase& m, uint32 D, Lines& lines, std::string_view type, uint32 k, const std::string& name,
						  uint32 count, uint32 nb_darts, std::tuple<T...>*)
{
	const auto read = [&]<typename V>(V*) {
		const ParsedValues<V> p = parse_values<V>(lines, count, nb_darts);
		// only the D-cells can be boundary cells
		for (std::size_t i = 0; i < p.darts.size(); ++i)
			if (k == D && is_boundary(m, Dart(p.darts[i])))
				lines.fail_at(p.lines[i],
							  "dart " + std::to_string(p.darts[i]) + " is in a boundary cell, which has no attribute");
		read_attribute<V>(m, lines, k, name, p);
		return true;
	};
	return ((type == type_name<T>() && read(static_cast<T*>(nullptr))) || ...);
}

// Indexes the k-cells of m (k <= D) if they are not.
template <typename MAP, std::size_t... K>
void index_dimension(MAP& m, uint32 k, std::index_sequence<K...>)
{
	((k == K && !is_indexed<CellD<uint32(K)>>(m) ? index_cells<CellD<uint32(K)>>(m) : void()), ...);
}

// The header lines: the version, the model and the dimension, with the
// numbers of the lines of the last two (for the errors of a load).
struct HeaderLines
{
	NMapHeader header;
	uint64 model_line = 0;
	uint64 dimension_line = 0;
};

HeaderLines read_header(Lines& lines)
{
	{
		const auto t = lines.next("the header");
		if (t.size() != 2 || t[0] != "cgogn_nmap" || t[1] != "1")
			lines.fail("not a .nmap file of version 1 (the first line must be 'cgogn_nmap 1')");
	}
	HeaderLines h;
	const std::string_view model = lines.keyword("model");
	h.model_line = lines.line();
	if (model != "cmap" && model != "gmap")
		lines.fail("unknown model '" + std::string(model) + "' (cmap or gmap)");
	h.header.gmap = model == "gmap";
	h.header.dimension = lines.number<uint32>(lines.keyword("dimension"), "the dimension");
	h.dimension_line = lines.line();
	if (h.header.dimension < 1 || h.header.dimension > MAX_DIMENSION)
		lines.fail("the dimension " + std::to_string(h.header.dimension) + " is out of 1 ... " +
				   std::to_string(MAX_DIMENSION));
	return h;
}

} // namespace

template <typename MAP>
requires is_nmap_v<MAP> std::vector<std::string> save_nmap(const MAP& m, const std::string& path)
{
	constexpr uint32 D = MAP::dimension;
	const AttributeContainer& darts = *cgogn::detail::state_of(m).darts;
	std::vector<uint32> number(darts.end_index(), INVALID_INDEX);
	uint32 n = 0;
	foreach_dart(m, [&](Dart d) { number[d.index] = n++; });
	std::string s = "cgogn_nmap 1\n";
	s += is_gmap_v<MAP> ? "model gmap\n" : "model cmap\n";
	s += "dimension " + std::to_string(D) + "\ndarts " + std::to_string(n) + "\n";
	foreach_dart(m, [&](Dart d) {
		for (uint32 i = 1; i <= D; ++i)
		{
			detail::append_uint(s, number[cgogn::detail::relation(m, i, d).index]);
			s.push_back(' ');
		}
		s += is_boundary(m, d) ? "1\n" : "0\n";
	});
	std::vector<std::string> skipped;
	write_attributes(m, D, s, number, skipped);
	s += "end\n";
	detail::write_file(path, s);
	return skipped;
}

NMapHeader read_nmap_header(const std::string& path)
{
	const std::string text = detail::read_file(path);
	Lines lines(path, text);
	return read_header(lines).header;
}

template <typename MAP>
requires is_nmap_v<MAP>
void load_nmap(MAP& m, const std::string& path)
{
	constexpr uint32 D = MAP::dimension;
	if (nb_darts(m) != 0)
		throw Error(path, "load_nmap: the map is not empty");
	const std::string text = detail::read_file(path);
	Lines lines(path, text);
	const HeaderLines h = read_header(lines);
	if (h.header.gmap != is_gmap_v<MAP>)
		lines.fail_at(h.model_line, std::string("the file holds a ") + (h.header.gmap ? "gmap" : "cmap") +
										", the map is a " + (is_gmap_v<MAP> ? "gmap" : "cmap"));
	if (h.header.dimension != D)
		lines.fail_at(h.dimension_line, "the file holds a map of dimension " + std::to_string(h.header.dimension) +
											", the map has dimension " + std::to_string(D));
	const uint32 n = lines.number<uint32>(lines.keyword("darts"), "the number of darts");
	if (is_gmap_v<MAP> && n % 2 != 0)
		lines.fail("a G-map has an even number of darts (beta0 pairs darts 2k and 2k + 1)");
	MAP local;
	for (uint32 i = 0; i < n; i += is_gmap_v<MAP> ? 2 : 1)
	{
		if constexpr (is_gmap_v<MAP>)
			cgogn::detail::add_dart_pair(local);
		else
			cgogn::detail::add_dart(local);
	}
	for (uint32 d = 0; d < n; ++d)
	{
		const auto t = lines.next("a dart");
		if (t.size() != D + 1)
			lines.fail("a dart line holds " + std::to_string(D) + " relations and a boundary mark");
		for (uint32 i = 1; i <= D; ++i)
		{
			const uint32 e = lines.number<uint32>(t[i - 1], "a relation");
			if (e >= n)
				lines.fail("relation " + std::to_string(i) + " points to dart " + std::to_string(e) +
						   ", out of range (" + std::to_string(n) + " darts)");
			cgogn::detail::set_relation(local, i, Dart(d), Dart(e));
		}
		const uint32 b = lines.number<uint32>(t[D], "the boundary mark");
		if (b > 1)
			lines.fail("the boundary mark is 0 or 1");
		cgogn::detail::set_boundary(local, Dart(d), b == 1);
	}
	if (const IntegrityReport r = check_integrity(local); !r.ok())
		throw Error(path, "the darts do not make a valid map: " + r.errors.front().message);
	for (;;)
	{
		const auto t = lines.next("an attribute or 'end'");
		if (t.size() == 1 && t[0] == "end")
			break;
		if (t.size() != 5 || t[0] != "attribute")
			lines.fail("'attribute <dimension> <name> <type> <count>' or 'end' expected");
		const uint32 k = lines.number<uint32>(t[1], "the cell dimension");
		if (k > D)
			lines.fail("no cell of dimension " + std::to_string(k) + " in a map of dimension " + std::to_string(D));
		const std::string name(t[2]);
		const uint32 count = lines.number<uint32>(t[4], "the number of values");
		index_dimension(local, k, std::make_index_sequence<D + 1>{});
		const bool known =
			read_typed_attribute(local, D, lines, t[3], k, name, count, n, static_cast<ValueTypes*>(nullptr));
		if (!known)
			lines.fail("unknown value type '" + std::string(t[3]) + "'");
	}
	m = std::move(local);
}

#define CGOGN_NMAP_IO(MAP)                                                                                             \
	template std::vector<std::string> save_nmap(const MAP&, const std::string&);                                       \
	template void load_nmap(MAP&, const std::string&);
CGOGN_NMAP_IO(CMapN<1>)
CGOGN_NMAP_IO(CMapN<2>)
CGOGN_NMAP_IO(CMapN<3>)
CGOGN_NMAP_IO(CMapN<4>)
CGOGN_NMAP_IO(CMapN<5>)
CGOGN_NMAP_IO(CMapN<6>)
CGOGN_NMAP_IO(CMapN<7>)
CGOGN_NMAP_IO(GMapN<1>)
CGOGN_NMAP_IO(GMapN<2>)
CGOGN_NMAP_IO(GMapN<3>)
CGOGN_NMAP_IO(GMapN<4>)
CGOGN_NMAP_IO(GMapN<5>)
CGOGN_NMAP_IO(GMapN<6>)
CGOGN_NMAP_IO(GMapN<7>)
#undef CGOGN_NMAP_IO

} // namespace cgogn::io
