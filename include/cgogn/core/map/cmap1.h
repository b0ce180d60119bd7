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
	static constexpr uint32 dimension = 1;

	using Vertex = Cell<Orbit::DART>;
	using Edge = Cell<Orbit::DART>;
	using Face = Cell<Orbit::PHI1>;
};

} // namespace cgogn
