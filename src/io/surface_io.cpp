// SPDX-License-Identifier: MIT
#include <cgogn/io/surface.h>

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
		throw Error(path, "unknown surface format: use .off, .obj, .ply, .stl, .msh, .mesh, .vtk, .vtu or .pvtu, or "
						  "give the format");
	if (f == Format::TetGen || f == Format::Ovm)
		throw Error(path, std::string(format_name(f)) + " is not a surface format (use load_volume/save_volume)");
	return f;
}

// Formats of volumes and surfaces, which list faces and edges beside the cells.
bool lists_faces(Format f)
{
	return f == Format::Gmsh || f == Format::Medit || f == Format::VtkLegacy || f == Format::Vtu || f == Format::Pvtu;
}

template <typename MAP>
LoadReport load_surface_into(MAP& m, const std::string& path, const LoadOptions& options)
{
	const Format f = resolve(options.format, path);
	detail::MeshData d =
		f == Format::Pvtu ? detail::read_pvtu(path) : detail::read_mesh(f, detail::read_file(path), path);
	if (lists_faces(f))
		d.faces_as_cells(path);
	detail::validate(d, path);
	LoadReport r = detail::build_map(m, d, path);
	r.format = f;
	return r;
}

template <typename MAP>
void save_surface_of(const MAP& m, const std::string& path, const SaveOptions& options)
{
	const Format f = resolve(options.format, path);
	detail::MeshData d = detail::extract_surface(m, path, options.attributes);
	if (lists_faces(f))
	{
		if (f == Format::Gmsh || f == Format::Medit)
		{
			const auto nb = std::count_if(d.cell_sizes.begin(), d.cell_sizes.end(), [](uint32 n) { return n > 4; });
			if (nb > 0)
				throw Error(path, "the map has " + std::to_string(nb) +
									  " face(s) of more than 4 vertices: the format holds triangles and quadrangles "
									  "(triangulate first, or write .vtk, .vtu, .obj or .ply)");
		}
		if constexpr (!std::is_same_v<MAP, IncidenceGraph>)
			if (options.attributes)
				detail::list_edges_with_data(m, d, path);
		d.cells_as_faces();
	}
	std::string out;
	switch (f)
	{
	case Format::Off:
		out = detail::write_off(d);
		break;
	case Format::Obj:
		out = detail::write_obj(d);
		break;
	case Format::Ply:
		detail::check_written_names(d, path);
		out = detail::write_ply(d, options.binary, path);
		break;
	case Format::Stl:
		out = detail::write_stl(d, options.binary);
		break;
	case Format::Gmsh:
		out = detail::write_gmsh(d, options.binary, path);
		break;
	case Format::Medit:
		out = detail::write_medit(d, path);
		break;
	case Format::VtkLegacy:
		detail::check_written_names(d, path);
		out = detail::write_vtk(d, options.binary);
		break;
	case Format::Pvtu:
		detail::check_written_names(d, path);
		detail::write_single_piece_pvtu(d, path, options.binary);
		return;
	default:
		detail::check_written_names(d, path);
		out = detail::write_vtu(d, options.binary);
		break;
	}
	detail::write_file(path, out);
}

} // namespace

LoadReport load_surface(CMap2& m, const std::string& path, const LoadOptions& options)
{
	return load_surface_into(m, path, options);
}

LoadReport load_surface(GMap2& m, const std::string& path, const LoadOptions& options)
{
	return load_surface_into(m, path, options);
}

LoadReport load_surface(IncidenceGraph& ig, const std::string& path, const LoadOptions& options)
{
	return load_surface_into(ig, path, options);
}

void save_surface(const IncidenceGraph& ig, const std::string& path, const SaveOptions& options)
{
	save_surface_of(ig, path, options);
}

void save_surface(const CMap2& m, const std::string& path, const SaveOptions& options)
{
	save_surface_of(m, path, options);
}

void save_surface(const GMap2& m, const std::string& path, const SaveOptions& options)
{
	save_surface_of(m, path, options);
}

} // namespace cgogn::io
