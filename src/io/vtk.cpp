// SPDX-License-Identifier: MIT
#include <cgogn/io/error.h>

#include "formats.h"

namespace cgogn::io::detail
{

MeshData read_vtk(std::string_view, const std::string& path)
{
	throw Error(path, "not implemented yet");
}
std::string write_vtk(const MeshData&, bool)
{
	throw Error("", "not implemented yet");
}

} // namespace cgogn::io::detail
