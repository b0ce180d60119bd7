// SPDX-License-Identifier: MIT
// A distributed map's local mesh as a DMPlex. Each rank builds the plex of
// its cells and their vertices (depth 1), with the corners of each cell
// listed from a vertex chosen by global id, and lets PETSc add the faces and
// edges. It then turns each edge and face so that its vertices come in an
// order chosen by global id, so that the copies of a shared point have the
// same cone on every rank, and sets the star forest: each ghost point is a
// leaf of its cell's owner.
#include <cgogn/core.h>
#include <cgogn/distributed/dmplex.h>
#include <cgogn/distributed/exchange.h>
#include <cgogn/geometry/types/vector_traits.h>

#include "collective_failure.h"

#include <algorithm>
#include <array>
#include <limits>
#include <petscsf.h>
#include <unordered_map>

namespace cgogn::dist
{

PlexMesh::PlexMesh(PlexMesh&& other) noexcept : dm_(other.dm_), points_(std::move(other.points_))
{
	other.dm_ = nullptr;
}

PlexMesh& PlexMesh::operator=(PlexMesh&& other) noexcept
{
	if (this != &other)
	{
		if (dm_)
			DMDestroy(&dm_);
		dm_ = other.dm_;
		other.dm_ = nullptr;
		points_ = std::move(other.points_);
	}
	return *this;
}

PlexMesh::~PlexMesh()
{
	if (dm_)
		DMDestroy(&dm_);
}

DM PlexMesh::release()
{
	DM d = dm_;
	dm_ = nullptr;
	return d;
}

namespace
{

/// Throws DMPlexError naming the call when a PETSc call failed.
void check(PetscErrorCode code, const char* call)
{
	if (code == 0)
		return;
	const char* text = nullptr;
	PetscErrorMessage(code, &text, nullptr);
	throw DMPlexError(std::string("to_dmplex: ") + call + " failed: " + (text ? text : "unknown PETSc error"));
}

/// While alive, PETSc returns its errors without printing them.
struct QuietPetsc
{
	QuietPetsc()
	{
		PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
	}
	~QuietPetsc()
	{
		PetscPopErrorHandler();
	}
	QuietPetsc(const QuietPetsc&) = delete;
	QuietPetsc& operator=(const QuietPetsc&) = delete;
};

/// Destroys a DM unless released (the DM under construction).
struct DMGuard
{
	DM dm = nullptr;
	~DMGuard()
	{
		if (dm)
			DMDestroy(&dm);
	}
};

/// Appends to `corners` the corners of volume w, by vertex line, in
/// DMPlex's order; false (nothing appended) when w is not a tetrahedron,
/// pyramid, triangular prism or hexahedron. DMPlex lists first a face of the cell counterclockwise seen
/// from outside, as a face's darts turn, then the apex, or the corners above
/// the face's corners 0, 2, 1 (prism) or 0, 3, 2, 1 (hexahedron). The corner
/// above a face's dart d ends the edge that follows d's twin. The first
/// corner is chosen by global vertex ids, so that every rank holding the
/// volume lists its corners (and DMPlex its faces) in the same order.
bool append_plex_corners(const CMap3& m, CMap3::Volume w, const AttributeArray<uint64>& vertex_gids,
						 std::vector<uint32>& corners)
{
	uint32 nb_darts = 0, triangle_darts = 0, quad_darts = 0;
	auto key = [&](Dart d) {
		return std::pair(vertex_gids[index_of(m, CMap3::Vertex(d))],
						 vertex_gids[index_of(m, CMap3::Vertex(phi1(m, d)))]);
	};
	Dart triangle, quad;
	foreach_dart_of_orbit(m, w, [&](Dart d) {
		++nb_darts;
		uint32 degree = 1;
		for (Dart x = phi1(m, d); x != d && degree <= 4; x = phi1(m, x))
			++degree;
		if (degree == 3 && (triangle_darts++ == 0 || key(d) < key(triangle)))
			triangle = d;
		else if (degree == 4 && (quad_darts++ == 0 || key(d) < key(quad)))
			quad = d;
		return true;
	});
	auto line = [&](Dart d) { return index_of(m, CMap3::Vertex(d)); };
	auto above = [&](Dart d) { return line(phi1(m, phi1(m, phi2(m, d)))); };
	std::array<uint32, 8> c{};
	uint32 n = 0;
	if (triangle_darts == 12 && nb_darts == 12) // tetrahedron
		c = {line(triangle), line(phi1(m, triangle)), line(phi_1(m, triangle)), line(phi_1(m, phi2(m, triangle)))},
		n = 4;
	else if (triangle_darts == 12 && quad_darts == 4 && nb_darts == 16) // pyramid
	{
		const Dart q1 = phi1(m, quad), q2 = phi1(m, q1), q3 = phi1(m, q2);
		c = {line(quad), line(q1), line(q2), line(q3), line(phi_1(m, phi2(m, quad)))}, n = 5;
	}
	else if (triangle_darts == 6 && quad_darts == 12 && nb_darts == 18) // triangular prism
	{
		const Dart t1 = phi1(m, triangle), t2 = phi1(m, t1);
		c = {line(triangle), line(t1), line(t2), above(triangle), above(t2), above(t1)}, n = 6;
	}
	else if (quad_darts == 24 && nb_darts == 24) // hexahedron
	{
		const Dart q1 = phi1(m, quad), q2 = phi1(m, q1), q3 = phi1(m, q2);
		c = {line(quad), line(q1), line(q2), line(q3), above(quad), above(q3), above(q2), above(q1)}, n = 8;
	}
	// a volume with the right faces glued otherwise repeats a corner
	std::array<uint32, 8> sorted = c;
	std::sort(sorted.begin(), sorted.begin() + n);
	if (n == 0 || std::adjacent_find(sorted.begin(), sorted.begin() + n) != sorted.begin() + n)
		return false;
	corners.insert(corners.end(), c.begin(), c.begin() + n);
	return true;
}

/// The type of a cell of dimension dim with the given number of corners
/// (as append_plex_corners gives them).
DMPolytopeType cell_type(uint32 dim, PetscInt nb_corners)
{
	if (dim == 2)
		return nb_corners == 3 ? DM_POLYTOPE_TRIANGLE : DM_POLYTOPE_QUADRILATERAL;
	switch (nb_corners)
	{
	case 4:
		return DM_POLYTOPE_TETRAHEDRON;
	case 5:
		return DM_POLYTOPE_PYRAMID;
	case 6:
		return DM_POLYTOPE_TRI_PRISM;
	default:
		return DM_POLYTOPE_HEXAHEDRON;
	}
}

/// Appends to `corners` the corners of face f by vertex line,
/// counterclockwise from the one of smallest global id; false (nothing
/// appended) when f is neither a triangle nor a quadrilateral.
bool append_plex_corners(const CMap2& m, CMap2::Face f, const AttributeArray<uint64>& vertex_gids,
						 std::vector<uint32>& corners)
{
	const std::size_t first = corners.size();
	foreach_incident_vertex(m, f, [&](CMap2::Vertex v) {
		corners.push_back(index_of(m, v));
		return corners.size() - first <= 4;
	});
	const auto begin = corners.begin() + long(first);
	if (corners.size() - first < 3 || corners.size() - first > 4)
	{
		corners.erase(begin, corners.end());
		return false;
	}
	std::rotate(
		begin,
		std::min_element(begin, corners.end(), [&](uint32 a, uint32 b) { return vertex_gids[a] < vertex_gids[b]; }),
		corners.end());
	return true;
}

/// The vertices of point p of plex, an edge (depth 1) or a polygon (depth
/// 2), in the order its cone gives them: an edge's cone, or the first
/// vertex of each edge of a polygon's cone as the polygon turns it (a
/// negative orientation reverses the edge).
void cone_vertices(DM plex, PetscInt p, PetscInt depth, std::vector<PetscInt>& vertices)
{
	vertices.clear();
	PetscInt size = 0;
	const PetscInt* cone = nullptr;
	check(DMPlexGetConeSize(plex, p, &size), "DMPlexGetConeSize");
	check(DMPlexGetCone(plex, p, &cone), "DMPlexGetCone");
	if (depth == 1)
	{
		vertices.assign(cone, cone + size);
		return;
	}
	const PetscInt* orientations = nullptr;
	check(DMPlexGetConeOrientation(plex, p, &orientations), "DMPlexGetConeOrientation");
	for (PetscInt i = 0; i < size; ++i)
	{
		const PetscInt* ends = nullptr;
		check(DMPlexGetCone(plex, cone[i], &ends), "DMPlexGetCone");
		vertices.push_back(orientations[i] >= 0 ? ends[0] : ends[1]);
	}
}

/// Up to 4 vertex points, sorted, padded with -1: an edge's or a face's key.
using VertexKey = std::array<PetscInt, 4>;

VertexKey key_of(const std::vector<PetscInt>& vertices)
{
	VertexKey key{-1, -1, -1, -1};
	const std::size_t n = std::min(vertices.size(), key.size());
	for (std::size_t i = 0; i < n; ++i) // insertion sort
	{
		std::size_t j = i;
		for (; j > 0 && key[j - 1] > vertices[i]; --j)
			key[j] = key[j - 1];
		key[j] = vertices[i];
	}
	return key;
}

/// A hash of a VertexKey, for the map from keys to plex points.
struct VertexKeyHash
{
	std::size_t operator()(const VertexKey& k) const
	{
		std::size_t h = 0;
		for (PetscInt v : k)
			h = h * 0x9E3779B97F4A7C15ull + std::size_t(uint32(v));
		return h;
	}
};

/// Turns the cone of point p (an edge, or a face of a volume) so that its
/// vertices come in the order `target` instead of `current`; the cells that
/// hold p keep their shape (PETSc updates their cone orientations).
void orient_point(DM plex, PetscInt p, const std::vector<PetscInt>& current, const std::vector<PetscInt>& target)
{
	if (current == target)
		return;
	const DMPolytopeType type = current.size() == 2   ? DM_POLYTOPE_SEGMENT
								: current.size() == 3 ? DM_POLYTOPE_TRIANGLE
													  : DM_POLYTOPE_QUADRILATERAL;
	PetscInt orientation = 0;
	check(DMPolytopeGetVertexOrientation(type, current.data(), target.data(), &orientation),
		  "DMPolytopeGetVertexOrientation");
	check(DMPlexOrientPoint(plex, p, orientation), "DMPlexOrientPoint");
}

/// The ghost points of one dimension as star forest leaves: for each local
/// cell owned elsewhere, its point here and its owner's point there.
template <typename MAP>
void add_leaves(const DistributedMap<MAP>& dm, uint32 k, const std::vector<PetscInt>& point_by_line,
				std::vector<PetscInt>& leaves, std::vector<PetscSFNode>& remotes)
{
	std::vector<PetscInt> remote_point = point_by_line;
	exchange_lines(dm, k, remote_point);
	const AttributeArray<int32>& owners = dm.owners(k);
	std::vector<uint8> seen;
	for (uint32 line = 0; line < point_by_line.size(); ++line)
	{
		const PetscInt p = point_by_line[line];
		if (p < 0 || owners[line] == dm.rank())
			continue;
		// the rim's copies of one cell are one point: one leaf
		if (seen.size() <= std::size_t(p))
			seen.resize(std::size_t(p) + 1, 0);
		if (seen[std::size_t(p)])
			continue;
		seen[std::size_t(p)] = 1;
		leaves.push_back(p);
		remotes.push_back(PetscSFNode{owners[line], remote_point[line]});
	}
}

/// Sets the point star forest of plex from the leaves, sorted by point.
void set_point_sf(MPI_Comm comm, DM plex, PetscInt nb_points, std::vector<PetscInt>& leaves,
				  std::vector<PetscSFNode>& remotes)
{
	std::vector<std::size_t> order(leaves.size());
	for (std::size_t i = 0; i < order.size(); ++i)
		order[i] = i;
	std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return leaves[a] < leaves[b]; });
	std::vector<PetscInt> sorted_leaves(leaves.size());
	std::vector<PetscSFNode> sorted_remotes(leaves.size());
	for (std::size_t i = 0; i < order.size(); ++i)
	{
		sorted_leaves[i] = leaves[order[i]];
		sorted_remotes[i] = remotes[order[i]];
	}
	PetscSF sf = nullptr;
	check(PetscSFCreate(comm, &sf), "PetscSFCreate");
	const PetscErrorCode set = PetscSFSetGraph(sf, nb_points, PetscInt(sorted_leaves.size()), sorted_leaves.data(),
											   PETSC_COPY_VALUES, sorted_remotes.data(), PETSC_COPY_VALUES);
	if (set == 0)
		check(DMSetPointSF(plex, sf), "DMSetPointSF");
	PetscSFDestroy(&sf);
	check(set, "PetscSFSetGraph");
}

