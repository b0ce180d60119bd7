// SPDX-License-Identifier: MIT
// The libFuzzer target of the .cgmap reader. The first byte chooses the map
// type to load into, the rest is the file. Any input must either throw
// io::Error and leave the map as it was, or give a map that passes
// check_integrity and saves to bytes that load back to the same bytes.
// Crashes, leaks and sanitizer reports are bugs.
#include <cgogn/core/build/generators.h>
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/properties/integrity.h>
#include <cgogn/io/map_file.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

using namespace cgogn;

namespace
{

void require(bool ok)
{
	if (!ok)
		std::abort();
}

template <typename MAP>
void load(std::string_view bytes)
{
	MAP m;
	if constexpr (std::same_as<MAP, CMap2>)
		build_surface(m, grid_soup(1, 1));
	const std::string before = io::save_map_to_bytes(m);
	try
	{
		io::load_map_from_bytes(m, bytes, "fuzz");
	}
	catch (const io::Error&)
	{
		require(io::save_map_to_bytes(m) == before);
		return;
	}
	require(check_integrity(m).ok());
	const std::string once = io::save_map_to_bytes(m);
	MAP again;
	io::load_map_from_bytes(again, once, "fuzz");
	require(io::save_map_to_bytes(again) == once);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	if (size == 0)
		return 0;
	const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
	switch (data[0] % 8)
	{
	case 0:
		load<CMap2>(bytes);
		break;
	case 1:
		load<CMap3>(bytes);
		break;
	case 2:
		load<GMap2>(bytes);
		break;
	case 3:
		load<GMap3>(bytes);
		break;
	case 4:
		load<Graph>(bytes);
		break;
	case 5:
		load<CMapN<3>>(bytes);
		break;
	case 6:
		load<GMapN<2>>(bytes);
		break;
	default:
		load<CMap1>(bytes);
		break;
	}
	return 0;
}
