// SPDX-License-Identifier: MIT
// VTK XML unstructured grids (.vtu): DataArrays in ascii, inline binary
// (base64) or appended data (raw or base64), UInt32 or UInt64 headers, little
// or big endian, zlib-compressed blocks when zlib is available. One Piece.
#include "byte_reader.h"
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"
#include "value_type_names.h"
#include "vtk_cells.h"

#include <map>

#ifdef CGOGN_IO_HAS_ZLIB
#include <zlib.h>
#endif

namespace cgogn::io::detail
{

namespace
{

struct Tag
{
	std::string name; // "DataArray", "/Points", ...
	std::map<std::string, std::string> attrs;
	bool self_closing = false;
	std::size_t begin = 0; // offset of '<'
	std::size_t end = 0;   // offset after '>'
};

// Decodes base64, restarting after padding (VTK encodes header and data as
// separate base64 chunks). Whitespace is skipped. Returns false on bad input.
bool base64_decode(std::string_view in, std::string& out, std::size_t max_out)
{
	auto val = [](char c) -> int {
		if (c >= 'A' && c <= 'Z')
			return c - 'A';
		if (c >= 'a' && c <= 'z')
			return c - 'a' + 26;
		if (c >= '0' && c <= '9')
			return c - '0' + 52;
		if (c == '+')
			return 62;
		if (c == '/')
			return 63;
		return -1;
	};
	uint32 acc = 0;
	int bits = 0;
	for (char c : in)
	{
		if (out.size() >= max_out)
			return true;
		if (c == ' ' || c == '\n' || c == '\r' || c == '\t')
			continue;
		if (c == '=')
		{
			acc = 0;
			bits = 0;
			continue;
		}
		const int v = val(c);
		if (v < 0)
			return false;
		acc = (acc << 6) | uint32(v);
		bits += 6;
		if (bits >= 8)
		{
			bits -= 8;
			out.push_back(char((acc >> bits) & 0xffu));
		}
	}
	return true;
}

class VtuReader
{
public:
	VtuReader(std::string_view data, const std::string& path) : data_(data), path_(path)
	{
	}