/// The vertices of an edge or face in an order that depends on their
/// global ids only: from the smallest, towards its smaller neighbour.
void canonical_cycle(std::vector<PetscInt>& vertices, std::vector<uint64>& gids)
{
	const std::size_t n = vertices.size();
	const std::size_t first = std::size_t(std::min_element(gids.begin(), gids.end()) - gids.begin());
	std::rotate(vertices.begin(), vertices.begin() + long(first), vertices.end());
	std::rotate(gids.begin(), gids.begin() + long(first), gids.end());
	if (n > 2 && gids[n - 1] < gids[1])
	{
		std::reverse(vertices.begin() + 1, vertices.end());
		std::reverse(gids.begin() + 1, gids.end());
	}
}

/// Whether each line of the cells of dimension k is held by another rank
/// too: a ghost, or an owned cell that a neighbour holds as a ghost.
template <typename MAP>
std::vector<uint8> shared_lines(const DistributedMap<MAP>& dm, uint32 k)
{
	const AttributeArray<int32>& owners = dm.owners(k);
	std::vector<uint8> shared;
	detail::foreach_cell_type<MAP>([&](auto cell, uint32 dim) {
		if (dim != k)
			return;
		shared.assign(container_of<decltype(cell)::ORBIT>(dm.map()).end_index(), 0);
		foreach_cell(dm.map(), [&](decltype(cell) c) {
			const uint32 line = index_of(dm.map(), c);
			shared[line] = owners[line] != dm.rank();
		});
	});
	for (uint32 line : dm.plan(k).send_lines)
		shared[line] = 1;
	return shared;
}

