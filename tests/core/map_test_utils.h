// SPDX-License-Identifier: MIT
// Shared by the operator tests:
#pragma once

#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace cgogn::test
{

/// Every cell of type CELL, in traversal order.
template <typename CELL, typename MAP>
std::vector<CELL> all(const MAP& m)
{
	std::vector<CELL> v;
	foreach_cell(m, [&](CELL c) { v.push_back(c); });
	return v;
}

/// The first cell of type CELL satisfying pred (invalid when none does).
template <typename CELL, typename MAP, typename P>
CELL find(const MAP& m, P pred)
{
	CELL r;
	foreach_cell(m, [&](CELL c) {
		if (!pred(c))
			return true;
		r = c;
		return false;
	});
	return r;
}

/// Swaps the phi3 partners of the inner dart d of a 3-map and of phi1(d):
/// phi3 stays a fixed-point-free involution, but phi3 o phi1 no longer is
/// (the faces do not match across phi3), which check_integrity must see.
inline void cross_phi3_inside_face(CMap3& m, Dart d)
{
	const Dart e = phi1(m, d);
	const Dart d3 = phi3(m, d), e3 = phi3(m, e);
	phi3_unsew(m, d);
	phi3_unsew(m, e);
	phi3_sew(m, d, e3);
	phi3_sew(m, e, d3);
}

/// Indexes every orbit of m (an attribute per orbit), so that the operators'
/// index maintenance is exercised on all of them.
inline void index_everything(CMap2& m)
{
	add_attribute<uint32, CMap2::Vertex>(m, "vtag");
	add_attribute<uint32, CMap2::Edge>(m, "etag");
	add_attribute<uint32, CMap2::Face>(m, "ftag");
	add_attribute<uint32, CMap2::Volume>(m, "wtag");
}
inline void index_everything(CMap3& m)
{
	add_attribute<uint32, CMap3::Vertex>(m, "vtag");
	add_attribute<uint32, CMap3::Edge>(m, "etag");
	add_attribute<uint32, CMap3::Face>(m, "ftag");
	add_attribute<uint32, CMap3::Volume>(m, "wtag");
	add_attribute<uint32, CMap3::Face2>(m, "f2tag");
	add_attribute<uint32, CMap3::Edge2>(m, "e2tag");
	add_attribute<uint32, CMap3::Vertex2>(m, "v2tag");
	add_attribute<uint32, CMap3::CC>(m, "cctag");
}

/// The map built from a soup, with every orbit indexed.
inline CMap2 indexed(const SurfaceSoup& s)
{
	CMap2 m;
	build_surface(m, s);
	index_everything(m);
	return m;
}
inline CMap3 indexed(const VolumeSoup& s)
{
	CMap3 m;
	build_volume(m, s);
	index_everything(m);
	return m;
}

/// Numbers of vertices, edges, faces and volumes of a map (for a 2-map, w
/// counts its connected components), compared in one assertion.
struct Counts
{
	uint32 v = 0, e = 0, f = 0, w = 0;
	uint32 dimension = 0; ///< of the map counted (not compared)

	bool operator==(const Counts& o) const
	{
		return v == o.v && e == o.e && f == o.f && w == o.w;
	}
	/// v - e + f on a 2-map, v - e + f - w on a 3-map.
	int64 euler() const
	{
		return int64(v) - int64(e) + int64(f) - (dimension == 3 ? int64(w) : 0);
	}
};
inline std::ostream& operator<<(std::ostream& o, const Counts& c)
{
	return o << "{" << c.v << ", " << c.e << ", " << c.f << ", " << c.w << "}";
}
template <typename MAP>
Counts counts(const MAP& m)
{
	return {nb_cells<typename MAP::Vertex>(m), nb_cells<typename MAP::Edge>(m), nb_cells<typename MAP::Face>(m),
			nb_cells<typename MAP::Volume>(m), MAP::dimension};
}

} // namespace cgogn::test

/// check_integrity(m) is clean, or the test fails with the report.
#define EXPECT_INTEGRITY(m)                                                                                            \
	do                                                                                                                 \
	{                                                                                                                  \
		const ::cgogn::IntegrityReport r_ = ::cgogn::check_integrity(m);                                               \
		EXPECT_TRUE(r_.ok()) << r_.to_string();                                                                        \
	} while (0)

/// check_integrity(m) is clean, or the test stops with the report.
#define ASSERT_INTEGRITY(m)                                                                                            \
	do                                                                                                                 \
	{                                                                                                                  \
		const ::cgogn::IntegrityReport r_ = ::cgogn::check_integrity(m);                                               \
		ASSERT_TRUE(r_.ok()) << r_.to_string();                                                                        \
	} while (0)
