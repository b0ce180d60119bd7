// SPDX-License-Identifier: MIT
#include "mesh_info.h"

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/operators/mrmap2.h>
#include <cgogn/core/operators/mrmap3.h>
#include <cgogn/core/properties/gmap_properties.h>
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/properties/incidence_graph_properties.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_mrmap2.h>
#include <cgogn/core/traversals/local_mrmap3.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/map_file.h>
#include <cgogn/io/options.h>

#include <algorithm>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

namespace cgogn::tool
{

namespace
{

using nlohmann::json;

template <typename MAP>
void geometry(const MAP& m, json& j)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Edge = typename mesh_traits<MAP>::Edge;
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	if (!pos)
		return;
	Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
	foreach_cell(m, [&](Vertex v) {
		const Vec3& p = value<Vec3>(m, *pos, v);
		lo = lo.cwiseMin(p);
		hi = hi.cwiseMax(p);
	});
	if (nb_cells<Vertex>(m) > 0)
		j["bbox"] = {{"min", {lo[0], lo[1], lo[2]}}, {"max", {hi[0], hi[1], hi[2]}}};
	else
		j["bbox"] = nullptr;
	double mn = std::numeric_limits<double>::infinity(), mx = 0.0, sum = 0.0;
	uint64 n = 0;
	foreach_cell(m, [&](Edge e) {
		Dart other;
		if constexpr (is_gmap_v<MAP>)
			other = beta0(m, e.dart);
		else if constexpr (std::is_same_v<MAP, Graph>)
			other = alpha0(m, e.dart);
		else
			other = phi1(m, e.dart);
		const double l = ((*pos)[index_of(m, Vertex(e.dart))] - (*pos)[index_of(m, Vertex(other))]).norm();
		mn = std::min(mn, l);
		mx = std::max(mx, l);
		sum += l;
		++n;
	});
	if (n > 0)
		j["edge_length"] = {{"min", mn}, {"max", mx}, {"mean", sum / double(n)}};
	else
		j["edge_length"] = nullptr;
}

void load_report(const io::LoadReport& r, json& j)
{
	j["format"] = io::format_name(r.format);
	j["manifold"] = r.manifold();
	j["isolated_vertices"] = r.nb_isolated_vertices;
	j["nonmanifold_vertices"] = r.nb_nonmanifold_vertices;
	j["split_vertex_copies"] = r.nb_vertices_split;
	j["nonmanifold_edges"] = r.nb_nonmanifold_edges;
	j["skipped_cells"] = r.nb_cells_skipped;
	j["holes_closed"] = r.nb_holes_closed;
	j["orientation_conflicts"] = r.nb_orientation_conflicts;
	if (!r.dropped.empty())
		j["not_loaded"] = r.dropped;
}

template <typename MAP>
json faces_info(const MAP& m, const io::LoadReport& r)
{
	using T = mesh_traits<MAP>;
	json j;
	j["dimension"] = 2;
	j["map"] = is_gmap_v<MAP> ? "GMap2" : "CMap2";
	const int64 v = nb_cells<typename T::Vertex>(m), e = nb_cells<typename T::Edge>(m),
				f = nb_cells<typename T::Face>(m);
	j["vertices"] = v;
	j["edges"] = e;
	j["faces"] = f;
	if constexpr (is_gmap_v<MAP>)
		j["darts"] = nb_darts(m);
	else
		j["halfedges"] = nb_darts(m);
	uint64 boundary_edges = 0;
	foreach_cell(m, [&](typename T::Edge x) { boundary_edges += is_incident_to_boundary(m, x); });
	j["boundary_edges"] = boundary_edges;
	const uint32 bc = nb_boundary_components(m), cc = nb_connected_components(m);
	j["boundary_components"] = bc;
	j["connected_components"] = cc;
	const int64 chi = v - e + f;
	j["euler_characteristic"] = chi;
	bool orientable = true;
	if constexpr (is_gmap_v<MAP>)
		orientable = is_orientable(m);
	j["orientable"] = orientable;
	// closed orientable surfaces: chi = 2 cc - 2 g (total genus over the
	// components); closed non-orientable connected ones: chi = 2 - k, with k
	// the non-orientable genus (the number of cross-caps)
	if (bc == 0 && cc > 0 && orientable && (2 * int64(cc) - chi) % 2 == 0)
		j["genus"] = (2 * int64(cc) - chi) / 2;
	else if (bc == 0 && cc == 1 && !orientable)
		j["genus"] = 2 - chi;
	else
		j["genus"] = nullptr;
	load_report(r, j);
	std::map<uint32, uint64> degrees;
	foreach_cell(m, [&](typename T::Face x) { ++degrees[codegree(m, x)]; });
	json h = json::object();
	for (auto [d, n] : degrees)
		h[std::to_string(d)] = n;
	j["face_degrees"] = h;
	geometry(m, j);
	return j;
}

} // namespace

