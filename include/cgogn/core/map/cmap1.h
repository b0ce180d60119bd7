// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap_base.h>

namespace cgogn
{

/// A 1-dimensional combinatorial map: darts linked by the permutation phi1
/// into cycles (faces). Vertices and edges are single darts.
class CMap1 : public CMapBase
{
public:
	static constexpr uint32 dimension = 1; ///< The dimension of the map.

	using Vertex = Cell<Orbit::DART>; ///< A vertex: one dart (the vertex at the start of the dart).
	using Edge = Cell<Orbit::DART>;   ///< An edge: one dart (the edge from its vertex to the next).
	using Face = Cell<Orbit::PHI1>;   ///< A face: a phi1 cycle of darts.
};

} // namespace cgogn
