// SPDX-License-Identifier: MIT
// From a CMap2 (its faces) or a CMap3 (its boundary faces) to a Scene.
#include "extract.h"

namespace cgogn::render
{

namespace
{

using detail::Extractor;
using detail::Scene;

template <typename MAP, typename PRED>
Image render_map(const MAP& m, const AttributeArray<Vec3>& pos, const RenderOptions& o, const PRED& rendered)
{
	Extractor<MAP> x(m, pos, o);
	Scene s = x.run(rendered);
	add_scalar(m, pos, o, s, x.face_darts(), x.vertex_darts());
	return detail::rasterize(s, o);
}

} // namespace

double triangle_quality(const Vec3& a, const Vec3& b, const Vec3& c)
{
	const double l2 = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
	if (!(l2 > 0.0))
		return 0.0;
	return 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / l2;
}

Image render_surface(const CMap2& m, const AttributeArray<Vec3>& pos, const RenderOptions& options)
{
	return render_map(m, pos, options, [](Dart) { return true; });
}

Image render_volume_boundary(const CMap3& m, const AttributeArray<Vec3>& pos, const RenderOptions& options)
{
	return render_map(m, pos, options, [&](Dart d) { return is_boundary(m, phi3(m, d)); });
}

} // namespace cgogn::render
