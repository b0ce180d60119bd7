// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap2.h>

namespace cgogn
{

/// A 3-dimensional combinatorial map: volumes (closed 2-maps) glued along faces
/// by the involution phi3. Always closed: the outside is made of boundary
/// volumes whose darts carry the boundary mark.
class CMap3 : public CMap2
{
public:
	static constexpr uint32 dimension = 3; ///< The dimension of the map.

	using HalfEdge = Cell<Orbit::DART>;      ///< A dart: the side of an edge in one face of one volume.
	using Vertex = Cell<Orbit::PHI21_PHI31>; ///< A vertex: the darts leaving it in all the volumes around it.
	using Edge = Cell<Orbit::PHI2_PHI3>;     ///< An edge: its darts in all the faces and volumes around it.
	using Face = Cell<Orbit::PHI1_PHI3>;     ///< A face: both of its sides, exchanged by phi3.
	using Volume = Cell<Orbit::PHI1_PHI2>;   ///< A volume: a closed 2-map glued to its neighbours by phi3.
	using CC = Cell<Orbit::PHI1_PHI2_PHI3>;  ///< A connected component of the volume mesh.
	// The cells of one volume (those of its own 2-map):
	using Vertex2 = Cell<Orbit::PHI21>; ///< A vertex of one volume.
	using Edge2 = Cell<Orbit::PHI2>;    ///< An edge of one volume.
	using Face2 = Cell<Orbit::PHI1>;    ///< A face of one volume: one side of a face.

	CMap3()
	{
		add_relation("__phi3");
	}
};

} // namespace cgogn
