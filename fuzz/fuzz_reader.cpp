// SPDX-License-Identifier: MIT
// libFuzzer target for one reader (chosen by CGOGN_FUZZ_FORMAT at compile
// time): any input must either throw io::Error or give data that builds into
// a map passing check_integrity. Crashes, leaks and sanitizer reports are bugs.
#include <cgogn/core/builder/map_builder.h>
#include <cgogn/core/functions/integrity.h>
#include <cgogn/io/error.h>

#include "formats.h"
#include "map_transfer.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

using namespace cgogn;
using namespace cgogn::io;

namespace
{

enum Kind
{
	OFF,
	OBJ,
	PLY,
	STL,
	MEDIT,
	VTK,
	VTU,
	GMSH,
	TETGEN
};

io::detail::MeshData parse(std::string_view in, const std::string& path)
{
	switch (CGOGN_FUZZ_FORMAT)
	{
	case OFF:
		return io::detail::read_off(in, path);
	case OBJ:
		return io::detail::read_obj(in, path);
	case PLY:
		return io::detail::read_ply(in, path);
	case STL:
		return io::detail::read_stl(in, path);
	case MEDIT:
		return io::detail::read_medit(in, path);
	case VTK:
		return io::detail::read_vtk(in, path);
	case VTU:
		return io::detail::read_vtu(in, path);
	case GMSH:
		return io::detail::read_gmsh(in, path);
	default:
	{
		// the .node and .ele contents, separated by the first NUL byte
		const std::size_t sep = in.find('\0');
		const std::string_view node = in.substr(0, sep);
		const std::string_view ele = sep == std::string_view::npos ? std::string_view() : in.substr(sep + 1);
		return io::detail::read_tetgen(node, path + ".node", ele, path + ".ele");
	}
	}
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const std::string path = "fuzz-input";
	const std::string_view in(reinterpret_cast<const char*>(data), size);
	io::detail::MeshData d;
	try
	{
		d = parse(in, path);
		io::detail::validate(d, path);
	}
	catch (const io::Error&)
	{
		return 0;
	}
	const bool volume = CGOGN_FUZZ_FORMAT >= MEDIT;
	try
	{
		if (volume)
		{
			io::detail::orient_cells(d);
			CMap3 m;
			io::detail::build_map(m, d, path);
			if (!check_integrity(m).ok())
				std::abort();
		}
		else
		{
			CMap2 m;
			io::detail::build_map(m, d, path);
			if (!check_integrity(m).ok())
				std::abort();
		}
	}
	catch (const io::Error&)
	{
		// e.g. too large for 32-bit indices
	}
	return 0;
}
