// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/functions/darts.h>

namespace cgogn::detail
{

/// Takes darts x and y out of their phi1 cycles as if the walk along the faces
/// went through them: a dart followed by x continues after y and conversely
/// (through x again when y is followed by x). This is how the boundary faces
/// of an edge {x, y} merge when the edge goes, and how the boundary faces of
/// two boundary darts x and y merge when their edges are sewn. It holds in
/// every case, a dart alone in its cycle (a face of one edge) and x, y
/// following each other included. x and y are left as fixed points; callers
/// remove them. O(degree of their faces).
inline void unlink_from_faces(CMap1& m, Dart x, Dart y)
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
	const Dart px = phi_1(m, x), py = phi_1(m, y);
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

} // namespace cgogn::detail
