// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/map/graph.h>
#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/map/mrmap2.h>
#include <cgogn/core/map/mrmap3.h>

#include <string>
#include <vector>

namespace cgogn
{

/// One violated invariant found by check_integrity.
struct IntegrityError
{
	/// Which invariant is violated.
	enum class Kind
	{
		DeadRelation,          ///< a relation points to a dart that is not live
		Phi1NotPermutation,    ///< two darts have the same phi1
		PhiNotInvolution,      ///< phi_i(phi_i(d)) != d for i >= 2 (beta_i(beta_i(d)) != d in a G-map)
		PhiFixedPoint,         ///< phi_i(d) == d for i >= 2 (beta_i(d) == d in a G-map): the map is not closed
		Phi1Phi3NotInvolution, ///< phi3 o phi1 is not an involution (3-maps; phi_j o phi_i, i + 2 <= j, in a CMapN)
		BetaCompositionNotInvolution, ///< beta_j o beta_i is not an involution for i + 2 <= j (G-maps)
		BoundaryLinked,               ///< phi_n links two boundary darts
		BoundaryMarkNotConstant,      ///< a boundary cell is only partly marked
		BoundaryCountWrong,           ///< the map's count of boundary darts is not the number of marked darts
		IndexNotConstant,             ///< two darts of one orbit have different indices
		MissingIndex,                 ///< a cell of an indexed orbit has no index
		BoundaryCellIndexed,          ///< a boundary cell has an index
		DeadIndex,                    ///< a dart refers to a free line
		BadRepresentative,            ///< a line's representative dart is not a dart of its cell
		IndexShared,                  ///< two cells use the same line
		FreeLineLive,                 ///< the free list holds a live line
		FreeLineDuplicate,            ///< the free list holds a line twice (it would be handed out twice)
		StaleUnusedLine,              ///< a line never handed out since the last compaction holds an old index
		ShortFace,                    ///< a non-boundary face of a 2- or 3-map has 1 or 2 edges
		IncidenceCacheStale,          ///< a quick incidence cache disagrees with the map (see IncidenceCache)
		InverseRelationWrong,         ///< a stored inverse (a graph's alpha_1) is not the relation's inverse
		EdgelessDartNotAlone,         ///< a graph dart without edge shares its vertex with other darts
		RingBroken,          ///< an incidence graph's ring (edge ends around a vertex, uses around an edge) is broken
		FaceNotSimpleCycle,  ///< an incidence graph's face is not a simple cycle of consecutive sides
		LevelCountWrong,     ///< a multiresolution map's per-level dart count disagrees with its darts' levels
		LevelRelationBroken, ///< phi1, phi_1 or phi2 at a level leaves the level, does not end, or is not inverted
		EdgeIdWrong,         ///< an edge id is above 2, or the two darts of a finest edge have different ids
		FaceIdWrong,         ///< the darts of a finest face of a multiresolution 3-map have different face ids
		LevelLineWrong,      ///< a multiresolution line holds at a level where its cell is not, or refines a wrong line
	};
	Kind kind;                   ///< The violated invariant.
	Orbit orbit = Orbit::DART;   ///< The orbit of the cell or line at fault; DART for errors of the relations.
	uint32 dart = INVALID_INDEX; ///< The index of a dart at fault; INVALID_INDEX when none is singled out.
	/// The line at fault in the container of `orbit` (for a stale incidence
	/// cache, its row); INVALID_INDEX when none is singled out.
	uint32 index = INVALID_INDEX;
	std::string message; ///< The description, with the dart and line when known.
};

/// The result of check_integrity: every violated invariant (the first 1000
/// are described; `nb_errors` counts them all).
struct IntegrityReport
{
	std::vector<IntegrityError> errors; ///< The first 1000 errors found.
	std::size_t nb_errors = 0;          ///< The number of errors found, described or not.