/// The plex points of the edges (and faces) of dm's map, written to
/// points[k]: the plex's edges and faces are found by their vertices
/// (points[0]). Each one that another rank holds too is turned so that its
/// vertices come in their canonical_cycle order, the same on every rank;
/// the others keep the order PETSc gave them. Returns the first dimension
/// (1 or 2) in which two cells of different global ids have the same
/// vertices, 0 if none: DMPlex names the edges and faces it interpolates by
/// their vertices, so it holds one point for both (the mesh is not
/// conforming there, like a face of a hexahedron meeting two triangles).
template <typename MAP>
uint32 find_inner_points(const DistributedMap<MAP>& dm, DM plex, std::vector<std::vector<PetscInt>>& points)
{
	uint32 merged = 0;
	using Vertex = typename MAP::Vertex;
	const MAP& m = dm.map();
	const AttributeArray<uint64>& vertex_gids = dm.global_ids(0);
	std::vector<PetscInt> vertices, current;
	std::vector<uint64> gids;
	detail::foreach_cell_type<MAP>([&](auto cell, uint32 k) {
		using CELL = decltype(cell);
		if constexpr (!std::is_same_v<CELL, Vertex> && !std::is_same_v<CELL, typename DistributedMap<MAP>::TopCell>)
		{
			PetscInt start = 0, end = 0;
			check(DMPlexGetDepthStratum(plex, PetscInt(k), &start, &end), "DMPlexGetDepthStratum");
			std::unordered_map<VertexKey, PetscInt, VertexKeyHash> point_of;
			point_of.reserve(std::size_t(end - start));
			for (PetscInt p = start; p < end; ++p)
			{
				cone_vertices(plex, p, PetscInt(k), vertices);
				point_of.emplace(key_of(vertices), p);
			}
			// the global id of the cell each point was found for; the rim's
			// copies of a cell share their point
			constexpr uint64 none = std::numeric_limits<uint64>::max();
			std::vector<uint64> gid_of_point(std::size_t(end - start), none);
			const AttributeArray<uint64>& cell_gids = dm.global_ids(k);
			const std::vector<uint8> shared = shared_lines(dm, k);
			foreach_cell(m, [&](CELL c) {
				vertices.clear();
				gids.clear();
				foreach_incident_vertex(m, c, [&](Vertex v) {
					vertices.push_back(points[0][index_of(m, v)]);
					gids.push_back(vertex_gids[index_of(m, v)]);
					return vertices.size() <= 4;
				});
				const auto it = vertices.size() <= 4 ? point_of.find(key_of(vertices)) : point_of.end();
				if (it == point_of.end())
					throw DMPlexError("to_dmplex: a cell of dimension " + std::to_string(k) + " has no plex point");
				const PetscInt p = it->second;
				const uint32 line = index_of(m, c);
				points[k][line] = p;
				uint64& found_for = gid_of_point[std::size_t(p - start)];
				if (found_for != none)
				{
					if (found_for != cell_gids[line] && merged == 0)
						merged = k;
					return true;
				}
				found_for = cell_gids[line];
				if (shared[line])
				{
					canonical_cycle(vertices, gids);
					cone_vertices(plex, p, PetscInt(k), current);
					orient_point(plex, p, current, vertices);
				}
				return true;
			});
		}
	});
	return merged;
}

