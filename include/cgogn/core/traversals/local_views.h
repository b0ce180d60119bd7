// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/views/mesh_view.h>

namespace cgogn
{

// Local traversals on views: those of the viewed mesh, reporting only the
// neighbours the view accepts (a CellFilter's predicate of the neighbour's
// type; a CellCache accepts every cell). Costs are those of the viewed mesh's
// traversal plus one predicate call per neighbour. The starting cell itself
// is not checked.

#define CGOGN_VIEW_LOCAL_TRAVERSAL(NAME)                                                                               \
	template <MeshView V, CellType CELL, typename FUNC>                                                                \
	void NAME(const V& v, CELL c, const FUNC& f)                                                                       \
	{                                                                                                                  \
		NAME(v.mesh(), c, [&](auto x) { return !v.accepts(x) || call_and_continue(f, x); });                           \
	}

CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_incident_vertex)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_incident_edge)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_incident_face)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_incident_volume)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_vertex_through_edge)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_vertex_through_face)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_vertex_through_volume)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_edge_through_vertex)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_edge_through_face)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_edge_through_volume)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_face_through_vertex)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_face_through_edge)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_face_through_volume)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_volume_through_vertex)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_volume_through_edge)
CGOGN_VIEW_LOCAL_TRAVERSAL(foreach_adjacent_volume_through_face)

#undef CGOGN_VIEW_LOCAL_TRAVERSAL

} // namespace cgogn
