// SPDX-License-Identifier: MIT
// 1-to-8 refinement of hexahedral and tetrahedral meshes. The refined cells
// are listed with their vertices (old vertices, then one per edge, face and
// cell as the scheme needs), then the map is rebuilt with build_volume: far
// simpler and faster than cutting every cell with cut_edge / cut_face /
// cut_volume, which would re-sew the same faces many times.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/operators/maintenance.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/modeling/refinement_patterns.h>
#include <cgogn/modeling/subdivision.h>

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace cgogn::modeling
{

namespace
{

using Vertex = CMap3::Vertex;
using Edge = CMap3::Edge;
using Face = CMap3::Face;
using Volume = CMap3::Volume;

/// True when every volume has nb_faces faces of `degree` edges.
bool every_volume_is(const CMap3& m, uint32 nb_faces, uint32 degree)
{
	bool ok = true;
	foreach_cell(m, [&](Volume w) {
		uint32 darts = 0;
		foreach_dart_of_orbit(m, w, [&](Dart d) {
			++darts;
			Dart x = d;
			for (uint32 i = 0; i < degree; ++i)
			{
				x = phi1(m, x);
				if (x == d && i + 1 < degree)
					ok = false;
			}
			ok = ok && x == d;
			return ok;
		});
		ok = ok && darts == nb_faces * degree;
		return ok;
	});
	return ok;
}

/// The refined mesh being listed: new vertex ids and positions, and the
/// cells (all of one size) by their vertex ids.
struct Refinement
{
	std::vector<Vec3> positions;
	std::vector<uint32> cell_vertices;
	/// ids by dart of the old map (edges and faces) and by vertex line
	std::vector<uint32> vertex_id, edge_id, face_id;
	/// for the attribute rules: each new vertex's parents (old vertex
	/// lines, equal weights) from parent_offsets[id], and each new cell's
	/// old volume line
	std::vector<uint32> parent_offsets{0}, parent_lines, cell_parent;

	/// A new vertex at p whose parents are the old vertices of `lines`.
	uint32 add(const Vec3& p, std::initializer_list<uint32> lines)
	{
		parent_lines.insert(parent_lines.end(), lines);
		return add(p);
	}
	/// The same, its parents already pushed on parent_lines.
	uint32 add(const Vec3& p)
	{
		parent_offsets.push_back(uint32(parent_lines.size()));
		positions.push_back(p);
		return uint32(positions.size() - 1);
	}
	/// The old vertex line of new vertex id (an old vertex's own id).
	uint32 old_line(uint32 id) const
	{
		return parent_lines[parent_offsets[id]];
	}
};

const Vec3& position(const CMap3& m, const AttributeArray<Vec3>& pos, Dart d)
{
	return pos[index_of(m, Vertex(d))];
}

/// The line of w, INVALID_INDEX when volumes are not indexed.
uint32 volume_line(const CMap3& m, Volume w)
{
	return is_indexed<Volume>(m) ? index_of(m, w) : INVALID_INDEX;
}

/// A vertex per old vertex, then one per edge at its midpoint, then (with
/// `faces`) one per face at its vertex centroid.
void number_vertices_edges_faces(const CMap3& m, const AttributeArray<Vec3>& pos, Refinement& r, bool faces)
{
	r.vertex_id.assign(pos.container()->end_index(), INVALID_INDEX);
	foreach_cell(m, [&](Vertex v) { r.vertex_id[index_of(m, v)] = r.add(position(m, pos, v.dart), {index_of(m, v)}); });
	r.edge_id.assign(container_of<Orbit::DART>(m).end_index(), INVALID_INDEX);
	foreach_cell(m, [&](Edge e) {
		const uint32 id = r.add(0.5 * (position(m, pos, e.dart) + position(m, pos, phi1(m, e.dart))),
								{index_of(m, Vertex(e.dart)), index_of(m, Vertex(phi1(m, e.dart)))});
		foreach_dart_of_orbit(m, e, [&](Dart d) { r.edge_id[d.index] = id; });
	});
	if (!faces)
		return;
	r.face_id.assign(container_of<Orbit::DART>(m).end_index(), INVALID_INDEX);
	foreach_cell(m, [&](Face f) {
		Vec3 sum = Vec3::Zero();
		uint32 n = 0;
		Dart d = f.dart;
		do
		{
			sum += position(m, pos, d);
			r.parent_lines.push_back(index_of(m, Vertex(d)));
			++n;
			d = phi1(m, d);
		} while (d != f.dart);
		const uint32 id = r.add(sum / double(n));
		foreach_dart_of_orbit(m, f, [&](Dart x) { r.face_id[x.index] = id; });
	});
}

/// The old edges or faces of m by the sorted lines of their vertices, taken
/// before the map is rebuilt: a new edge or face lies on the old one whose
/// vertices are the old vertices its own vertices come from. O(cells x
/// degree x log cells) to collect.
class CellsByVertices
{
public:
	template <typename CELL>
	void collect(const CMap3& m)
	{
		std::vector<uint32> key;
		foreach_cell(m, [&](CELL c) {
			key.clear();
			foreach_incident_vertex(m, c, [&](Vertex v) { key.push_back(index_of(m, v)); });
			std::sort(key.begin(), key.end());
			line_.emplace(key, index_of(m, c));
		});
	}
	/// The old cell whose vertices are `lines` (sorted and made unique
	/// here), or INVALID_INDEX.
	uint32 find(std::vector<uint32>& lines) const
	{
		std::sort(lines.begin(), lines.end());
		lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
		const auto it = line_.find(lines);
		return it == line_.end() ? INVALID_INDEX : it->second;
	}

private:
	std::map<std::vector<uint32>, uint32> line_;
};

/// Applies the rules of the edges (faces) of the rebuilt map: a new cell
/// lying on an old one copies it; the others (inside an old face or
/// volume) keep the default value, as with cut_face and cut_volume.
template <typename CELL>
void apply_cell_rules(const CMap3& m, detail::RuleSnapshot& rules, const CellsByVertices& old, const Refinement& r,
					  uint32 vertex_offset)
{
	std::vector<uint32> lines;
	const double one = 1.0;
	foreach_cell(m, [&](CELL c) {
		lines.clear();
		foreach_incident_vertex(m, c, [&](Vertex v) {
			const uint32 id = index_of(m, v) - vertex_offset;
			lines.insert(lines.end(), r.parent_lines.begin() + r.parent_offsets[id],
						 r.parent_lines.begin() + r.parent_offsets[id + 1]);
		});
		if (const uint32 parent = old.find(lines); parent != INVALID_INDEX)
			rules.apply(index_of(m, c), std::span(&parent, 1), std::span(&one, 1));
	});
}

/// Removes every dart and cell of m, keeping its attributes (and whether each
/// orbit is indexed), then builds the listed cells into it. Attributes with
/// a rule (attribute_rules.h): a new vertex gets it from its parents (equal
/// weights), a new cell from its old volume, a new edge or face that lies
/// on an old one from it; edges and faces inside an old face or volume
/// hold the default value.
void rebuild(CMap3& m, AttributeArray<Vec3>& pos, const Refinement& r, uint32 cell_size, uint32 darts_per_cell)
{
	detail::RuleSnapshot vertex_rules(container_of<Vertex::ORBIT>(m));
	detail::RuleSnapshot volume_rules(container_of<Volume::ORBIT>(m));
	detail::RuleSnapshot edge_rules(container_of<Edge::ORBIT>(m));
	detail::RuleSnapshot face_rules(container_of<Face::ORBIT>(m));
	CellsByVertices old_edges, old_faces;
	if (!edge_rules.empty())
		old_edges.collect<Edge>(m);
	if (!face_rules.empty())
		old_faces.collect<Face>(m);
	clear(m);
	const std::vector<uint32> sizes(r.cell_vertices.size() / cell_size, cell_size);
	const BuildReport report = build_volume(m, uint32(r.positions.size()), sizes, r.cell_vertices);
	for (std::size_t i = 0; i < r.positions.size(); ++i)
		pos[report.vertex_offset + uint32(i)] = r.positions[i];
	std::vector<double> w;
	if (!vertex_rules.empty())
		for (uint32 i = 0; i + 1 < r.parent_offsets.size(); ++i)
		{
			const std::span<const uint32> parents(r.parent_lines.data() + r.parent_offsets[i],
												  r.parent_offsets[i + 1] - r.parent_offsets[i]);
			w.assign(parents.size(), 1.0 / double(parents.size()));
			vertex_rules.apply(report.vertex_offset + i, parents, w);
		}
	// build_volume gives the cells' darts in their order, darts_per_cell each
	if (!volume_rules.empty() && report.nb_cells_built == sizes.size())
	{
		const double one = 1.0;
		for (uint32 k = 0; k < sizes.size(); ++k)
			volume_rules.apply(index_of(m, Volume(Dart(k * darts_per_cell))), std::span(&r.cell_parent[k], 1),
							   std::span(&one, 1));
	}
	if (!edge_rules.empty())
		apply_cell_rules<Edge>(m, edge_rules, old_edges, r, report.vertex_offset);
	if (!face_rules.empty())
		apply_cell_rules<Face>(m, face_rules, old_faces, r, report.vertex_offset);
}

} // namespace

bool is_hex_mesh(const CMap3& m)
{
	return every_volume_is(m, 6, 4);
}

bool is_tet_mesh(const CMap3& m)
{
	return every_volume_is(m, 4, 3);
}

SubdivisionResult tet_subdivision(CMap3& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	// positions are the algorithm's own: no rule interpolates them
	const SuspendedRule own_positions(pos);
	if (!is_tet_mesh(m))
		throw SubdivisionError("tetrahedral subdivision: every volume must be a tetrahedron");
	ProgressReporter reporter(progress);
	Refinement r;
	number_vertices_edges_faces(m, pos, r, false);
	const uint32 nb_volumes = nb_cells<Volume>(m);
	r.cell_vertices.reserve(std::size_t(nb_volumes) * 32);
	uint32 done = 0;
	foreach_cell(m, [&](Volume w) {
		if ((done & 1023u) == 0 && !reporter.report(0.9 * double(done) / double(nb_volumes)))
			return false;
		++done;
		const auto points = tet_refinement_points(m, w);
		std::array<uint32, 10> local;
		for (uint32 i = 0; i < 10; ++i)
			local[i] =
				points[i].dim == 0 ? r.vertex_id[index_of(m, Vertex(points[i].dart))] : r.edge_id[points[i].dart.index];
		std::array<Vec3, 10> at;
		for (uint32 i = 0; i < 10; ++i)
			at[i] = r.positions[local[i]];
		const uint32 best = tet_cut_diagonal(at);
		for (const auto& t : tet_children(best))
		{
			for (uint32 i : t)
				r.cell_vertices.push_back(local[i]);
			r.cell_parent.push_back(volume_line(m, w));
		}
		return true;
	});
	if (reporter.cancelled())
		return {true, 0};
	rebuild(m, pos, r, 4, 12);
	reporter.report(1.0);
	return {reporter.cancelled(), 1};
}

SubdivisionResult hex_subdivision(CMap3& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	// positions are the algorithm's own: no rule interpolates them
	const SuspendedRule own_positions(pos);
	if (!is_hex_mesh(m))
		throw SubdivisionError("hexahedral subdivision: every volume must be a hexahedron");
	ProgressReporter reporter(progress);
	Refinement r;
	number_vertices_edges_faces(m, pos, r, true);
	const uint32 nb_volumes = nb_cells<Volume>(m);
	r.cell_vertices.reserve(std::size_t(nb_volumes) * 64);
	uint32 done = 0;
	foreach_cell(m, [&](Volume w) {
		if ((done & 1023u) == 0 && !reporter.report(0.9 * double(done) / double(nb_volumes)))
			return false;
		++done;
		const auto points = hex_refinement_points(m, w);
		std::array<uint32, 27> grid{};
		for (uint32 i = 0; i < 27; ++i)
		{
			const Dart d = points[i].dart;
			switch (points[i].dim)
			{
			case 0:
				grid[i] = r.vertex_id[index_of(m, Vertex(d))];
				break;
			case 1:
				grid[i] = r.edge_id[d.index];
				break;
			case 2:
				grid[i] = r.face_id[d.index];
				break;
			default:
				break;
			}
		}
		Vec3 centre = Vec3::Zero();
		for (uint32 x : {0u, 2u})
			for (uint32 y : {0u, 2u})
				for (uint32 z : {0u, 2u})
				{
					const uint32 corner = grid[x + 3 * y + 9 * z];
					centre += r.positions[corner];
					r.parent_lines.push_back(r.old_line(corner));
				}
		grid[1 + 3 + 9] = r.add(centre / 8.0);
		for (const auto& child : hex_children())
			for (uint32 i : child)
				r.cell_vertices.push_back(grid[i]);
		r.cell_parent.insert(r.cell_parent.end(), 8, volume_line(m, w));
		return true;
	});
	if (reporter.cancelled())
		return {true, 0};
	rebuild(m, pos, r, 8, 24);
	reporter.report(1.0);
	return {reporter.cancelled(), 1};
}

} // namespace cgogn::modeling