template <typename MAP>
PlexMesh build_plex(const DistributedMap<MAP>& dm, const std::string& position)
{
	using Vertex = typename MAP::Vertex;
	using Top = typename DistributedMap<MAP>::TopCell;
	constexpr uint32 D = MAP::dimension;
	const MAP& m = dm.map();
	PetscBool initialised = PETSC_FALSE;
	PetscInitialized(&initialised);
	if (!initialised)
		throw std::invalid_argument("to_dmplex: PETSc is not initialised (call PetscInitialize first)");
	auto pos = get_attribute<Vec3, Vertex>(m, position);
	if (!detail::on_all_ranks(dm.comm(), pos != nullptr))
		throw std::invalid_argument("to_dmplex: a rank has no Vec3 vertex attribute '" + position + "'");

	// cells first, then the vertices: one point per global vertex id
	std::vector<uint32> cell_lines;
	std::vector<PetscInt> cone_sizes, cones;
	std::vector<uint32> corner_lines;
	bool supported = true;
	foreach_cell(m, [&](Top c) {
		const std::size_t before = corner_lines.size();
		supported = append_plex_corners(m, c, dm.global_ids(0), corner_lines);
		cell_lines.push_back(index_of(m, c));
		cone_sizes.push_back(PetscInt(corner_lines.size() - before));
		return supported;
	});
	if (!detail::on_all_ranks(dm.comm(), supported))
		throw std::invalid_argument(
			D == 3 ? "to_dmplex: every volume must be a tetrahedron, a pyramid, a triangular prism or a hexahedron"
				   : "to_dmplex: every face must be a triangle or a quadrilateral");
	const std::size_t nb_cells = cell_lines.size();
	// a cell adds at most 6 faces, 12 edges and 8 vertices
	if (nb_cells > std::size_t(std::numeric_limits<PetscInt>::max()) / 27)
		throw std::invalid_argument("to_dmplex: the local map has too many cells for PETSc's 32-bit indices");

	std::vector<std::vector<PetscInt>> points(D + 1);
	detail::foreach_cell_type<MAP>(
		[&](auto cell, uint32 k) { points[k].assign(container_of<decltype(cell)::ORBIT>(m).end_index(), -1); });
	std::unordered_map<uint64, PetscInt> point_of_gid;
	std::vector<PetscScalar> coordinates;
	const AttributeArray<uint64>& vertex_gids = dm.global_ids(0);
	foreach_cell(m, [&](Vertex v) {
		const uint32 line = index_of(m, v);
		const auto [it, inserted] = point_of_gid.emplace(vertex_gids[line], PetscInt(nb_cells + point_of_gid.size()));
		points[0][line] = it->second;
		if (inserted)
			for (uint32 i = 0; i < 3; ++i)
				coordinates.push_back((*pos)[line][i]);
	});
	const PetscInt nb_vertices = PetscInt(point_of_gid.size());
	for (std::size_t i = 0; i < nb_cells; ++i)
		points[D][cell_lines[i]] = PetscInt(i);
	cones.reserve(corner_lines.size());
	for (uint32 line : corner_lines)
		cones.push_back(points[0][line]);
	cone_sizes.resize(nb_cells + std::size_t(nb_vertices), 0);
	const std::vector<PetscInt> orientations(cones.size(), 0);

	QuietPetsc quiet;
	DMGuard cells;
	check(DMCreate(dm.comm(), &cells.dm), "DMCreate");
	check(DMSetType(cells.dm, DMPLEX), "DMSetType");
	check(DMSetDimension(cells.dm, PetscInt(D)), "DMSetDimension");
	check(DMSetCoordinateDim(cells.dm, 3), "DMSetCoordinateDim");
	const PetscInt per_depth[2] = {nb_vertices, PetscInt(nb_cells)};
	check(DMPlexCreateFromDAG(cells.dm, 1, per_depth, cone_sizes.data(), cones.data(), orientations.data(),
							  coordinates.data()),
		  "DMPlexCreateFromDAG");
	// PETSc guesses a cell's type from its number of corners and takes six
	// corners for a tensor prism (which orders them otherwise): say which
	{
		DMLabel types = nullptr;
		check(DMPlexGetCellTypeLabel(cells.dm, &types), "DMPlexGetCellTypeLabel");
		for (std::size_t i = 0; i < nb_cells; ++i)
		{
			DMPolytopeType guess = DM_POLYTOPE_UNKNOWN;
			check(DMPlexGetCellType(cells.dm, PetscInt(i), &guess), "DMPlexGetCellType");
			const DMPolytopeType type = cell_type(D, cone_sizes[i]);
			if (guess != type)
			{
				check(DMLabelClearValue(types, PetscInt(i), guess), "DMLabelClearValue");
				check(DMLabelSetValue(types, PetscInt(i), type), "DMLabelSetValue");
			}
		}
	}
	// PETSc adds the faces and edges on each rank alone: its parallel
	// interpolation orients the shared cones of tetrahedral meshes only
	DMGuard plex;
	check(DMPlexInterpolate(cells.dm, &plex.dm), "DMPlexInterpolate");
	PetscInt c_start = 0, c_end = 0, v_start = 0, v_end = 0;
	check(DMPlexGetHeightStratum(plex.dm, 0, &c_start, &c_end), "DMPlexGetHeightStratum");
	check(DMPlexGetDepthStratum(plex.dm, 0, &v_start, &v_end), "DMPlexGetDepthStratum");
	// interpolation keeps the order of the cells and of the vertices
	for (auto& p : points[D])
		if (p >= 0)
			p += c_start;
	for (auto& p : points[0])
		if (p >= 0)
			p += v_start - PetscInt(nb_cells);

	// the edges (and faces) found by their vertices, the shared ones turned
	// the same way on every rank; a failure on one rank is raised on all
	// (the next call is collective)
	uint32 merged = 0;
	detail::on_every_rank(dm.comm(), [&] { merged = find_inner_points(dm, plex.dm, points); });
	MPI_Allreduce(MPI_IN_PLACE, &merged, 1, MPI_UINT32_T, MPI_MAX, dm.comm());
	if (merged != 0)
		throw std::invalid_argument(std::string("to_dmplex: two ") + (merged == 1 ? "edges" : "faces") +
									" have the same vertices (the mesh is not conforming there); DMPlex names a cell "
									"by its vertices");
	// the final star forest: every dimension's ghosts, rooted at the owners
	PetscInt p_start = 0, p_end = 0;
	check(DMPlexGetChart(plex.dm, &p_start, &p_end), "DMPlexGetChart");
	std::vector<PetscInt> leaves;
	std::vector<PetscSFNode> remotes;
	for (uint32 k = 0; k <= D; ++k)
		add_leaves(dm, k, points[k], leaves, remotes);
	set_point_sf(dm.comm(), plex.dm, p_end - p_start, leaves, remotes);
	// the ghost layer is PETSc's overlap of one cell (the cells that share a
	// vertex with an owned one); DMSetFromOptions must not distribute again
	check(DMPlexSetOverlap(plex.dm, nullptr, 1), "DMPlexSetOverlap");
	check(DMPlexDistributeSetDefault(plex.dm, PETSC_FALSE), "DMPlexDistributeSetDefault");
	DM result = plex.dm;
	plex.dm = nullptr;
	return PlexMesh(result, std::move(points));
}

} // namespace

PlexMesh to_dmplex(const DistributedCMap3& dm, const std::string& position)
{
	return build_plex(dm, position);
}

PlexMesh to_dmplex(const DistributedCMap3& dm)
{
	return build_plex(dm, "position");
}

PlexMesh to_dmplex(const DistributedCMap2& dm, const std::string& position)
{
	return build_plex(dm, position);
}

PlexMesh to_dmplex(const DistributedCMap2& dm)
{
	return build_plex(dm, "position");
}

} // namespace cgogn::dist