json surface_info(const CMap2& m, const io::LoadReport& r)
{
	return faces_info(m, r);
}

json surface_info(const GMap2& m, const io::LoadReport& r)
{
	return faces_info(m, r);
}

template <typename MAP>
json cells_info3(const MAP& m, const io::LoadReport& r)
{
	using T = mesh_traits<MAP>;
	json j;
	j["dimension"] = 3;
	j["map"] = is_gmap_v<MAP> ? "GMap3" : "CMap3";
	// the io layer orients every cell by its geometry, so a CMap3 holds any
	// mesh whose cells are glued consistently; the tool loads the others
	// into a GMap3
	if constexpr (is_gmap_v<MAP>)
		j["orientable"] = is_orientable(m);
	else
		j["orientable"] = true;
	const int64 v = nb_cells<typename T::Vertex>(m), e = nb_cells<typename T::Edge>(m),
				f = nb_cells<typename T::Face>(m), w = nb_cells<typename T::Volume>(m);
	j["vertices"] = v;
	j["edges"] = e;
	j["faces"] = f;
	j["volumes"] = w;
	uint64 boundary_faces = 0;
	foreach_cell(m, [&](typename T::Face x) { boundary_faces += degree(m, x) < 2; });
	j["boundary_faces"] = boundary_faces;
	j["boundary_components"] = nb_boundary_components(m);
	j["connected_components"] = nb_connected_components(m);
	j["euler_characteristic"] = v - e + f - w;
	load_report(r, j);
	j["nonmanifold_faces"] = r.nb_nonmanifold_faces;
	j["reoriented_cells"] = r.nb_cells_reoriented;
	std::map<uint32, uint64> degrees;
	foreach_cell(m, [&](typename T::Face x) { ++degrees[codegree(m, x)]; });
	json h = json::object();
	for (auto [d, n] : degrees)
		h[std::to_string(d)] = n;
	j["face_degrees"] = h;
	uint64 tets = 0, pyramids = 0, prisms = 0, hexes = 0, others = 0;
	foreach_cell(m, [&](typename T::Volume x) {
		uint32 nf = 0, tri = 0, quad = 0;
		foreach_incident_face(m, x, [&](typename T::Face fc) {
			const uint32 d = codegree(m, fc);
			++nf;
			tri += d == 3;
			quad += d == 4;
		});
		if (nf == 4 && tri == 4)
			++tets;
		else if (nf == 5 && tri == 4)
			++pyramids;
		else if (nf == 5 && tri == 2 && quad == 3)
			++prisms;
		else if (nf == 6 && quad == 6)
			++hexes;
		else
			++others;
	});
	j["cell_kinds"] = {
		{"tetrahedra", tets}, {"pyramids", pyramids}, {"prisms", prisms}, {"hexahedra", hexes}, {"other", others}};
	geometry(m, j);
	return j;
}

json volume_info(const CMap3& m, const io::LoadReport& r)
{
	return cells_info3(m, r);
}

json volume_info(const GMap3& m, const io::LoadReport& r)
{
	return cells_info3(m, r);
}

