// SPDX-License-Identifier: MIT
#include <cgogn/io/error.h>

#include "formats.h"

namespace cgogn::io::detail
{

MeshData read_tetgen(std::string_view, const std::string& node_path, std::string_view, const std::string&)
{
	throw Error(node_path, "not implemented yet");
}
std::pair<std::string, std::string> write_tetgen(const MeshData&)
{
	throw Error("", "not implemented yet");
}

} // namespace cgogn::io::detail