	MeshData read()
	{
		std::vector<Tag> tags;
		std::size_t p = 0;
		// the appended section is opaque: stop scanning tags at its '_'
		while ((p = data_.find('<', p)) != std::string_view::npos)
		{
			Tag t = parse_tag(p);
			p = t.end;
			if (t.name == "AppendedData")
			{
				encoding_ = t.attrs["encoding"];
				const std::size_t u = data_.find('_', p);
				if (u == std::string_view::npos)
					fail_at(p, "AppendedData without the '_' marker");
				appended_ = u + 1;
				break;
			}
			tags.push_back(std::move(t));
		}
		std::string section;
		MeshData d;
		std::vector<int64> connectivity, offsets, types, faces, face_offsets;
		std::vector<Column> cell_data;
		std::vector<std::string> point_data_names, cell_data_names;
		bool have_points = false, have_piece = false;
		for (std::size_t i = 0; i < tags.size(); ++i)
		{
			Tag& t = tags[i];
			if (t.name == "VTKFile")
			{
				if (t.attrs["type"] != "UnstructuredGrid")
					fail_at(t.begin, "only UnstructuredGrid VTK XML files are read");
				big_endian_ = t.attrs["byte_order"] == "BigEndian";
				header64_ = t.attrs["header_type"] == "UInt64";
				compressed_ = !t.attrs["compressor"].empty();
				if (compressed_ && t.attrs["compressor"] != "vtkZLibDataCompressor")
					fail_at(t.begin, "unsupported compressor " + t.attrs["compressor"]);
			}
			else if (t.name == "Piece")
			{
				if (have_piece)
					fail_at(t.begin, "only one Piece is read");
				have_piece = true;
				nb_points_ = to_uint(t, "NumberOfPoints");
				nb_cells_ = to_uint(t, "NumberOfCells");
			}
			else if (t.name == "Points" || t.name == "Cells" || t.name == "PointData" || t.name == "CellData")
				section = t.self_closing ? "" : t.name;
			else if (t.name.size() > 1 && t.name[0] == '/' &&
					 (t.name == "/Points" || t.name == "/Cells" || t.name == "/PointData" || t.name == "/CellData"))
				section.clear();
			else if (t.name == "DataArray")
			{
				const std::size_t content_end =
					t.self_closing ? t.end : (i + 1 < tags.size() ? tags[i + 1].begin : data_.size());
				const uint32 dim = t.attrs.count("NumberOfComponents") ? to_uint(t, "NumberOfComponents") : 1;
				const std::string name = t.attrs["Name"];
				if (section == "Points")
				{
					if (dim != 3)
						fail_at(t.begin, "points must have 3 components");
					d.positions = values(t, content_end, uint64(nb_points_) * 3, true);
					have_points = true;
				}
				else if (section == "Cells")
				{
					if (name == "connectivity")
					{
						connectivity = integers(t, content_end, 0);
						cells_byte_ = t.begin;
					}
					else if (name == "offsets")
						offsets = integers(t, content_end, nb_cells_);
					else if (name == "types")
						types = integers(t, content_end, nb_cells_);
					else if (name == "faces") // polyhedra: their face streams
						faces = integers(t, content_end, 0);
					else if (name == "faceoffsets")
						face_offsets = integers(t, content_end, nb_cells_);
				}
				else if (section == "PointData" || section == "CellData")
				{
					// every named array counts for conflicts, the ones of other sizes too
					const bool of_points = section == "PointData";
					std::vector<std::string>& names = of_points ? point_data_names : cell_data_names;
					if (std::string why = data_name_conflict(names, name, of_points); !why.empty())
						fail_at(t.begin, why);
					names.push_back(name);
					// every array is kept: the load reports those no attribute holds
					const uint64 count = of_points ? nb_points_ : nb_cells_;
					Column c{name, dim, values(t, content_end, count * dim, false),
							 vtu_value_type(t.attrs["type"]).value_or(ValueType::Float64)};
					(of_points ? d.vertex_columns : cell_data).push_back(std::move(c));
				}
			}
		}
		if (!have_piece || !have_points)
			fail_at(data_.size(), "no Piece with Points");
		offsets.insert(offsets.begin(), 0);
		if (face_offsets.empty() && std::find(types.begin(), types.end(), 42) != types.end())
			fail_at(cells_byte_, "polyhedron cells (type 42) without the 'faces' and 'faceoffsets' arrays that "
								 "give their faces");
		vtk_cells_to_mesh(
			d, offsets, connectivity, types, cell_data, [&](const std::string& m) { fail_at(cells_byte_, m); }, faces,
			face_offsets);
		return d;
	}

private:
	[[noreturn]] void fail_at(std::size_t byte, const std::string& cause) const
	{
		throw Error(path_, Error::Where::Byte, byte, cause);
	}

	uint32 to_uint(Tag& t, const char* key)
	{
		const std::string& v = t.attrs[key];
		uint32 x = 0;
		auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
		if (ec != std::errc() || ptr != v.data() + v.size() || x == INVALID_INDEX)
			fail_at(t.begin, std::string("bad ") + key + " '" + TextReader::printable(v) + "'");
		return x;
	}

