// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/gmap2.h>

namespace cgogn
{

/// A 3-dimensional generalized map: closed 2-G-maps (the volumes) glued
/// along faces by a fourth involution, beta3, which exchanges the darts of
/// two volumes at the same vertex, edge and face. beta0 o beta3 and
/// beta1 o beta3 are involutions too (faces are glued vertex to vertex and
/// edge to edge). As the 3-maps, the map is always closed: the outside is
/// made of boundary volumes whose darts carry the boundary mark. Twice the
/// darts of a CMap3 of the same mesh.
class GMap3 : public GMap2
{
public:
	static constexpr uint32 dimension = 3; ///< The dimension of the map.

	/// A vertex: its corners in every volume around it (beta1, beta2, beta3).
	using Vertex = Cell<Orbit::BETA1_BETA2_BETA3>;
	/// An edge: its darts in every face and volume around it (beta0, beta2, beta3).
	using Edge = Cell<Orbit::BETA0_BETA2_BETA3>;
	/// A face: both of its sides, exchanged by beta3 (beta0, beta1, beta3).
	using Face = Cell<Orbit::BETA0_BETA1_BETA3>;
	/// A volume: a closed 2-G-map (beta0, beta1, beta2).
	using Volume = Cell<Orbit::BETA0_BETA1_BETA2>;
	/// A connected component of the volume mesh.
	using CC = Cell<Orbit::BETA0_BETA1_BETA2_BETA3>;
	using Vertex2 = Cell<Orbit::BETA1_BETA2>; ///< A vertex of one volume.
	using Edge2 = Cell<Orbit::BETA0_BETA2>;   ///< An edge of one volume.
	using Face2 = Cell<Orbit::BETA0_BETA1>;   ///< A face of one volume: one side of a face.

	GMap3()
	{
		add_beta_relation("__beta3");
	}
};

} // namespace cgogn
