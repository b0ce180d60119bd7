// SPDX-License-Identifier: MIT
// The .pvtu index: the arrays of the first piece, declared once, and the
// list of pieces.
#include <cgogn/io/error.h>
#include <cgogn/io/pvtu.h>

#include "file_io.h"
#include "formats.h"

#include <filesystem>

namespace cgogn::io
{

namespace
{

// The <DataArray .../> declarations of one section of a VTU header, as
// <PDataArray> tags (type, name and components; no data).
std::string declarations(const std::string& head, const std::string& section, const std::string& path)
{
	const std::size_t open = head.find("<" + section + ">");
	const std::size_t close = head.find("</" + section + ">");
	if (open == std::string::npos || close == std::string::npos || close < open)
		throw Error(path, "no " + section + " section in the piece");
	std::string out;
	const std::string tag = "<DataArray";
	for (std::size_t at = head.find(tag, open); at != std::string::npos && at < close; at = head.find(tag, at + 1))
	{
		const std::size_t end = head.find('>', at);
		std::string decl = "<PDataArray";
		for (const char* key : {"type", "Name", "NumberOfComponents"})
		{
			const std::string k = std::string(" ") + key + "=\"";
			const std::size_t first = head.find(k, at);
			if (first == std::string::npos || first > end)
				continue;
			const std::size_t last = head.find('"', first + k.size());
			decl += head.substr(first, last + 1 - first);
		}
		out += decl + "/>\n";
	}
	return out;
}

} // namespace

void write_pvtu_index(const std::string& pvtu_path, const std::vector<std::string>& sources, int ghost_level)
{
	if (sources.empty())
		throw Error(pvtu_path, "a .pvtu index needs at least one piece");
	const std::filesystem::path dir = std::filesystem::path(pvtu_path).parent_path();
	const std::string first = (dir / sources[0]).string();
	std::string head = detail::read_file(first);
	const std::size_t piece_end = head.find("</Piece>");
	if (piece_end == std::string::npos)
		throw Error(first, "not a VTU piece (no </Piece>)");
	head.resize(piece_end);
	std::string index = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
						"byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<PUnstructuredGrid GhostLevel=\"" +
						std::to_string(ghost_level) + "\">\n";
	index += "<PPointData>\n" + declarations(head, "PointData", first) + "</PPointData>\n";
	index += "<PCellData>\n" + declarations(head, "CellData", first) + "</PCellData>\n";
	index += "<PPoints>\n" + declarations(head, "Points", first) + "</PPoints>\n";
	for (const std::string& s : sources)
		index += "<Piece Source=\"" + s + "\"/>\n";
	index += "</PUnstructuredGrid>\n</VTKFile>\n";
	detail::write_file(pvtu_path, index);
}

namespace detail
{

void write_single_piece_pvtu(const MeshData& d, const std::string& path, bool binary)
{
	std::filesystem::path piece(path);
	piece.replace_filename(piece.stem().string() + "_0.vtu");
	write_file(piece.string(), write_vtu(d, binary));
	write_pvtu_index(path, {piece.filename().string()}, 0);
}

} // namespace detail

} // namespace cgogn::io
