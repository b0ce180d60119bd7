// SPDX-License-Identifier: MIT
// What the multiresolution maps of every dimension share: the refinement
// patterns and the step budgets of their level walks.
#pragma once

#include <cgogn/core/utils/numeric.h>

namespace cgogn
{

/// The subdivision pattern of a new level (add_level) or of one cell
/// (subdivide_face).
enum class Refinement
{
	Triangular,   ///< 2-D: every triangle into 4 triangles (edge midpoints joined).
	Quadrangular, ///< 2-D: every k-gon into k quads (edge midpoints joined to a face centre).
	Mixed,        ///< 2-D: triangles as Triangular, the other faces as Quadrangular.
	Hexahedral,   ///< 3-D: every hexahedron into 8 (edge midpoints, face and volume centres).
	TetraOcta,    ///< 3-D: a tetrahedron into 4 tetrahedra and an octahedron, an octahedron into 6 and 8.
};

namespace detail
{

/// What the code shared by the multiresolution maps of every dimension needs
/// to know of the map of state S (specialized beside each state).
template <typename S>
struct MRDim;

/// The step budget of the level walks: unlimited (the relations' own use,
/// checked away by the compiler), or a count that check_integrity gives so
/// that broken labels end a walk instead of looping (see MRStepLimit).
struct MRNoStepLimit
{
	static constexpr bool spend()
	{
		return true;
	}
};
/// A budget of n steps: spend() is false once they are used.
struct MRStepLimit
{
	uint32 left;
	bool spend()
	{
		return left-- > 0;
	}
};

} // namespace detail

} // namespace cgogn
