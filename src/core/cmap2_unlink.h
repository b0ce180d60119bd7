// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/darts.h>

namespace cgogn::detail
{

/// Takes darts x and y out of their phi1 cycles as if the walk along the faces
/// went through them: a dart followed by x continues after y and conversely
/// (through x again when y is followed by x). This is how the boundary faces
/// of an edge {x, y} merge when the edge goes, and how the boundary faces of
/// two boundary darts x and y merge when their edges are sewn. It holds in
/// every case, a dart alone in its cycle (a face of one edge) and x, y
/// following each other included. x and y are left as fixed points; callers
/// remove them. px and py are the darts before x and y in their cycles.
/// O(1) beyond those.
inline void unlink_from_faces(CMap1& m, Dart x, Dart y, Dart px, Dart py)
{
	const auto other = [&](Dart d) { return d == x ? y : x; };
	const auto next_outside = [&](Dart from) {
		Dart n = phi1(m, from);
		// at most one pass through each of x and y: the walk leaves them unless
		// they form their cycles alone, in which case no other dart reaches them
		for (int i = 0; i < 3 && (n == x || n == y); ++i)
			n = phi1(m, other(n));
		return n;
	};
	const bool relink_px = px != x && px != y;
	const bool relink_py = py != x && py != y;
	const Dart nx = relink_px ? next_outside(px) : Dart();
	const Dart ny = relink_py ? next_outside(py) : Dart();
	if (relink_px)
		set_phi1(m, px, nx);
	if (relink_py)
		set_phi1(m, py, ny);
	set_phi1(m, x, x);
	set_phi1(m, y, y);
}

/// The same, finding the darts before x and y by walking their faces. O(degree
/// of their faces); callers whose map is consistent can pass phi_1 of a 2-map
/// instead, which does not walk a boundary face.
inline void unlink_from_faces(CMap1& m, Dart x, Dart y)
{
	unlink_from_faces(m, x, y, phi_1(m, x), phi_1(m, y));
}

} // namespace cgogn::detail
