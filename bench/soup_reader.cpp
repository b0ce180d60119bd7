// SPDX-License-Identifier: MIT
#include "soup_reader.h"

#include <charconv>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

namespace cgogn_bench
{

namespace
{

bool read_file(const std::string& path, std::string& out)
{
	std::ifstream in(path, std::ios::binary);
	if (!in)
		return false;
	std::ostringstream ss;
	ss << in.rdbuf();
	out = ss.str();
	return true;
}

// splits text into lines without copying
template <typename F>
void foreach_line(std::string_view text, F&& f)
{
	std::size_t pos = 0;
	while (pos < text.size())
	{
		std::size_t end = text.find('\n', pos);
		if (end == std::string_view::npos)
			end = text.size();
		std::string_view line = text.substr(pos, end - pos);
		if (!line.empty() && line.back() == '\r')
			line.remove_suffix(1);
		f(line);
		pos = end + 1;
	}
}

std::string_view next_token(std::string_view& s)
{
	std::size_t b = s.find_first_not_of(" \t");
	if (b == std::string_view::npos)
	{
		s = {};
		return {};
	}
	std::size_t e = s.find_first_of(" \t", b);
	if (e == std::string_view::npos)
		e = s.size();
	std::string_view t = s.substr(b, e - b);
	s.remove_prefix(e);
	return t;
}

double to_double(std::string_view t)
{
	std::string tmp(t); // strtod: exact round-trip of the printed digits
	return std::strtod(tmp.c_str(), nullptr);
}

long to_long(std::string_view t)
{
	long v = 0;
	std::from_chars(t.data(), t.data() + t.size(), v);
	return v;
}

} // namespace

std::optional<cgogn::SurfaceSoup> read_obj_soup(const std::string& path)
{
	std::string text;
	if (!read_file(path, text))
		return std::nullopt;
	cgogn::SurfaceSoup soup;
	foreach_line(text, [&](std::string_view line) {
		std::string_view rest = line;
		std::string_view key = next_token(rest);
		if (key == "v")
		{
			std::array<double, 3> p{};
			for (double& x : p)
				x = to_double(next_token(rest));
			soup.positions.push_back(p);
		}
		else if (key == "f")
		{
			uint32_t n = 0;
			for (std::string_view t = next_token(rest); !t.empty(); t = next_token(rest))
			{
				long i = to_long(t.substr(0, t.find('/')));
				i = i < 0 ? long(soup.positions.size()) + i : i - 1;
				soup.face_vertices.push_back(uint32_t(i));
				++n;
			}
			soup.face_sizes.push_back(n);
		}
	});
	soup.nb_vertices = uint32_t(soup.positions.size());
	return soup;
}

std::optional<cgogn::VolumeSoup> read_medit_tet_soup(const std::string& path)
{
	std::string text;
	if (!read_file(path, text))
		return std::nullopt;
	cgogn::VolumeSoup soup;
	enum class Section
	{
		none,
		vertices_count,
		vertices,
		tets_count,
		tets
	} section = Section::none;
	long remaining = 0;
	foreach_line(text, [&](std::string_view line) {
		std::string_view rest = line;
		std::string_view t = next_token(rest);
		if (t.empty() || t[0] == '#')
			return;
		switch (section)
		{
		case Section::vertices_count:
		case Section::tets_count:
			remaining = to_long(t);
			section = section == Section::vertices_count ? Section::vertices : Section::tets;
			if (remaining == 0)
				section = Section::none;
			return;
		case Section::vertices: {
			std::array<double, 3> p{to_double(t), 0, 0};
			p[1] = to_double(next_token(rest));
			p[2] = to_double(next_token(rest));
			soup.positions.push_back(p);
			if (--remaining == 0)
				section = Section::none;
			return;
		}
		case Section::tets: {
			soup.cell_sizes.push_back(4);
			soup.cell_vertices.push_back(uint32_t(to_long(t) - 1));
			for (int k = 0; k < 3; ++k)
				soup.cell_vertices.push_back(uint32_t(to_long(next_token(rest)) - 1));
			if (--remaining == 0)
				section = Section::none;
			return;
		}
		case Section::none:
			// data lines of other sections are numbers and fall here, ignored
			if (t == "Vertices" || t == "Tetrahedra")
			{
				const bool v = t == "Vertices";
				std::string_view count = next_token(rest); // the count may follow on the same line
				if (count.empty())
					section = v ? Section::vertices_count : Section::tets_count;
				else
				{
					remaining = to_long(count);
					section = remaining == 0 ? Section::none : (v ? Section::vertices : Section::tets);
				}
			}
			return;
		}
	});
	soup.nb_vertices = uint32_t(soup.positions.size());
	return soup;
}

} // namespace cgogn_bench
