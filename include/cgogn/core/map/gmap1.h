// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap_base.h>

namespace cgogn
{

/// A 1-dimensional generalized map: darts linked by two involutions, beta0
/// (the other end of the same edge) and beta1 (the other edge at the same
/// vertex), into closed polygons. Each edge of a polygon has two darts, one
/// at each of its vertices; a polygon of n edges has 2n darts. Unlike phi1,
/// the involutions carry no orientation, which is what lets a 2-G-map
/// represent surfaces that cannot be oriented.
class GMap1 : public CMapBase
{
public:
	static constexpr uint32 dimension = 1; ///< The dimension of the map.

	using Vertex = Cell<Orbit::BETA1>;     ///< A vertex of a polygon: its two darts, exchanged by beta1.
	using Edge = Cell<Orbit::BETA0>;       ///< An edge: its two darts, exchanged by beta0.
	using Face = Cell<Orbit::BETA0_BETA1>; ///< A polygon: the darts reached by beta0 and beta1.

	GMap1() : CMapBase("__beta1")
	{
		use_key_as_beta1();
	}
};

} // namespace cgogn
