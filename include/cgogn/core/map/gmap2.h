// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/gmap1.h>

namespace cgogn
{

/// A 2-dimensional generalized map: the polygons of a GMap1 glued along edges
/// by a third involution, beta2, which exchanges the darts of two faces at
/// the same vertex of the same edge. beta0 o beta2 is an involution too (the
/// two faces are glued vertex to vertex). Orientable or not: a Möbius strip,
/// a Klein bottle or a projective plane is a GMap2 (is_orientable tells).
/// As the combinatorial maps, the map is always closed: holes are boundary
/// faces whose darts carry the boundary mark. Twice the darts of a CMap2 of
/// the same surface (one per corner side of each half-edge).
class GMap2 : public GMap1
{
public:
	static constexpr uint32 dimension = 2; ///< The dimension of the map.

	using Vertex = Cell<Orbit::BETA1_BETA2>; ///< A vertex: the darts around it (beta1 and beta2).
	using Edge = Cell<Orbit::BETA0_BETA2>;   ///< An edge: its (up to) four darts, beta0 and beta2.
	using Face = Cell<Orbit::BETA0_BETA1>;   ///< A face: the darts of one polygon.
	/// A connected component: the surface seen as one volume.
	using Volume = Cell<Orbit::BETA0_BETA1_BETA2>;

	GMap2()
	{
		add_beta_relation("__beta2");
	}
};

} // namespace cgogn