	Tag parse_tag(std::size_t p)
	{
		Tag t;
		t.begin = p;
		std::size_t q = p + 1;
		if (data_.substr(q, 3) == "!--")
		{
			const std::size_t e = data_.find("-->", q);
			t.end = e == std::string_view::npos ? data_.size() : e + 3;
			t.name = "!--";
			return t;
		}
		auto is_space = [](char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; };
		while (q < data_.size() && !is_space(data_[q]) && data_[q] != '>' && data_[q] != '/')
			++q;
		if (q < data_.size() && data_[q] == '/' && q == p + 1)
		{
			++q;
			while (q < data_.size() && !is_space(data_[q]) && data_[q] != '>')
				++q;
		}
		t.name = std::string(data_.substr(p + 1, q - p - 1));
		while (true)
		{
			while (q < data_.size() && is_space(data_[q]))
				++q;
			if (q >= data_.size())
				fail_at(p, "unterminated tag <" + TextReader::printable(t.name));
			if (data_[q] == '>')
			{
				t.end = q + 1;
				return t;
			}
			if (data_[q] == '/' || data_[q] == '?')
			{
				t.self_closing = data_[q] == '/';
				++q;
				continue;
			}
			const std::size_t eq = data_.find('=', q);
			if (eq == std::string_view::npos || eq + 1 >= data_.size() ||
				(data_[eq + 1] != '"' && data_[eq + 1] != '\''))
				fail_at(q, "malformed attribute in <" + TextReader::printable(t.name) + ">");
			const char quote = data_[eq + 1];
			const std::size_t close = data_.find(quote, eq + 2);
			if (close == std::string_view::npos)
				fail_at(q, "unterminated attribute value");
			std::string key(data_.substr(q, eq - q));
			while (!key.empty() && is_space(key.back()))
				key.pop_back();
			t.attrs[key] = std::string(data_.substr(eq + 2, close - eq - 2));
			q = close + 1;
		}
	}

	// The raw bytes of a binary or appended array (header removed, decompressed).
	std::string bytes(Tag& t, std::size_t content_end)
	{
		const std::string format = t.attrs["format"];
		std::string raw;
		std::size_t at = t.end;
		const uint32 hs = header64_ ? 8 : 4;
		if (format == "binary")
		{
			if (!base64_decode(data_.substr(t.end, content_end - t.end), raw, data_.size()))
				fail_at(t.end, "bad base64 data");
		}
		else if (format == "appended")
		{
			if (appended_ == 0)
				fail_at(t.begin, "appended DataArray without AppendedData");
			const std::string& off = t.attrs["offset"];
			uint64 o = 0;
			auto [ptr, ec] = std::from_chars(off.data(), off.data() + off.size(), o);
			if (ec != std::errc() || o > data_.size() - appended_)
				fail_at(t.begin, "bad appended offset '" + TextReader::printable(off) + "'");
			at = appended_ + std::size_t(o);
			if (encoding_ == "base64")
			{
				if (!base64_decode(data_.substr(at), raw, data_.size()))
					fail_at(at, "bad base64 data");
			}
			else
				raw = std::string(data_.substr(at));
		}
		else
			fail_at(t.begin, "unknown DataArray format '" + TextReader::printable(format) + "'");
		ByteReader b(raw, 0, path_, big_endian_);
		auto word = [&]() { return header64_ ? b.read<uint64>() : uint64(b.read<uint32>()); };
		if (!compressed_)
		{
			const uint64 n = word();
			if (n > raw.size() - hs)
				fail_at(at, "array of " + std::to_string(n) + " bytes runs past the end of the data");
			return raw.substr(hs, std::size_t(n));
		}
#ifdef CGOGN_IO_HAS_ZLIB
		const uint64 nblocks = word(), block = word(), last = word();
		if (nblocks > raw.size() / hs)
			fail_at(at, "bad compressed header");
		std::vector<uint64> sizes(nblocks);
		for (auto& s : sizes)
			s = word();
		std::string out;
		std::size_t pos = b.position();
		for (uint64 k = 0; k < nblocks; ++k)
		{
			const uint64 usize = (k + 1 == nblocks && last != 0) ? last : block;
			if (sizes[k] > raw.size() - pos || usize > 64 * (raw.size() + 1024))
				fail_at(at, "compressed block runs past the end of the data");
			std::string u(usize, '\0');
			uLongf len = uLongf(usize);
			if (uncompress(reinterpret_cast<Bytef*>(u.data()), &len, reinterpret_cast<const Bytef*>(raw.data() + pos),
						   uLong(sizes[k])) != Z_OK ||
				len != usize)
				fail_at(at, "corrupt zlib block");
			out += u;
			pos += std::size_t(sizes[k]);
		}
		return out;
#else
		fail_at(at, "compressed VTU data needs zlib, which this build does not have");
#endif
	}

