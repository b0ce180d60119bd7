// SPDX-License-Identifier: MIT
// The tetrahedral-octahedral refinement of the finest map of a
// multiresolution 3-map.
#include "mrmap3_tetra_octa.h"

#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/traversals/local_cmap3.h>

#include <algorithm>
#include <stdexcept>

namespace cgogn::detail
{

namespace
{

/// The corners of the regular shapes the cuts follow, scaled so that every
/// edge midpoint has integer coordinates: a regular tetrahedron, and the
/// octahedron of corners +-2 e_i (corner i + 3 is opposite to corner i).
using Point = std::array<int, 3>;
constexpr std::array<Point, 4> tetra_points{{{2, 2, 2}, {2, -2, -2}, {-2, 2, -2}, {-2, -2, 2}}};
constexpr std::array<Point, 6> octa_points{{{2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {-2, 0, 0}, {0, -2, 0}, {0, 0, -2}}};
constexpr Point centre{0, 0, 0};

/// The points x with normal . x = offset.
struct Plane
{
	Point normal;
	int offset;
};
/// A tetrahedron: the plane through the midpoints of the edges at each
/// corner cuts the corner off. An octahedron: the 4 planes through its
/// centre parallel to two opposite faces; each holds a hexagon of edge
/// midpoints, and together they cut the 6 corner octahedra and 8 face
/// tetrahedra apart.
constexpr std::array<Plane, 4> tetra_planes{{{{1, 1, 1}, 2}, {{1, -1, -1}, 2}, {{-1, 1, -1}, 2}, {{-1, -1, 1}, 2}}};
constexpr std::array<Plane, 4> octa_planes{{{{1, 1, 1}, 0}, {{1, -1, -1}, 0}, {{-1, 1, -1}, 0}, {{-1, -1, 1}, 0}}};

/// A point's code (0 ... 124; its coordinates are in [-2, 2]) and back.
constexpr uint8 unknown_point = 255;
uint8 encode(const Point& p)
{
	return uint8((p[0] + 2) * 25 + (p[1] + 2) * 5 + (p[2] + 2));
}
Point decode(uint8 c)
{
	return {c / 25 - 2, c / 5 % 5 - 2, c % 5 - 2};
}

/// Cuts one cell along the planes of its shape, one piece at a time. Every
/// dart of the pieces knows the point of the shape its origin is.
class PlaneSplit
{
public:
	PlaneSplit(MRVolumeRefinement& r, MRTetraOctaScratch& scratch) : r_(r), map_(r.map()), s_(scratch)
	{
	}

	/// Gives point p to the darts leaving the origin of d in d's volume
	/// (nothing to do when d has it: a corner is met from each of its darts).
	void name_vertex(Dart d, const Point& p)
	{
		if (at_or_unknown(d) == encode(p))
			return;
		Dart x = d;
		do
		{
			set(x, p);
			x = phi2(map_, phi_1(map_, x));
		} while (x != d);
	}

	/// Cuts the pieces, starting from the whole cell of dart d, along each
	/// plane in turn.
	template <std::size_t N>
	void run(Dart d, const std::array<Plane, N>& planes)
	{
		s_.pieces.assign(1, d);
		for (const Plane& p : planes)
			for (std::size_t i = 0, end = s_.pieces.size(); i < end; ++i)
				cut(i, p);
	}

private:
	uint8 at_or_unknown(Dart d) const
	{
		return d.index < s_.point.size() ? s_.point[d.index] : unknown_point;
	}
	Point at(Dart d) const
	{
		return decode(s_.point[d.index]);
	}
	void set(Dart d, const Point& p)
	{
		if (d.index >= s_.point.size())
			s_.point.resize(std::max<std::size_t>(d.index + 1, 2 * s_.point.size()), unknown_point);
		s_.point[d.index] = encode(p);
	}
	int value(const Plane& p, Dart d) const
	{
		const Point q = at(d);
		return p.normal[0] * q[0] + p.normal[1] * q[1] + p.normal[2] * q[2] - p.offset;
	}
	/// The side of p on which the face of d lies, d's edge being in p.
	int side(const Plane& p, Dart d) const
	{
		for (Dart x = phi1(map_, phi1(map_, d)); x != d; x = phi1(map_, x))
			if (const int v = value(p, x); v != 0)
				return v;
		return 0;
	}

	/// A new edge from origin(d) to origin(e) in their face (see
	/// MRVolumeRefinement::cut_face), its darts named.
	Dart cut_face(Dart d, Dart e)
	{
		const Point from = at(d), to = at(e);
		const Dart y = r_.cut_face(d, e, 0);
		const Dart y3 = phi3(map_, y);
		set(y, from);
		set(phi2(map_, y), to);
		set(y3, to);
		set(phi2(map_, y3), from);
		return y;
	}

	/// The darts of the face of d in phi1 order, from d, in s_.polygon.
	void read_polygon(Dart d)
	{
		s_.polygon.clear();
		Dart it = d;
		do
		{
			s_.polygon.push_back(it);
			it = phi1(map_, it);
		} while (it != d);
	}

	/// Cuts the polygon of `from_centre` (a dart leaving the centre) into
	/// triangles around the centre.
	void fan(Dart from_centre)
	{
		read_polygon(from_centre);
		Dart y = from_centre;
		for (std::size_t i = 2; i + 1 < s_.polygon.size(); ++i)
			y = cut_face(y, s_.polygon[i]);
	}

	/// Cuts new face f into triangles around the cell's centre, which is
	/// made (in the middle of the chord between two opposite corners of f)
	/// when f is the first section through it.
	void triangulate_section(Dart f)
	{
		read_polygon(f);
		for (Dart x : s_.polygon)
			if (at(x) == centre)
				return fan(x);
		const Dart chord = cut_face(s_.polygon[0], s_.polygon[s_.polygon.size() / 2]);
		// the darts of the chord, each followed by the new centre's dart
		const std::array<Dart, 4> ring{chord, phi2(map_, chord), phi3(map_, chord), phi2(map_, phi3(map_, chord))};
		r_.cut_edge(chord);
		for (Dart x : ring)
			set(phi1(map_, x), centre);
		const Dart from_centre = phi1(map_, chord);
		fan(from_centre);
		fan(phi1(map_, phi2(map_, from_centre)));
	}

	/// Cuts piece i along p when p has corners of it on both sides: the
	/// section's edges on the piece's surface, each taken in its face on the
	/// positive side, make the path.
	void cut(std::size_t i, const Plane& p)
	{
		std::vector<Dart>& on = s_.on_plane;
		on.clear();
		bool positive = false, negative = false;
		foreach_dart_of_orbit(map_, CMap3::Volume(s_.pieces[i]), [&](Dart x) {
			const int v = value(p, x);
			positive = positive || v > 0;
			negative = negative || v < 0;
			if (v == 0 && value(p, phi1(map_, x)) == 0 && side(p, x) > 0)
				on.push_back(x);
		});
		if (!positive || !negative)
			return;
		std::vector<Dart>& path = s_.path;
		path.assign(1, on.front());
		while (path.size() < on.size())
		{
			const Point end = at(phi1(map_, path.back()));
			const auto next = std::find_if(on.begin(), on.end(), [&](Dart x) { return at(x) == end; });
			if (next == on.end())
				throw std::logic_error("tetrahedral-octahedral refinement: a section of a volume is not a polygon");
			path.push_back(*next);
		}
		const Dart f = r_.cut_volume_along(path);
		for (Dart x : path)
		{
			const Dart y = phi2(map_, x);
			set(y, at(phi1(map_, x)));
			set(phi3(map_, y), at(x));
		}
		s_.pieces[i] = path.front();
		s_.pieces.push_back(phi3(map_, f));
		if (path.size() > 3)
			triangulate_section(f);
	}

	MRVolumeRefinement& r_;
	CMap3& map_;
	MRTetraOctaScratch& s_;
};

} // namespace

std::optional<MRTetraOctaCell> mr_read_tetra_octa(const CMap3& map, Dart w)
{
	std::array<Dart, 25> darts;
	uint32 nb = 0;
	foreach_dart_of_orbit(map, CMap3::Volume(w), [&](Dart x) {
		darts[nb++] = x;
		return nb < darts.size();
	});
	if (nb != 12 && nb != 24)
		return std::nullopt;
	for (uint32 i = 0; i < nb; ++i)
		if (phi1(map, phi1(map, phi1(map, darts[i]))) != darts[i])
			return std::nullopt;
	MRTetraOctaCell c;
	c.octahedron = nb == 24;
	c.nb_darts = nb;
	const uint32 degree = c.octahedron ? 4 : 3;
	// the corner number of each dart (position i in darts)
	constexpr uint8 none = 255;
	std::array<uint8, 24> corner;
	corner.fill(none);
	const auto position = [&](Dart x) {
		return uint32(std::find(darts.begin(), darts.begin() + nb, x) - darts.begin());
	};
	// numbers the corner of d; false when it has another number already or
	// has not `degree` edges
	const auto number = [&](Dart d, uint8 n) {
		Dart x = d;
		uint32 edges = 0;
		do
		{
			uint8& at = corner[position(x)];
			if ((at != none && at != n) || ++edges > degree)
				return false;
			at = n;
			x = phi2(map, phi_1(map, x));
		} while (x != d);
		return edges == degree;
	};
	// a tetrahedron: w's face, then the corner across w's edge; an
	// octahedron: w's face, then the corners across its 3 edges, each
	// opposite to the corner of the face that is not on that edge
	const Dart a = w, b = phi1(map, w), c3 = phi_1(map, w);
	const auto across = [&](Dart d) { return phi_1(map, phi2(map, d)); };
	bool ok = number(a, 0) && number(b, 1) && number(c3, 2);
	if (c.octahedron)
		ok = ok && number(across(b), 3) && number(across(c3), 4) && number(across(a), 5);
	else
		ok = ok && number(across(a), 3);
	if (!ok || std::find(corner.begin(), corner.begin() + nb, none) != corner.begin() + nb)
		return std::nullopt;
	// the corners of a face are distinct; an octahedron's face has one
	// corner on each axis
	const uint8 axes = c.octahedron ? 3 : 4;
	for (uint32 i = 0; i < nb; ++i)
	{
		const Dart x = darts[i];
		const uint8 u = corner[i], v = corner[position(phi1(map, x))], t = corner[position(phi_1(map, x))];
		if (u % axes == v % axes || v % axes == t % axes || t % axes == u % axes)
			return std::nullopt;
		c.darts[i] = {x, {u, v}};
	}
	return c;
}

void mr_split_tetra_octa(MRVolumeRefinement& r, const MRTetraOctaCell& c, MRTetraOctaScratch& scratch)
{
	const CMap3& map = r.map();
	PlaneSplit split(r, scratch);
	for (uint32 i = 0; i < c.nb_darts; ++i)
	{
		const auto& [d, ends] = c.darts[i];
		const Point& u = c.octahedron ? octa_points[ends[0]] : tetra_points[ends[0]];
		const Point& v = c.octahedron ? octa_points[ends[1]] : tetra_points[ends[1]];
		split.name_vertex(d, u);
		split.name_vertex(phi1(map, d), {(u[0] + v[0]) / 2, (u[1] + v[1]) / 2, (u[2] + v[2]) / 2});
	}
	if (c.octahedron)
		split.run(c.darts[0].first, octa_planes);
	else
		split.run(c.darts[0].first, tetra_planes);
}

} // namespace cgogn::detail
