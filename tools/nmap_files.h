// SPDX-License-Identifier: MIT
// The maps of any dimension in the `cgogn` program: .nmap files loaded into
// the map type their header names, what `cgogn info` reports about them, and
// a surface or volume mesh as a map of any dimension.
#pragma once

#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/nmap.h>

#include "tool_common.h"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>

namespace cgogn::tool
{

/// Loads the .nmap file at path into the map its header names (CMapN<D> or
/// GMapN<D>) and calls f(map). Throws io::Error as io::load_nmap does.
template <typename FUNC>
void with_loaded_nmap(const std::string& path, Progress& progress, const FUNC& f)
{
	progress.stage("loading " + path);
	const io::NMapHeader h = io::read_nmap_header(path);
	const auto load = [&]<typename MAP>() {
		MAP m;
		io::load_nmap(m, path);
		f(m);
	};
	[&]<uint32... D>(std::integer_sequence<uint32, D...>)
	{
		(
			[&] {
				if (h.dimension != D + 1)
					return;
				if (h.gmap)
					load.template operator()<GMapN<D + 1>>();
				else
					load.template operator()<CMapN<D + 1>>();
			}(),
			...);
	}
	(std::make_integer_sequence<uint32, MAX_DIMENSION>{});
}

/// What `cgogn info` reports about a map of any dimension: the map type, its
/// dimension and darts, the f-vector, Euler characteristic, connected
/// components, whether it has a boundary (and the f-vector of the boundary
/// when it does), and, for a G-map, whether it is orientable. O(size of m).
template <typename MAP>
nlohmann::json nmap_info(const MAP& m)
{
	constexpr uint32 D = MAP::dimension;
	nlohmann::json j;
	j["map"] = std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(D) + ">";
	j["dimension"] = D;
	j["darts"] = nb_darts(m);
	j["f_vector"] = f_vector(m);
	j["euler_characteristic"] = euler_characteristic(m);
	j["connected_components"] = nb_connected_components(m);
	j["boundary"] = has_boundary(m);
	if constexpr (D >= 2)
		if (has_boundary(m))
			j["boundary_f_vector"] = f_vector(extract_boundary(m));
	if constexpr (is_gmap_v<MAP>)
		j["orientable"] = is_orientable(m);
	else
		j["orientable"] = true;
	return j;
}

/// A surface or volume mesh as the map of any dimension of the same darts
/// (to_nmap), its vertex positions as the PointD<3> attribute `position`
/// (the type .nmap files and io::save_vtu take). O(size of m).
template <typename MAP>
auto mesh_as_nmap(const MAP& m)
{
	auto n = to_nmap(m);
	const auto from = get_attribute<geometry::Vec3, typename MAP::Vertex>(m, "position");
	if (auto p = get_attribute<geometry::Vec3, CellD<0>>(n, "position"); p && from)
	{
		remove_attribute(n, p);
		auto to = add_attribute<PointD<3>, CellD<0>>(n, "position");
		foreach_cell(n, [&](CellD<0> v) {
			const geometry::Vec3& x = value(m, *from, typename MAP::Vertex(v.dart));
			(*to)[v] = {x[0], x[1], x[2]};
		});
	}
	return n;
}

} // namespace cgogn::tool