	std::vector<double> values(Tag& t, std::size_t content_end, uint64 count, bool finite)
	{
		const std::string type = t.attrs["type"];
		// the type, once: Float32 is read as float and held as a double
		const std::optional<ValueType> stored = vtu_value_type(type);
		if (!stored)
			fail_at(t.begin, "unknown DataArray type '" + TextReader::printable(type) + "'");
		const bool float32 = type == "Float32";
		std::vector<double> out;
		if (t.attrs["format"] == "ascii")
		{
			TextReader r(data_.substr(t.end, content_end - t.end), path_, '\0');
			r.check_count(count, 2, "values");
			out.reserve(count);
			const bool integer = is_integer_type(*stored);
			for (uint64 i = 0; i < count; ++i)
				out.push_back(integer ? double(r.read_int("an integer value")) : r.read_double("a value"));
			return out;
		}
		const std::string raw = bytes(t, content_end);
		ByteReader b(raw, 0, path_, big_endian_);
		const std::size_t size =
			float32 ? sizeof(float) : visit_value_type(*stored, []<typename T>() { return sizeof(T); });
		if (count == 0)
			count = raw.size() / size;
		if (raw.size() / size < count)
			fail_at(t.begin, "DataArray '" + t.attrs["Name"] + "' has " + std::to_string(raw.size() / size) +
								 " values, " + std::to_string(count) + " expected");
		out.reserve(count);
		auto read_all = [&]<typename T>() {
			for (uint64 i = 0; i < count; ++i)
			{
				const double v = double(b.read<T>());
				if (finite && !std::isfinite(v))
					fail_at(t.begin, "a point coordinate is not finite: NaN and infinite values are rejected");
				out.push_back(v);
			}
		};
		if (float32)
			read_all.template operator()<float>();
		else
			visit_value_type(*stored, read_all);
		return out;
	}

	std::vector<int64> integers(Tag& t, std::size_t content_end, uint64 count)
	{
		if (t.attrs["format"] == "ascii" && count == 0)
		{
			// connectivity: as many integers as the element holds
			TextReader r(data_.substr(t.end, content_end - t.end), path_, '\0');
			std::vector<int64> out;
			while (!r.at_end())
				out.push_back(r.read_int("an index"));
			return out;
		}
		return to_int64(values(t, content_end, count, true));
	}

