// SPDX-License-Identifier: MIT
#include <cgogn/io/volume.h>

#include "file_io.h"
#include "formats.h"
#include "map_transfer.h"

#include <algorithm>

namespace cgogn::io
{

namespace
{
Format resolve(Format f, const std::string& path)
{
	if (f == Format::Auto)
		f = format_from_extension(path);
	if (f == Format::Auto)
		throw Error(
			path, "unknown volume format: use .mesh, .vtk, .vtu, .pvtu, .msh, .node/.ele or .ovm, or give the format");
	if (f != Format::Medit && f != Format::VtkLegacy && f != Format::Vtu && f != Format::Gmsh && f != Format::TetGen &&
		f != Format::Ovm && f != Format::Pvtu)
		throw Error(path, std::string(format_name(f)) + " is not a volume format (use load_surface/save_surface)");
	return f;
}

// foo.ele -> foo.node and the reverse
std::string with_extension(const std::string& path, const char* ext)
{
	const std::size_t dot = path.find_last_of('.');
	return (dot == std::string::npos ? path : path.substr(0, dot)) + ext;
}

template <typename MAP>
LoadReport load_volume_into(MAP& m, const std::string& path, const LoadOptions& options)
{
	const Format f = resolve(options.format, path);
	detail::MeshData d;
	if (f == Format::TetGen)
	{
		const std::string node_path = with_extension(path, ".node"), ele_path = with_extension(path, ".ele");
		const std::string node = detail::read_file(node_path), ele = detail::read_file(ele_path);
		d = detail::read_tetgen(node, node_path, ele, ele_path);
	}
	else if (f == Format::Pvtu)
		d = detail::read_pvtu(path);
	else
		d = detail::read_mesh(f, detail::read_file(path), path);
	detail::validate(d, path);
	const uint32 flipped = detail::orient_cells(d);
	LoadReport r = detail::build_map(m, d, path);
	r.format = f;
	r.nb_cells_reoriented = flipped;
	return r;
}

template <typename MAP>
void save_volume_of(const MAP& m, const std::string& path, const SaveOptions& options)
{
	const Format f = resolve(options.format, path);
	const detail::MeshData d = detail::extract_volume(m, path, options.attributes);
	if (!d.cell_nb_faces.empty() && f != Format::VtkLegacy && f != Format::Vtu && f != Format::Pvtu && f != Format::Ovm)
	{
		const auto nb = std::count_if(d.cell_nb_faces.begin(), d.cell_nb_faces.end(), [](uint32 n) { return n > 0; });
		throw Error(path, "the map has " + std::to_string(nb) +
							  " volume(s) that are not tetrahedra, pyramids, prisms or hexahedra: the format cannot "
							  "hold them (.vtk, .vtu and .ovm hold any polyhedron)");
	}
	switch (f)
	{
	case Format::Medit:
		detail::write_file(path, detail::write_medit(d, path));
		break;
	case Format::VtkLegacy:
		detail::check_written_names(d, path);
		detail::write_file(path, detail::write_vtk(d, options.binary));
		break;
	case Format::Vtu:
		detail::check_written_names(d, path);
		detail::write_file(path, detail::write_vtu(d, options.binary));
		break;
	case Format::Pvtu:
		detail::check_written_names(d, path);
		detail::write_single_piece_pvtu(d, path, options.binary);
		break;
	case Format::Gmsh:
		detail::write_file(path, detail::write_gmsh(d, options.binary, path));
		break;
	case Format::Ovm:
		detail::check_written_names(d, path);
		detail::write_file(path, detail::write_ovm(d));
		break;
	default: {
		for (uint32 n : d.cell_sizes)
			if (n != 4)
				throw Error(path, "TetGen files hold tetrahedra only; the map has other volumes");
		auto [node, ele] = detail::write_tetgen(d);
		detail::write_file(with_extension(path, ".node"), node);
		detail::write_file(with_extension(path, ".ele"), ele);
		break;
	}
	}
}

} // namespace

LoadReport load_volume(CMap3& m, const std::string& path, const LoadOptions& options)
{
	return load_volume_into(m, path, options);
}

LoadReport load_volume(GMap3& m, const std::string& path, const LoadOptions& options)
{
	return load_volume_into(m, path, options);
}

void save_volume(const CMap3& m, const std::string& path, const SaveOptions& options)
{
	save_volume_of(m, path, options);
}

void save_volume(const GMap3& m, const std::string& path, const SaveOptions& options)
{
	save_volume_of(m, path, options);
}

} // namespace cgogn::io
