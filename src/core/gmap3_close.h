// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/gmap3.h>

#include <vector>

namespace cgogn::detail
{

/// Closes the beta3 fixed points among `darts` with boundary volumes: each
/// free dart d gets a new boundary dart b = beta3(d) at the same vertex, edge
/// and face; beta0(b) and beta1(b) are the new darts of beta0(d) and
/// beta1(d) (the faces of the boundary mirror the free faces), and beta2(b)
/// the first boundary dart met by turning around the edge of d through the
/// inner volumes (beta2 in a volume, beta3 across a face): the mirror of the
/// next free dart, or a boundary dart that was there before, which is then
/// taken from its former neighbour (unsewing a face at the boundary: that
/// neighbour meets a new dart from the other side of the face). The new darts
/// are appended to `created`; they get the vertex, edge, face and
/// connected-component index of d in the orbits that are indexed.
/// Precondition: free darts come in whole faces (beta0(d) and beta1(d) free
/// with d). O(number of free darts x degree of their edges).
void close_beta3_holes(GMap3& m, const std::vector<Dart>& darts, std::vector<Dart>& created);

} // namespace cgogn::detail