	std::string_view data_;
	const std::string& path_;
	std::string encoding_;
	std::size_t appended_ = 0;
	bool big_endian_ = false;
	bool header64_ = false;
	bool compressed_ = false;
	uint32 nb_points_ = 0;
	uint32 nb_cells_ = 0;
	std::size_t cells_byte_ = 0; // where cell errors are reported
};

} // namespace

MeshData read_vtu(std::string_view data, const std::string& path)
{
	return VtuReader(data, path).read();
}

std::string write_vtu(const MeshData& d, bool binary)
{
	std::string head = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
					   "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece "
					   "NumberOfPoints=\"" +
					   std::to_string(d.nb_vertices()) + "\" NumberOfCells=\"" +
					   std::to_string(d.nb_cells() + d.nb_faces() + d.segments.size()) + "\">\n";
	std::string appended;
	auto array = [&](const std::string& type, const std::string& name, uint32 dim, const auto& fill_text,
					 const auto& fill_raw) {
		head += "<DataArray type=\"" + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" + std::to_string(dim) +
				"\" format=\"" + (binary ? "appended" : "ascii") + "\"";
		if (binary)
		{
			head += " offset=\"" + std::to_string(appended.size()) + "\"/>\n";
			std::string block;
			fill_raw(block);
			append_raw(appended, uint64(block.size()));
			appended += block;
		}
		else
		{
			head += ">\n";
			fill_text(head);
			head += "\n</DataArray>\n";
		}
	};
	auto doubles = [&](const std::string& name, uint32 dim, const std::vector<double>& v) {
		array(
			"Float64", name, dim,
			[&](std::string& s) {
				for (std::size_t i = 0; i < v.size(); ++i)
				{
					if (i > 0)
						s += i % 12 == 0 ? '\n' : ' ';
					append_double(s, v[i]);
				}
			},
			[&](std::string& s) {
				for (double x : v)
					append_raw(s, x);
			});
	};
	auto ints = [&](const std::string& name, const std::vector<int64>& v) {
		array(
			"Int64", name, 1,
			[&](std::string& s) {
				for (std::size_t i = 0; i < v.size(); ++i)
				{
					if (i > 0)
						s += i % 16 == 0 ? '\n' : ' ';
					if (v[i] < 0) // faceoffsets of the cells that are not polyhedra
						s += '-';
					append_uint(s, uint64(v[i] < 0 ? -v[i] : v[i]));
				}
			},
			[&](std::string& s) {
				for (int64 x : v)
					append_raw(s, x);
			});
	};
	// an integer column of type t (its values are exact: see Column)
	auto integers_of_type = [&](const std::string& name, ValueType t, const std::vector<double>& v) {
		array(
			vtu_type_name(t), name, 1,
			[&](std::string& s) {
				for (std::size_t i = 0; i < v.size(); ++i)
				{
					if (i > 0)
						s += i % 16 == 0 ? '\n' : ' ';
					append_int(s, int64(v[i]));
				}
			},
			[&](std::string& s) {
				visit_value_type(t, [&]<typename T>() {
					for (double x : v)
						append_raw(s, T(x));
				});
			});
	};
	head += "<Points>\n";
	doubles("Points", 3, d.positions);
	head += "</Points>\n<Cells>\n";
	std::vector<int64> conn, offsets, types, faces, face_offsets;
	const std::vector<std::vector<uint32>> streams = polyhedron_streams(d);
	std::size_t k = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		const uint32 n = d.cell_sizes[c];
		const bool polyhedron = d.is_polyhedron(c);
		for (uint32 i = 0; i < n; ++i)
			conn.push_back(d.cell_vertices[k + (polyhedron ? i : vtk_order(n, i))]);
		k += n;
		offsets.push_back(int64(conn.size()));
		types.push_back(polyhedron ? 42 : vtk_cell_type(n));
		// a polyhedron's faces: its face stream, and where it ends (-1 for the other cells)
		faces.insert(faces.end(), streams[c].begin(), streams[c].end());
		face_offsets.push_back(polyhedron ? int64(faces.size()) : -1);
	}
	k = 0;
	for (uint32 n : d.face_sizes) // the listed faces
	{
		for (uint32 i = 0; i < n; ++i)
			conn.push_back(d.face_vertices[k++]);
		offsets.push_back(int64(conn.size()));
		types.push_back(vtk_face_type(n));
		face_offsets.push_back(-1);
	}
	for (const auto& [a, b] : d.segments)
	{
		conn.insert(conn.end(), {int64(a), int64(b)});
		offsets.push_back(int64(conn.size()));
		types.push_back(3); // VTK_LINE
	}
	ints("connectivity", conn);
	ints("offsets", offsets);
	ints("types", types);
	if (!d.cell_nb_faces.empty())
	{
		face_offsets.resize(types.size(), -1); // the segments
		ints("faces", faces);
		ints("faceoffsets", face_offsets);
	}
	head += "</Cells>\n";
	auto data = [&](const char* section, const std::vector<Column>& cols) {
		head += std::string("<") + section + ">\n";
		for (const auto& c : cols)
			if (c.dim < 1 || c.dim > 3 || c.name.find_first_of("\"<>&") != std::string::npos)
				continue;
			else if (c.dim == 1 && is_integer_type(c.type))
				integers_of_type(c.name, c.type, c.values);
			else
				doubles(c.name, c.dim, c.values);
		head += std::string("</") + section + ">\n";
	};
	data("PointData", d.vertex_columns);
	data("CellData", vtk_cell_data(d));
	head += "</Piece>\n</UnstructuredGrid>\n";
	if (binary)
	{
		head += "<AppendedData encoding=\"raw\">\n_";
		head += appended;
		head += "\n</AppendedData>\n";
	}
	head += "</VTKFile>\n";
	return head;
}

} // namespace cgogn::io::detail
