// SPDX-License-Identifier: MIT
#include <cgogn/io/options.h>

#include "formats.h"

#include <algorithm>
#include <cctype>

namespace cgogn::io
{

namespace detail
{

std::string lower_extension(const std::string& path)
{
	const std::size_t dot = path.find_last_of('.');
	const std::size_t slash = path.find_last_of("/\\");
	if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
		return {};
	std::string ext = path.substr(dot + 1);
	std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
	return ext;
}

} // namespace detail

Format format_from_extension(const std::string& path)
{
	const std::string ext = detail::lower_extension(path);
	if (ext == "off")
		return Format::Off;
	if (ext == "obj")
		return Format::Obj;
	if (ext == "ply")
		return Format::Ply;
	if (ext == "stl")
		return Format::Stl;
	if (ext == "mesh")
		return Format::Medit;
	if (ext == "vtk")
		return Format::VtkLegacy;
	if (ext == "vtu")
		return Format::Vtu;
	if (ext == "msh")
		return Format::Gmsh;
	if (ext == "node" || ext == "ele")
		return Format::TetGen;
	if (ext == "ovm")
		return Format::Ovm;
	if (ext == "pvtu")
		return Format::Pvtu;
	return Format::Auto;
}

const char* format_name(Format f)
{
	switch (f)
	{
	case Format::Auto:
		return "auto";
	case Format::Off:
		return "OFF";
	case Format::Obj:
		return "OBJ";
	case Format::Ply:
		return "PLY";
	case Format::Stl:
		return "STL";
	case Format::Medit:
		return "MEDIT";
	case Format::VtkLegacy:
		return "VTK";
	case Format::Vtu:
		return "VTU";
	case Format::Gmsh:
		return "gmsh";
	case Format::TetGen:
		return "TetGen";
	case Format::Ovm:
		return "OVM";
	case Format::Pvtu:
		return "PVTU";
	}
	return "unknown";
}

} // namespace cgogn::io
