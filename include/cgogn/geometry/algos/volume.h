// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/local_gmap3.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/geometry/algos/normal.h>

#include <Eigen/Geometry> // cross()

#include <cmath>
#include <vector>

namespace cgogn::geometry
{

// Volumes by the divergence theorem. Each face, seen from a reference point
// o, is split into the triangles (c, p_i, p_i+1) fanned around its vertex
// centroid c; the signed volumes of the tetrahedra (o, c, p_i, p_i+1) sum to
// (c - o) . N / 6 with N the face's Newell vector. The fan around the centroid
// is the same from both sides of a face, so non-planar faces (e.g. twisted
// hexahedra faces) are closed consistently: the volumes of the cells of a 3-map
// add up to the volume of the solid, and the result does not depend on o.

namespace detail
{
/// The centroid of the vertices of the face cycle of dart d (the centre of
/// the fan the volumes use). O(face degree).
template <GeometricMesh MESH>
Vec3 face_fan_centre(const MESH& m, const AttributeArray<Vec3>& pos, Dart d)
{
	Vec3 c = Vec3::Zero();
	uint32 n = 0;
	Dart it = d;
	do
	{
		c += origin_position(m, pos, it);
		++n;
		it = oriented_phi1(m, it);
	} while (it != d);
	return c / n;
}

/// Signed volume of the cone from o over the face cycle of dart d, in the
/// orientation of d. O(face degree).
template <GeometricMesh MESH>
double face_cone_volume(const MESH& m, const AttributeArray<Vec3>& pos, Dart d, const Vec3& o)
{
	return (face_fan_centre(m, pos, d) - o).dot(newell_vector(m, pos, d)) / 6.0;
}

/// Calls f(d) once per face reached from `start` by oriented_phi1 and beta0
/// o beta2 (a 2-G-map's oriented_phi2): the faces of start's connected
/// component in a 2-G-map (boundary faces too), of start's volume in a
/// 3-G-map. d is the dart of the face oriented consistently with start (in
/// a 2-G-map, the 2-map to_cmap would keep if start were the component's
/// smallest dart). Marks the reached darts in `reached` (a DartMarker or a
/// DartMarkerStore). Returns false, at the first face found in both
/// orientations, when those faces cannot be oriented. O(number of darts
/// reached).
template <typename MAP, typename MARKER, typename FUNC>
requires is_gmap_v<MAP> &&
	(MAP::dimension >= 2) bool foreach_oriented_face(const MAP& m, Dart start, MARKER& reached, const FUNC& f)
{
	std::vector<Dart> work(1, start);
	while (!work.empty())
	{
		const Dart d = work.back();
		work.pop_back();
		if (reached.is_marked(d))
			continue;
		// the darts of a face in one orientation are marked together: the
		// other orientation (that of beta0(d)) reached too means a twist
		if (reached.is_marked(beta0(m, d)))
			return false;
		Dart it = d;
		do
		{
			reached.mark(it);
			it = oriented_phi1(m, it);
		} while (it != d);
		f(d);
		do
		{
			if (const Dart o = beta<2, 0>(m, it); !reached.is_marked(o))
				work.push_back(o);
			it = oriented_phi1(m, it);
		} while (it != d);
	}
	return true;
}
} // namespace detail

/// Signed volume enclosed by a closed surface (all its components), positive
/// when the faces are oriented outwards (counterclockwise seen from outside).
/// The sign needs an orientation: on a 2-G-map each component is oriented as
/// its smallest dart, as by to_cmap (the value is that of to_cmap(m)), and a
/// non-orientable component throws TopologyError. Precondition: no boundary
/// (otherwise the value depends on the position of the mesh). O(number of
/// darts).
template <SurfaceMesh MESH>
double signed_volume(const MESH& m, const AttributeArray<Vec3>& pos)
{
	using Face = typename mesh_traits<MESH>::Face;
	bool first = true;
	Vec3 o = Vec3::Zero();
	double v = 0.0;
	auto add_face = [&](Dart d) {
		if (first)
			o = origin_position(m, pos, d);
		first = false;
		v += detail::face_cone_volume(m, pos, d, o);
	};
	if constexpr (is_gmap_v<MESH>)
	{
		// in dart order, a dart neither reached nor the other orientation of a
		// reached one is the smallest dart of a new component
		DartMarker<MESH> reached(m);
		foreach_dart(m, [&](Dart d) {
			if (reached.is_marked(d) || reached.is_marked(beta0(m, d)))
				return true;
			if (!detail::foreach_oriented_face(m, d, reached, [&](Dart x) {
					if (!is_boundary(m, x))
						add_face(x);
				}))
				throw TopologyError("signed_volume: the G-map is not orientable");
			return true;
		});
	}
	else
		foreach_cell(m, [&](Face f) { add_face(f.dart); });
	return v;
}

/// Signed volume enclosed by one connected component w of a closed surface.
/// On a 2-G-map the component is oriented as w.dart (positive when the face
/// of w.dart, seen from w.dart, is oriented outwards); a non-orientable
/// component throws TopologyError. O(number of darts of w).
template <SurfaceMesh MESH>
double volume(const MESH& m, typename mesh_traits<MESH>::Volume w, const AttributeArray<Vec3>& pos)
{
	using Face = typename mesh_traits<MESH>::Face;
	const Vec3 o = origin_position(m, pos, w.dart);
	double v = 0.0;
	if constexpr (is_gmap_v<MESH>)
	{
		DartMarker<MESH> reached(m);
		if (!detail::foreach_oriented_face(m, w.dart, reached, [&](Dart d) {
				if (!is_boundary(m, d))
					v += detail::face_cone_volume(m, pos, d, o);
			}))
			throw TopologyError("volume: the G-map component is not orientable");
	}
	else
		foreach_incident_face(m, w, [&](Face f) { v += detail::face_cone_volume(m, pos, f.dart, o); });
	return v;
}

/// Volume of volume w of a 3-map (any polyhedron: its faces are fanned around
/// their vertex centroids). Positive for the cells built by build_volume
/// (faces oriented outwards). O(number of darts of w).
inline double volume(const CMap3& m, CMap3::Volume w, const AttributeArray<Vec3>& pos)
{
	const Vec3 o = origin_position(m, pos, w.dart);
	double v = 0.0;
	// the faces are given by darts of w: their phi1 cycles are seen from w
	foreach_incident_face(m, w, [&](CMap3::Face f) { v += detail::face_cone_volume(m, pos, f.dart, o); });
	return v;
}

/// Writes the volume of every volume of a 3-map into the volume attribute
/// `out`. O(number of darts).
inline void compute_volumes(const CMap3& m, const AttributeArray<Vec3>& pos, AttributeArray<double>& out)
{
	foreach_cell(m, [&](CMap3::Volume w) { out[w] = volume(m, w, pos); });
}

/// Volume of the solid made by a 3-map, from its boundary surface alone (the
/// faces between a volume and the outside). Equal to the sum of the volumes of
/// its cells up to rounding. O(number of darts).
inline double solid_volume(const CMap3& m, const AttributeArray<Vec3>& pos)
{
	bool first = true;
	Vec3 o = Vec3::Zero();
	double v = 0.0;
	foreach_cell(m, [&](CMap3::Face f) {
		Dart d = f.dart;
		if (is_boundary(m, d))
			d = phi3(m, d);
		else if (!is_boundary(m, phi3(m, d)))
			return; // inner face
		if (first)
			o = origin_position(m, pos, d);
		first = false;
		v += detail::face_cone_volume(m, pos, d, o);
	});
	return v;
}

/// Volume of volume w of a 3-G-map, unsigned: a G-map gives its cells no
/// orientation, so the faces are oriented as the face of w.dart and the
/// magnitude is returned (the CMap3's value, on a cell that is not
/// inverted). Throws TopologyError when the faces of w cannot be oriented
/// (not a cell built from a polyhedron). O(number of darts of w).
inline double volume(const GMap3& m, GMap3::Volume w, const AttributeArray<Vec3>& pos)
{
	const Vec3 o = origin_position(m, pos, w.dart);
	double v = 0.0;
	DartMarkerStore<GMap3> reached(m);
	if (!detail::foreach_oriented_face(m, w.dart, reached,
									   [&](Dart d) { v += detail::face_cone_volume(m, pos, d, o); }))
		throw TopologyError("volume: the faces of the volume cannot be oriented");
	return std::abs(v);
}

/// Writes the (unsigned) volume of every volume of a 3-G-map into the volume
/// attribute `out`. O(number of darts).
inline void compute_volumes(const GMap3& m, const AttributeArray<Vec3>& pos, AttributeArray<double>& out)
{
	foreach_cell(m, [&](GMap3::Volume w) { out[w] = volume(m, w, pos); });
}

/// Volume of the solid made by a 3-G-map: the sum of the volumes of its
/// cells. A G-map's boundary surface may not be orientable (a solid Klein
/// bottle), so the CMap3's reading of the boundary alone does not apply;
/// on a 3-map without inverted cells the two agree up to rounding. O(number
/// of darts).
inline double solid_volume(const GMap3& m, const AttributeArray<Vec3>& pos)
{
	double v = 0.0;
	foreach_cell(m, [&](GMap3::Volume w) { v += volume(m, w, pos); });
	return v;
}

namespace detail
{
/// Adds to vol and moment the signed volumes and first moments of the
/// tetrahedra (o, c, p_i, p_i+1) over the face of d, in the orientation of
/// d, with c the face's vertex centroid. O(face degree).
template <GeometricMesh MESH>
void add_face_cone_moment(const MESH& m, const AttributeArray<Vec3>& pos, Dart f, const Vec3& o, double& vol,
						  Vec3& moment)
{
	const Vec3 c = face_fan_centre(m, pos, f);
	Dart d = f;
	do
	{
		const Vec3& a = origin_position(m, pos, d);
		const Vec3& b = origin_position(m, pos, oriented_phi1(m, d));
		const double t = (c - o).dot((a - o).cross(b - o)) / 6.0;
		vol += t;
		moment += t * (o + c + a + b) / 4.0;
		d = oriented_phi1(m, d);
	} while (d != f);
}

/// moment / vol, or the vertex centroid of w when its volume is zero.
template <VolumeMesh MESH>
Vec3 centre_of(const MESH& m, typename mesh_traits<MESH>::Volume w, const AttributeArray<Vec3>& pos, double vol,
			   const Vec3& moment)
{
	if (vol != 0.0)
		return moment / vol;
	Vec3 vertex_sum = Vec3::Zero();
	uint32 nb = 0;
	foreach_incident_vertex(m, w, [&](typename mesh_traits<MESH>::Vertex v) {
		vertex_sum += value<Vec3>(m, pos, v);
		++nb;
	});
	return nb > 0 ? Vec3(vertex_sum / nb) : vertex_sum;
}
} // namespace detail

/// Centre of mass of volume w of a 3-map (uniform density), from the same
/// decomposition into tetrahedra as volume(). The vertex centroid when the
/// volume is zero. O(number of darts of w).
inline Vec3 mass_center(const CMap3& m, CMap3::Volume w, const AttributeArray<Vec3>& pos)
{
	const Vec3 o = origin_position(m, pos, w.dart);
	double vol = 0.0;
	Vec3 moment = Vec3::Zero();
	foreach_incident_face(m, w, [&](CMap3::Face f) { detail::add_face_cone_moment(m, pos, f.dart, o, vol, moment); });
	return detail::centre_of(m, w, pos, vol, moment);
}

/// Centre of mass of volume w of a 3-G-map (uniform density), as for a
/// 3-map: the faces oriented as the face of w.dart (the sign of the
/// tetrahedra cancels out). Throws TopologyError when the faces of w cannot
/// be oriented. O(number of darts of w).
inline Vec3 mass_center(const GMap3& m, GMap3::Volume w, const AttributeArray<Vec3>& pos)
{
	const Vec3 o = origin_position(m, pos, w.dart);
	double vol = 0.0;
	Vec3 moment = Vec3::Zero();
	DartMarkerStore<GMap3> reached(m);
	if (!detail::foreach_oriented_face(m, w.dart, reached,
									   [&](Dart f) { detail::add_face_cone_moment(m, pos, f, o, vol, moment); }))
		throw TopologyError("mass_center: the faces of the volume cannot be oriented");
	return detail::centre_of(m, w, pos, vol, moment);
}

} // namespace cgogn::geometry
