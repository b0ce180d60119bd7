// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>

#include <array>
#include <unordered_map>
#include <vector>

namespace cgogn::detail
{

/// A set of volumes of a 3-map to be replaced by tetrahedra given by vertex
/// labels: the re-tetrahedralization behind split_tetra, the flips and edge
/// collapse. Labels name the vertex orbits touching the cavity (label(d)),
/// new vertices (new_vertex()) and may be merged (merge_vertices). fill()
/// removes the volumes and builds the tetrahedra: orientation is taken from
/// the cavity's boundary faces, faces are sewn by their labels.
class Cavity
{
public:
	Cavity(CMap3& m, const std::vector<Dart>& volumes);

	uint32 label(Dart d) const;
	uint32 new_vertex();
	/// Label `gone` now names the same vertex as `keep` (keep's line survives).
	void merge_vertices(uint32 keep, uint32 gone);
	/// The labels of the corners of tetrahedron w (one of the cavity's volumes)
	/// as (p, q, r, s) with s on the side of the normal of (p, q, r).
	std::array<uint32, 4> tetra_labels(Dart w) const;

	/// Replaces the cavity's volumes by `tets`. Returns one dart per new tet.
	/// Precondition (asserted): the faces of the new tets that are not shared
	/// by two of them are exactly the cavity's boundary faces.
	std::vector<Dart> fill(std::vector<std::array<uint32, 4>> tets, bool set_indices);

	/// After fill: a live dart of the vertex of label l (invalid if none).
	Dart vertex_dart(uint32 l) const;
	/// After fill: a new dart going from vertex `from` to vertex `to`.
	Dart dart_between(uint32 from, uint32 to) const;

private:
	uint32 find(uint32 l) const;

	CMap3& m_;
	std::vector<Dart> darts_;                      // darts of the cavity's volumes
	std::unordered_map<uint32, uint32> labels_;    // dart index -> vertex label
	std::vector<uint32> alias_;                    // label -> merged label
	std::vector<uint32> line_;                     // label -> vertex line (or INVALID)
	std::vector<std::pair<Dart, uint32>> created_; // new darts with the label of their origin
};

} // namespace cgogn::detail
