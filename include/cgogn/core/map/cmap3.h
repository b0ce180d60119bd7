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
	static constexpr uint32 dimension = 3;

	using HalfEdge = Cell<Orbit::DART>;
	using Vertex = Cell<Orbit::PHI21_PHI31>;
	using Edge = Cell<Orbit::PHI2_PHI3>;
	using Face = Cell<Orbit::PHI1_PHI3>;
	using Volume = Cell<Orbit::PHI1_PHI2>;
	using CC = Cell<Orbit::PHI1_PHI2_PHI3>;
	/// The cells of one volume (its own 2-map).
	using Vertex2 = Cell<Orbit::PHI21>;
	using Edge2 = Cell<Orbit::PHI2>;
	using Face2 = Cell<Orbit::PHI1>;

	CMap3()
	{
		phi3_ = add_relation("__phi3");
	}

private:
	friend struct detail::MapMembers;
	AttributeArray<uint32>* phi3_ = nullptr;
};

} // namespace cgogn