json graph_info(const Graph& g, const io::GraphLoadReport& r)
{
	json j;
	j["dimension"] = 1;
	j["map"] = "Graph";
	const int64 v = nb_cells<Graph::Vertex>(g), e = nb_cells<Graph::Edge>(g);
	j["vertices"] = v;
	j["edges"] = e;
	j["connected_components"] = nb_connected_components(g);
	j["euler_characteristic"] = v - e;
	j["cycle_rank"] = cycle_rank(g);
	uint64 isolated = 0, loops = 0;
	std::map<uint32, uint64> degrees;
	foreach_cell(g, [&](Graph::Vertex x) {
		const uint32 d = degree(g, x);
		isolated += d == 0;
		++degrees[d];
	});
	foreach_cell(
		g, [&](Graph::Edge x) { loops += same_cell(g, Graph::Vertex(x.dart), Graph::Vertex(alpha0(g, x.dart))); });
	j["isolated_vertices"] = isolated;
	j["self_loops"] = loops;
	uint64 open = 0, closed = 0;
	for (const GraphBranch& b : branches(g))
		(b.closed ? closed : open) += 1;
	j["branches"] = {{"open", open}, {"closed", closed}};
	json h = json::object();
	for (auto [d, n] : degrees)
		h[std::to_string(d)] = n;
	j["vertex_degrees"] = h;
	j["radius"] = r.radius;
	j["one_sided_edges"] = r.nb_one_sided_edges;
	geometry(g, j);
	return j;
}

namespace
{
// The levels (darts, f-vector) and the attributes of a multiresolution map,
// on top of what the info of its current level says; `cells` names the
// containers of its finest map to list.
template <typename MR>
json levels_and_attributes(const MR& m, json j, const std::vector<std::pair<const char*, Orbit>>& cells)
{
	j["map"] = io::map_type_name<MR>();
	j["max_level"] = max_level(m);
	j["current_level"] = current_level(m);
	json levels = json::array();
	for (uint32 l = 0; l <= max_level(m); ++l)
	{
		const auto v = level_view(m, l);
		levels.push_back({{"level", l}, {"darts", nb_darts(v)}, {"f_vector", f_vector(v)}});
	}
	j["levels"] = levels;
	json attributes = json::array();
	const detail::MapState& s = detail::state_of(finest_map(m));
	const auto list = [&](const char* cell, const AttributeContainer& c) {
		for (const auto& a : c.attributes())
			if (!detail::is_reserved_name(a->name()))
			{
				const std::string type = io::map_file_value_type(*a);
				attributes.push_back({{"cell", cell}, {"name", a->name()}, {"type", type.empty() ? "other" : type}});
			}
	};
	list("halfedge", *s.darts);
	for (const auto& [cell, o] : cells)
		list(cell, *s.cells[orbit_index(o)]);
	j["attributes"] = attributes;
	return j;
}
} // namespace

json mrmap_info(const MRMap2& m)
{
	return levels_and_attributes(
		m, surface_info(extract_level(m, current_level(m)), io::LoadReport{}),
		{{"vertex", Orbit::PHI21}, {"edge", Orbit::PHI2}, {"face", Orbit::PHI1}, {"volume", Orbit::PHI1_PHI2}});
}

json mrmap_info(const MRMap3& m)
{
	return levels_and_attributes(m, volume_info(extract_level(m, current_level(m)), io::LoadReport{}),
								 {{"vertex", Orbit::PHI21_PHI31},
								  {"edge", Orbit::PHI2_PHI3},
								  {"face", Orbit::PHI1_PHI3},
								  {"volume", Orbit::PHI1_PHI2},
								  {"connected component", Orbit::PHI1_PHI2_PHI3}});
}

