// SPDX-License-Identifier: MIT
// STL, ascii and binary. A file is binary when its size is exactly 84 + 50 n
// for the n of its header, ascii when it starts with "solid" otherwise.
// Vertices with bitwise-equal coordinates (after -0 -> +0) are welded into one;
// facet normals become the face column `normal`.
#include "byte_reader.h"
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace cgogn::io::detail
{

namespace
{

struct Key
{
	std::array<uint64, 3> bits;
	bool operator==(const Key&) const = default;
};
struct KeyHash
{
	std::size_t operator()(const Key& k) const
	{
		uint64 h = 1469598103934665603ull;
		for (uint64 b : k.bits)
		{
			h ^= b;
			h *= 1099511628211ull;
			h ^= h >> 29;
		}
		return std::size_t(h);
	}
};

class Welder
{
public:
	explicit Welder(MeshData& d, std::size_t expected) : d_(d)
	{
		map_.reserve(expected);
	}
	uint32 add(double x, double y, double z)
	{
		Key k;
		const double c[3] = {x + 0.0, y + 0.0, z + 0.0}; // -0 -> +0
		for (int i = 0; i < 3; ++i)
			std::memcpy(&k.bits[std::size_t(i)], &c[i], sizeof(double));
		auto [it, inserted] = map_.try_emplace(k, d_.nb_vertices());
		if (inserted)
			d_.positions.insert(d_.positions.end(), c, c + 3);
		return it->second;
	}

private:
	MeshData& d_;
	std::unordered_map<Key, uint32, KeyHash> map_;
};

MeshData read_binary_stl(std::string_view data, const std::string& path, uint32 n)
{
	MeshData d;
	ByteReader b(data, 84, path, false);
	Welder w(d, n / 2 + 16);
	Column normal{"normal", 3, {}};
	normal.values.reserve(3 * std::size_t(n));
	d.cell_sizes.assign(n, 3);
	d.cell_vertices.reserve(3 * std::size_t(n));
	for (uint32 f = 0; f < n; ++f)
	{
		float v[12];
		for (float& x : v)
		{
			x = b.read<float>();
			if (!std::isfinite(x))
				b.fail("coordinate is not finite: NaN and infinite values are rejected");
		}
		b.skip(2);
		normal.values.insert(normal.values.end(), {double(v[0]), double(v[1]), double(v[2])});
		for (int i = 1; i < 4; ++i)
			d.cell_vertices.push_back(w.add(v[3 * i], v[3 * i + 1], v[3 * i + 2]));
	}
	d.cell_columns.push_back(std::move(normal));
	return d;
}

MeshData read_ascii_stl(std::string_view text, const std::string& path)
{
	MeshData d;
	TextReader r(text, path, '\0');
	Welder w(d, text.size() / 200 + 16);
	Column normal{"normal", 3, {}};
	auto expect = [&](std::string_view word) {
		std::string_view t = r.token();
		if (t.empty())
			r.fail("unexpected end of file, expected '" + std::string(word) + "'");
		if (t != word)
			r.fail("expected '" + std::string(word) + "', found '" + TextReader::printable(t) + "'");
	};
	expect("solid");
	r.rest_of_line(); // the name
	while (true)
	{
		std::string_view t = r.token();
		if (t == "endsolid")
		{
			r.rest_of_line();
			break;
		}
		if (t != "facet")
			r.fail(t.empty() ? std::string("unexpected end of file, expected 'facet' or 'endsolid'")
							 : "expected 'facet' or 'endsolid', found '" + TextReader::printable(t) + "'");
		expect("normal");
		for (int i = 0; i < 3; ++i)
			normal.values.push_back(r.read_double("a normal coordinate"));
		expect("outer");
		expect("loop");
		uint32 n = 0;
		while (true)
		{
			std::string_view v = r.token();
			if (v == "endloop")
				break;
			if (v.empty())
				r.fail("unexpected end of file, expected 'vertex' or 'endloop'");
			if (v != "vertex")
				r.fail("expected 'vertex' or 'endloop', found '" + TextReader::printable(v) + "'");
			const double x = r.read_double("a vertex coordinate");
			const double y = r.read_double("a vertex coordinate");
			const double z = r.read_double("a vertex coordinate");
			d.cell_vertices.push_back(w.add(x, y, z));
			++n;
		}
		expect("endfacet");
		d.cell_sizes.push_back(n);
	}
	// several solids may follow each other
	if (!r.at_end())
		r.fail("unexpected content after 'endsolid'");
	d.cell_columns.push_back(std::move(normal));
	return d;
}

} // namespace

MeshData read_stl(std::string_view data, const std::string& path)
{
	if (data.size() >= 84)
	{
		uint32 n;
		std::memcpy(&n, data.data() + 80, 4);
		if constexpr (std::endian::native == std::endian::big)
			n = (n >> 24) | ((n >> 8) & 0xff00u) | ((n << 8) & 0xff0000u) | (n << 24);
		if (uint64(data.size()) == 84 + 50 * uint64(n))
			return read_binary_stl(data, path, n);
	}
	std::size_t i = 0;
	while (i < data.size() && (data[i] == ' ' || data[i] == '\t' || data[i] == '\r' || data[i] == '\n'))
		++i;
	if (data.substr(i, 5) == "solid")
		return read_ascii_stl(data, path);
	if (data.size() < 84)
		throw Error(path, Error::Where::Byte, data.size(),
					"too short for a binary STL file (84 bytes of header needed) and not an ascii one");
	uint32 n;
	std::memcpy(&n, data.data() + 80, 4);
	throw Error(path, Error::Where::Byte, 80,
				"binary STL declares " + std::to_string(n) + " triangles, which needs " +
					std::to_string(84 + 50 * uint64(n)) + " bytes, but the file has " + std::to_string(data.size()));
}

std::string write_stl(const MeshData& d, bool binary)
{
	std::string s;
	uint64 nt = 0;
	for (uint32 n : d.cell_sizes)
		nt += n >= 3 ? n - 2 : 0;
	if (binary)
	{
		s.assign(80, '\0');
		const char title[] = "binary STL written by cgogn";
		std::memcpy(s.data(), title, sizeof(title) - 1);
		append_raw(s, uint32(nt));
		s.reserve(84 + 50 * nt);
	}
	else
		s = "solid cgogn\n";
	auto pos = [&](uint32 v) {
		return std::array<double, 3>{d.positions[3 * std::size_t(v)], d.positions[3 * std::size_t(v) + 1],
									 d.positions[3 * std::size_t(v) + 2]};
	};
	std::size_t k = 0;
	for (uint32 f = 0; f < d.nb_cells(); ++f)
	{
		const uint32 n = d.cell_sizes[f];
		const uint32* fv = &d.cell_vertices[k];
		k += n;
		for (uint32 i = 1; i + 1 < n; ++i)
		{
			const std::array<std::array<double, 3>, 3> p = {pos(fv[0]), pos(fv[i]), pos(fv[i + 1])};
			const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
			const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
			double nrm[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
			const double l = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
			for (double& x : nrm)
				x = l > 0.0 ? x / l : 0.0;
			if (binary)
			{
				for (double x : nrm)
					append_raw(s, float(x));
				for (const auto& q : p)
					for (double x : q)
						append_raw(s, float(x));
				s.append(2, '\0');
			}
			else
			{
				s += "facet normal";
				for (double x : nrm)
				{
					s += ' ';
					append_double(s, x);
				}
				s += "\n outer loop\n";
				for (const auto& q : p)
				{
					s += "  vertex";
					for (double x : q)
					{
						s += ' ';
						append_double(s, x);
					}
					s += '\n';
				}
				s += " endloop\nendfacet\n";
			}
		}
	}
	if (!binary)
		s += "endsolid cgogn\n";
	return s;
}

} // namespace cgogn::io::detail
