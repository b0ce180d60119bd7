// SPDX-License-Identifier: MIT
#include <cgogn/io/error.h>

#include "formats.h"

namespace cgogn::io::detail
{

MeshData read_gmsh(std::string_view, const std::string& path)
{
	throw Error(path, "not implemented yet");
}
std::string write_gmsh(const MeshData&, bool)
{
	throw Error("", "not implemented yet");
}

} // namespace cgogn::io::detail