json complex_info(const IncidenceGraph& ig, const io::LoadReport& r)
{
	json j;
	j["dimension"] = 2;
	j["map"] = "IncidenceGraph";
	j["format"] = io::format_name(r.format);
	const int64 v = nb_cells<IncidenceGraph::Vertex>(ig), e = nb_cells<IncidenceGraph::Edge>(ig),
				f = nb_cells<IncidenceGraph::Face>(ig);
	j["vertices"] = v;
	j["edges"] = e;
	j["faces"] = f;
	j["connected_components"] = nb_connected_components(ig);
	j["euler_characteristic"] = v - e + f;
	uint64 nonmanifold_vertices = 0, isolated = 0, wires = 0, nonmanifold_edges = 0, border = 0;
	uint32 max_faces = 0;
	foreach_cell(ig, [&](IncidenceGraph::Vertex x) {
		if (degree(ig, x) == 0)
			++isolated;
		else if (!is_manifold_vertex(ig, x))
			++nonmanifold_vertices;
	});
	foreach_cell(ig, [&](IncidenceGraph::Edge x) {
		const uint32 d = degree(ig, x);
		wires += d == 0;
		border += d == 1;
		nonmanifold_edges += d > 2;
		max_faces = std::max(max_faces, d);
	});
	j["manifold"] = nonmanifold_vertices == 0 && nonmanifold_edges == 0 && wires == 0;
	j["nonmanifold_vertices"] = nonmanifold_vertices;
	j["nonmanifold_edges"] = nonmanifold_edges;
	j["boundary_edges"] = border;
	j["wire_edges"] = wires;
	j["isolated_vertices"] = isolated;
	j["max_faces_per_edge"] = max_faces;
	j["skipped_cells"] = r.nb_cells_skipped;
	return j;
}

std::string info_text(const json& j)
{
	std::ostringstream s;
	auto line = [&](const char* label, const json& v) {
		s << label << ": ";
		if (v.is_null())
			s << "-";
		else if (v.is_string())
			s << v.get<std::string>();
		else
			s << v.dump();
		s << "\n";
	};
	for (const char* k : {"file",
						  "format",
						  "dimension",
						  "map",
						  "max_level",
						  "current_level",
						  "levels",
						  "attributes",
						  "vertices",
						  "edges",
						  "faces",
						  "volumes",
						  "halfedges",
						  "darts",
						  "f_vector",
						  "boundary",
						  "boundary_f_vector",
						  "boundary_edges",
						  "boundary_faces",
						  "boundary_components",
						  "connected_components",
						  "euler_characteristic",
						  "genus",
						  "cycle_rank",
						  "self_loops",
						  "branches",
						  "vertex_degrees",
						  "radius",
						  "one_sided_edges",
						  "orientable",
						  "manifold",
						  "isolated_vertices",
						  "nonmanifold_vertices",
						  "split_vertex_copies",
						  "nonmanifold_edges",
						  "wire_edges",
						  "max_faces_per_edge",
						  "orientation_conflicts",
						  "nonmanifold_faces",
						  "skipped_cells",
						  "holes_closed",
						  "reoriented_cells",
						  "not_loaded",
						  "cell_kinds",
						  "face_degrees",
						  "bbox",
						  "edge_length",
						  "repaired_map",
						  "ranks",
						  "owned_cells_per_rank",
						  "ghost_cells_per_rank"})
		if (!j.contains(k))
			continue;
		else if (std::string_view(k) == "levels")
			for (const json& l : j[k])
				s << "level " << l["level"].dump() << ": darts " << l["darts"].dump() << ", f_vector "
				  << l["f_vector"].dump() << "\n";
		else if (std::string_view(k) == "attributes")
		{
			s << "attributes: ";
			for (std::size_t i = 0; i < j[k].size(); ++i)
				s << (i > 0 ? ", " : "") << j[k][i]["name"].get<std::string>() << " ("
				  << j[k][i]["cell"].get<std::string>() << ", " << j[k][i]["type"].get<std::string>() << ")";
			s << (j[k].empty() ? "-\n" : "\n");
		}
		else
			line(k, j[k]);
	return s.str();
}

} // namespace cgogn::tool
