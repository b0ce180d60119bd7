// SPDX-License-Identifier: MIT
#include <cgogn/io/error.h>

#include "formats.h"

namespace cgogn::io::detail
{

MeshData read_mesh(Format f, std::string_view data, const std::string& path)
{
	switch (f)
	{
	case Format::Off:
		return read_off(data, path);
	case Format::Obj:
		return read_obj(data, path);
	case Format::Ply:
		return read_ply(data, path);
	case Format::Stl:
		return read_stl(data, path);
	case Format::Medit:
		return read_medit(data, path);
	case Format::VtkLegacy:
		return read_vtk(data, path);
	case Format::Vtu:
		return read_vtu(data, path);
	case Format::Gmsh:
		return read_gmsh(data, path);
	case Format::Ovm:
		return read_ovm(data, path);
	case Format::TetGen:
	case Format::Pvtu:
	case Format::Auto:
		break;
	}
	throw Error(path, "no single-file reader for this format");
}

} // namespace cgogn::io::detail
