// SPDX-License-Identifier: MIT
// Several steps of a surface subdivision scheme.
#include <cgogn/modeling/subdivision.h>

namespace cgogn::modeling
{

namespace
{
template <typename MAP>
SubdivisionResult iterate(MAP& m, AttributeArray<Vec3>& pos, SurfaceScheme scheme, uint32 iterations,
						  const ProgressCallback& progress)
{
	SubdivisionResult result;
	for (uint32 i = 0; i < iterations; ++i)
	{
		ProgressCallback step_progress;
		if (progress)
			step_progress = [&](double f) { return progress((double(i) + f) / double(iterations)); };
		SubdivisionResult r;
		switch (scheme)
		{
		case SurfaceScheme::Loop:
			r = loop_subdivision(m, pos, step_progress);
			break;
		case SurfaceScheme::CatmullClark:
			r = catmull_clark_subdivision(m, pos, step_progress);
			break;
		case SurfaceScheme::Sqrt3:
			r = sqrt3_subdivision(m, pos, step_progress);
			break;
		}
		result.steps += r.steps;
		if (r.cancelled)
		{
			result.cancelled = true;
			break;
		}
	}
	return result;
}
} // namespace

SubdivisionResult subdivide(CMap2& m, AttributeArray<Vec3>& pos, SurfaceScheme scheme, uint32 iterations,
							const ProgressCallback& progress)
{
	return iterate(m, pos, scheme, iterations, progress);
}

SubdivisionResult subdivide(GMap2& m, AttributeArray<Vec3>& pos, SurfaceScheme scheme, uint32 iterations,
							const ProgressCallback& progress)
{
	return iterate(m, pos, scheme, iterations, progress);
}

} // namespace cgogn::modeling