	/// True when no invariant is violated.
	bool ok() const
	{
		return nb_errors == 0;
	}
	/// Whether one of the described errors (the first 1000) is of kind k.
	/// O(number of described errors).
	bool has(IntegrityError::Kind k) const
	{
		for (const auto& e : errors)
			if (e.kind == k)
				return true;
		return false;
	}
	/// All messages, one per line.
	std::string to_string() const;
};

/// Checks every invariant of the map: relations are permutations/fixed-point-
/// free involutions between live darts (and phi3 o phi1 is an involution in
/// 3-maps), no phi_n between two boundary darts, the boundary mark is constant
/// on each boundary cell, and for every indexed orbit: all darts of a cell
/// share one live index, boundary cells have none, no line is shared by two
/// cells, every live line's representative dart belongs to its cell, the free
/// lists hold only free lines, each once; the lines allocated past the last
/// one in use hold no relation, key or index (what new_line hands out is
/// clean); in 2- and 3-maps no non-boundary face has fewer than 3 edges;
/// every quick incidence cache present (IncidenceCache) matches the relation
/// recomputed from the darts. O(number of darts x number of indexed orbits +
/// size of the cached relations + number of lines). On a map of 65,536 darts
/// or more, the relations and the indexing are first checked yes or no on
/// the thread pool's workers (set_nb_workers), and the detailed checks, which
/// say what is wrong, run sequentially only where those fail: a 1M-triangle
/// map is checked in 16 ms on 2 cores instead of 28. Called from inside a
/// parallel traversal, it runs on the calling thread.
IntegrityReport check_integrity(const CMap1& m);
IntegrityReport check_integrity(const CMap2& m);
IntegrityReport check_integrity(const CMap3& m);
/// The same checks for a G-map, where the relations are the involutions
/// beta_i: each a fixed-point-free involution between live darts, beta_j o
/// beta_i an involution for i + 2 <= j, no beta_n between two boundary
/// darts, and faces of at least 3 edges (6 darts) unless boundary.
IntegrityReport check_integrity(const GMap1& m);
IntegrityReport check_integrity(const GMap2& m);
/// The same for a 3-G-map, with beta3 o beta0 and beta3 o beta1 involutions and boundary volumes.
IntegrityReport check_integrity(const GMap3& m);
/// The same checks for a map of any dimension D (CMapN, GMapN): phi1 a
/// permutation, phi_i (i >= 2) and beta_i (i >= 1) fixed-point-free
/// involutions between live darts, the darts of a G-map in pairs, phi1 o
/// phi_j (j >= 3), phi_i o phi_j and beta_i o beta_j (i + 2 <= j)
/// involutions, the boundary mark constant on D-cells and never on both
/// sides of the last relation, and the indexing of every indexed CellD<i>
/// orbit. No rule on the number of edges of a face (a contraction may make
/// a digon). O(D^2 x number of darts x number of indexed orbits + lines).
template <typename MAP>
requires is_nmap_v<MAP> IntegrityReport check_integrity(const MAP& m);
/// The invariants of an incidence graph: each edge joins two different live
/// vertices and its two ends are each in the ring of their vertex, every
/// ring holds exactly the ends of its vertex once; every use (dart) is on a
/// live edge and in that edge's radial ring, once; phi1 is a permutation of
/// the uses whose cycles (the faces) are simple cycles of at least 3 sides,
/// each side starting where the previous one ends; and the face indexing
/// when faces are indexed. O(number of uses + edges + vertices + lines).
IntegrityReport check_integrity(const IncidenceGraph& ig);
/// The invariants of a multiresolution 2-map at every level: those of its
/// finest map (check_integrity(finest_map(m))); the per-level dart counts
/// equal the number of live darts of each level, and no dart is above the
/// finest level; edge ids are 0, 1 or 2, the same on both darts of a finest
/// edge; and at each level l, phi1 is a permutation of the darts of level
/// <= l whose walks end (a broken label would make them loop) and phi_1 is
/// its inverse, phi2 a fixed-point-free involution of those darts that
/// never links two boundary darts, the boundary mark is constant on each
/// face, and non-boundary faces have at least 3 edges. For every indexed
/// orbit: each line refines a live line of a lower level; at each level,
/// every real cell has one live line holding at that level, read the same
/// from all its darts, whose representative is one of them, no two cells
/// share a line, as many lines hold as there are cells, and boundary faces
/// have none. O(number of darts x levels x cost of a level step).
IntegrityReport check_integrity(const MRMap2& m);
/// The same checks for the level read by a view only (with the labels and
/// counts of the whole map). O(number of darts x cost of a level step).
IntegrityReport check_integrity(const MRLevelView2& v);

/// Checks a multiresolution 3-map: the finest map (check_integrity of a
/// CMap3), the labels (the per-level dart counts, one edge id per finest
/// edge, one face id per finest face) and, at every level l, the relations
/// of the darts of level <= l: phi1 is a permutation of them (phi_1 its
/// inverse), phi2 and phi3 are fixed-point-free involutions, phi3 o phi1 is
/// an involution, boundary marks are constant on the volumes and phi3 never
/// joins two boundary darts. A walk that does not end (broken labels) is
/// reported, not followed forever. For every indexed orbit, at every level:
/// every cell reads one live line that holds at that level from all its
/// darts, whose representative is one of them, no two cells share a line,
/// and as many lines hold as there are cells. O(number of darts x levels x
/// cost of a level step).
IntegrityReport check_integrity(const MRMap3& m);
/// The same checks for the level read by a view only (with the labels and
/// counts of the whole map). O(number of darts x cost of a level step).
IntegrityReport check_integrity(const MRLevelView3& v);

} // namespace cgogn
