// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap1.h>

namespace cgogn
{

/// A 2-dimensional combinatorial map: faces (phi1 cycles) glued along edges by
/// the fixed-point-free involution phi2. The map is always closed: holes are
/// boundary faces whose darts carry the boundary mark.
class CMap2 : public CMap1
{
public:
	static constexpr uint32 dimension = 2; ///< The dimension of the map.

	using HalfEdge = Cell<Orbit::DART>; ///< A dart: the side of an edge in one face.
	using Vertex = Cell<Orbit::PHI21>;  ///< A vertex: the darts leaving it (phi2 followed by phi1).
	using Edge = Cell<Orbit::PHI2>;     ///< An edge: its two darts, exchanged by phi2.
	using Face = Cell<Orbit::PHI1>;     ///< A face: a phi1 cycle of darts.
	/// A connected component: the surface seen as one volume.
	using Volume = Cell<Orbit::PHI1_PHI2>;

	CMap2()
	{
		add_relation("__phi2");
	}
};

} // namespace cgogn
