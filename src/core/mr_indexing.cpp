// SPDX-License-Identifier: MIT
// The lines of the cells of a multiresolution map at every level (see
// detail::MRCellIndex).
#include "mr_indexing.h"

#include <cgogn/core/map/indexing.h>

#include <algorithm>
#include <string>
#include <utility>

namespace cgogn::detail
{

namespace
{

/// Copies the values of line src to line dst in every attribute of the
/// container but the key and the library's own.
void copy_values(AttributeContainer& c, uint32 dst, uint32 src)
{
	for (const auto& a : c.attributes())
		if (a.get() != &c.key() && a->name().rfind("__", 0) != 0)
			a->copy_line(dst, src);
}

/// For a face of level l without a dart of level l - 1 (the middle triangle
/// of a triangle cut in 4): a dart of level l - 1 of a face that shares its
/// parent, reached across the new edges of level l. INVALID when none, or
/// for another slot than the faces'.
Dart old_dart_of_sibling(const MRState2& s, uint32 slot, uint32 l, Dart d)
{
	if (slot != MRDim<MRState2>::face_slot)
		return Dart();
	const auto level = s.level->view();
	std::vector<Dart> work{d};
	DartMarkerStore<CMap2> seen(s.map);
	seen.mark(d);
	for (std::size_t i = 0; i < work.size() && i < 64; ++i)
	{
		Dart found;
		foreach_dart_of_orbit(MRLevelView2(s, l), MRMap2::Face(work[i]), [&](Dart x) {
			if (level[x.index] < l)
			{
				found = x;
				return false;
			}
			const Dart y = mr_phi2(s, l, x);
			if (!is_boundary(s.map, y) && level[y.index] == l && !seen.is_marked(y))
			{
				seen.mark(y);
				work.push_back(y);
			}
			return true;
		});
		if (found.is_valid())
			return found;
	}
	return Dart();
}

/// For a face or volume of level l without a dart of level l - 1 (the middle
/// triangle of a triangle cut in 4, the middle octahedron of a tetrahedron,
/// a face tetrahedron of an octahedron): a dart of level l - 1 of a cell of
/// level l next to it in the same cell of level l - 1. A face's neighbours
/// are the pieces of its face across its edges (the faces around an edge
/// with its face id, see mr_phi2_in_face); a volume's are the volumes across
/// its faces (a middle cell touches only middle cells across the faces of
/// its parent, and its siblings across the others). INVALID when none.
/// O(size of the cell x size of a neighbour).
Dart old_dart_of_sibling(const MRState3& s, uint32 slot, uint32 l, Dart d)
{
	using D = MRDim<MRState3>;
	const MRLevelView3 v(s, l);
	const auto level = s.level->view();
	const auto face_id = s.face_id->view();
	const auto old_of = [&](auto cell) {
		Dart found;
		foreach_dart_of_orbit(v, cell, [&](Dart x) {
			if (level[x.index] < l)
				found = x;
			return !found.is_valid();
		});
		return found;
	};
	Dart found;
	if (slot == D::face_slot)
		foreach_dart_of_orbit(v, MRMap3::Face2(d), [&](Dart x) {
			Dart y = mr_phi2(s, l, x);
			for (uint32 steps = 0; face_id[y.index] != face_id[x.index] && steps < 256; ++steps)
				y = mr_phi2(s, l, mr_phi3(s, l, y));
			if (face_id[y.index] == face_id[x.index])
				found = old_of(MRMap3::Face2(y));
			return !found.is_valid();
		});
	else if (slot == D::volume_slot)
		foreach_dart_of_orbit(v, MRMap3::Volume(d), [&](Dart x) {
			const Dart y = mr_phi3(s, l, x);
			if (!is_boundary(s.map, y))
				found = old_of(MRMap3::Volume(y));
			return !found.is_valid();
		});
	return found;
}

} // namespace

std::vector<uint32> mr_vertex_parents(const MRState2& s, uint32 l, Dart v)
{
	constexpr uint32 vertex = MRDim<MRState2>::vertex_slot;
	std::vector<uint32> parents;
	const auto [origin, d] = mr_vertex_origin(s, l, v);
	if (origin == MRVertexOrigin::Midpoint)
		parents = {mr_line_of(s, l - 1, vertex, d), mr_line_of(s, l - 1, vertex, mr_phi2(s, l - 1, d))};
	else if (origin == MRVertexOrigin::Centre)
		foreach_dart_of_orbit(MRLevelView2(s, l - 1), MRMap2::Face(d),
							  [&](Dart x) { parents.push_back(mr_line_of(s, l - 1, vertex, x)); });
	return parents;
}

template <typename S>
void mr_foreach_cell_of_slot(const S& s, uint32 slot, uint32 l, const std::function<void(Dart)>& f)
{
	using D = MRDim<S>;
	const auto level = s.level->view();
	DartMarkerStore<typename D::Flat> seen(s.map);
	foreach_dart(s.map, [&](Dart d) {
		// a real cell has a dart outside the boundary
		if (level[d.index] > l || is_boundary(s.map, d) || seen.is_marked(d))
			return;
		mr_foreach_dart_of_cell(s, slot, l, d, [&](Dart x) { seen.mark(x); });
		f(d);
	});
}

template <typename S>
uint32 mr_add_line(S& s, uint32 slot, uint32 l, Dart representative, uint32 down)
{
	MRCellIndex& ci = s.cells[slot];
	AttributeContainer& c = mr_slot_container(s, slot);
	const uint32 i = c.new_line(representative.index);
	(*ci.down)[i] = down;
	(*ci.level)[i] = uint8(l);
	(*ci.replaced)[i] = MR_NOT_REPLACED;
	if (down != INVALID_INDEX)
	{
		(*ci.replaced)[down] = uint8(l);
		copy_values(c, i, down);
	}
	return i;
}

template <typename S>
void mr_add_slot_attributes(S& s, uint32 slot)
{
	MRCellIndex& ci = s.cells[slot];
	AttributeContainer& c = mr_slot_container(s, slot);
	ci.down = c.add_attribute<uint32>("__mr_down", INVALID_INDEX);
	ci.level = c.add_attribute<uint8>("__mr_level", 0);
	ci.replaced = c.add_attribute<uint8>("__mr_replaced", MR_NOT_REPLACED);
}

std::vector<uint32> mr_vertex_parents(const MRState3& s, uint32 l, Dart v)
{
	const MRLevelView3 here(s, l), below(s, l - 1);
	const auto level = s.level->view();
	constexpr uint32 vertex = MRDim<MRState3>::vertex_slot;
	std::vector<uint32> parents;
	// the middle of an edge: a dart of v at level l whose other end is old
	// (the first piece of the edge's other half keeps its dart)
	Dart old;
	foreach_dart_of_orbit(here, MRMap3::Vertex(v), [&](Dart d) {
		const Dart e = mr_phi2(s, l, d);
		if (level[e.index] < l)
			old = e;
		return !old.is_valid();
	});
	if (old.is_valid())
		return {mr_line_of(s, l - 1, vertex, old), mr_line_of(s, l - 1, vertex, mr_phi2(s, l - 1, old))};
	// the centre of a face, then of a volume: a cell of level l around v
	// holding an old corner, whose cell of level l - 1 gives the lines of
	// the corners, each once, in the order its darts meet them
	const auto corners_of = [&](auto cell_below) {
		foreach_dart_of_orbit(below, cell_below, [&](Dart x) {
			const uint32 line = mr_line_of(s, l - 1, vertex, x);
			if (std::find(parents.begin(), parents.end(), line) == parents.end())
				parents.push_back(line);
		});
	};
	foreach_dart_of_orbit(here, MRMap3::Vertex(v), [&](Dart d) {
		foreach_dart_of_orbit(here, MRMap3::Face2(d), [&](Dart x) {
			if (level[x.index] < l)
				old = x;
			return !old.is_valid();
		});
		return !old.is_valid();
	});
	if (old.is_valid())
	{
		corners_of(MRMap3::Face2(old));
		return parents;
	}
	// a volume around v holding an old corner (an octahedron's centre is
	// also a corner of tetrahedra made of new darts only)
	foreach_dart_of_orbit(here, MRMap3::Vertex(v), [&](Dart d) {
		foreach_dart_of_orbit(here, MRMap3::Volume(d), [&](Dart x) {
			if (level[x.index] < l)
				old = x;
			return !old.is_valid();
		});
		return !old.is_valid();
	});
	if (old.is_valid())
		corners_of(MRMap3::Volume(old));
	return parents;
}

template <typename S>
void mr_index_cells_at(S& s, uint32 slot, uint32 l)
{
	using D = MRDim<S>;
	AttributeContainer& c = mr_slot_container(s, slot);
	AttributeArray<uint32>& index = *s.cells[slot].index;
	const auto level = s.level->view();
	// the cells first: writing lines while finding cells would change what
	// the next cells read
	std::vector<Dart> cells;
	mr_foreach_cell_of_slot(s, slot, l, [&](Dart d) { cells.push_back(d); });
	std::vector<double> weights;
	for (Dart d : cells)
	{
		// a dart of the cell that the level below has, and whether the cell
		// is the same there
		Dart old;
		uint32 nb_old = 0, nb_new = 0;
		mr_foreach_dart_of_cell(s, slot, l, d, [&](Dart x) {
			if (l > 0 && level[x.index] < l)
			{
				++nb_old;
				if (!old.is_valid())
					old = x;
			}
			else
				++nb_new;
		});
		uint32 line = INVALID_INDEX;
		if (l == 0)
			line = mr_add_line(s, slot, 0, d, INVALID_INDEX);
		else if (slot == D::vertex_slot)
		{
			// a vertex gets a line at every level
			if (old.is_valid())
				line = mr_add_line(s, slot, l, old, mr_line_of(s, l - 1, slot, old));
			else
			{
				line = mr_add_line(s, slot, l, d, INVALID_INDEX);
				if (c.has_rules())
				{
					const std::vector<uint32> parents = mr_vertex_parents(s, l, d);
					weights.assign(parents.size(), parents.empty() ? 0.0 : 1.0 / double(parents.size()));
					if (!parents.empty())
						c.apply_rules(line, parents, weights);
				}
			}
		}
		else
		{
			// a child without a dart of its parent reads it through a sibling
			if (!old.is_valid())
				old = old_dart_of_sibling(s, slot, l, d);
			const uint32 below = old.is_valid() ? mr_line_of(s, l - 1, slot, old) : INVALID_INDEX;
			uint32 nb_below = 0;
			if (old.is_valid())
				mr_foreach_dart_of_cell(s, slot, l - 1, old, [&](Dart) { ++nb_below; });
			// the same cell as below: all its darts of the level below are in it,
			// and (for an edge) it has no new dart
			const bool same = slot == D::component_slot ||
							  (old.is_valid() && nb_old == nb_below && (slot != D::edge_slot || nb_new == 0));
			line = same ? below : mr_add_line(s, slot, l, d, below);
		}
		mr_foreach_dart_of_cell(s, slot, l, d, [&](Dart x) { index[x.index] = line; });
	}
}

template <typename S>
void mr_unindex_cells_at(S& s, uint32 slot, uint32 l)
{
	MRCellIndex& ci = s.cells[slot];
	AttributeContainer& c = mr_slot_container(s, slot);
	foreach_dart(s.map, [&](Dart d) {
		const uint32 i = (*ci.index)[d.index];
		if (i != INVALID_INDEX && (*ci.level)[i] == l)
			(*ci.index)[d.index] = (*ci.down)[i];
	});
	const auto key = c.key().view();
	for (uint32 i = 0, end = c.end_index(); i < end; ++i)
	{
		if (key[i] == INVALID_INDEX)
			continue;
		if ((*ci.level)[i] == l)
			c.release_line(i);
		else if ((*ci.replaced)[i] == l)
			(*ci.replaced)[i] = MR_NOT_REPLACED;
	}
}

template <typename S>
void mr_index_new_orbit(S& s, Orbit o)
{
	const uint32 slot = MRDim<S>::slot(o);
	AttributeContainer& darts = *state_of(s.map).darts;
	auto index = darts.add_attribute<uint32>("__mr_index_" + std::string(orbit_name(o)), INVALID_INDEX);
	s.cells[slot].index = index.get();
	state_of(s.map).cells[orbit_index(o)]->set_cell_index(index.get());
	mr_add_slot_attributes(s, slot);
	for (uint32 l = 0; l < s.darts_per_level.size(); ++l)
		mr_index_cells_at(s, slot, l);
}

template <typename S>
void mr_take_over_indexing(S& s)
{
	using D = MRDim<S>;
	for (uint32 slot = 0; slot < D::orbits.size(); ++slot)
	{
		AttributeArray<uint32>*& flat = state_of(s.map).cell_index[orbit_index(D::orbits[slot])];
		if (flat == nullptr)
			continue;
		s.cells[slot].index = flat;
		flat = nullptr;
		mr_add_slot_attributes(s, slot);
	}
}

template <typename S>
void mr_write_line(S& s, uint32 slot, Dart d, uint32 i)
{
	using D = MRDim<S>;
	AttributeArray<uint32>& index = *s.cells[slot].index;
	[&]<std::size_t... I>(std::index_sequence<I...>)
	{
		(void)((slot == I
					? (foreach_dart_of_orbit(s.map, Cell<D::orbits[I]>(d), [&](Dart x) { index[x.index] = i; }), true)
					: false) ||
			   ...);
	}
	(std::make_index_sequence<D::orbits.size()>{});
}

namespace
{
/// In the chain of vertex x: the line read at level l, and the finer line
/// that refines it (INVALID_INDEX when it is the newest).
struct ChainPlace
{
	uint32 line, above;
};
template <typename S>
ChainPlace chain_place(const S& s, Dart x, uint32 l)
{
	const MRCellIndex& ci = s.cells[MRDim<S>::vertex_slot];
	ChainPlace p{(*ci.index)[x.index], INVALID_INDEX};
	while ((*ci.level)[p.line] > l)
	{
		p.above = p.line;
		p.line = (*ci.down)[p.line];
	}
	return p;
}
} // namespace

template <typename S>
void mr_ensure_vertex_line(S& s, Dart x, uint32 l)
{
	constexpr uint32 vertex = MRDim<S>::vertex_slot;
	MRCellIndex& ci = s.cells[vertex];
	const auto [i, above] = chain_place(s, x, l);
	if ((*ci.level)[i] == l)
		return;
	const uint32 n = mr_add_line(s, vertex, l, x, i);
	if (above != INVALID_INDEX)
	{
		(*ci.down)[above] = n;
		(*ci.replaced)[n] = (*ci.level)[above];
	}
	else
		mr_write_line(s, vertex, x, n);
}

template <typename S>
void mr_drop_vertex_line(S& s, Dart x, uint32 l)
{
	constexpr uint32 vertex = MRDim<S>::vertex_slot;
	MRCellIndex& ci = s.cells[vertex];
	const auto [i, above] = chain_place(s, x, l);
	if ((*ci.level)[i] != l || (*ci.down)[i] == INVALID_INDEX)
		return;
	const uint32 below = (*ci.down)[i];
	if (above != INVALID_INDEX)
	{
		(*ci.down)[above] = below;
		(*ci.replaced)[below] = (*ci.level)[above];
	}
	else
	{
		mr_write_line(s, vertex, x, below);
		(*ci.replaced)[below] = MR_NOT_REPLACED;
	}
	mr_slot_container(s, vertex).release_line(i);
}

namespace
{
template <typename S, Orbit O>
void copy_cells(const S& s, uint32 l, typename MRDim<S>::Flat& flat, const std::vector<Dart>& source)
{
	using CELL = Cell<O>;
	constexpr uint32 slot = MRDim<S>::slot(O);
	if (s.cells[slot].index == nullptr)
		return;
	const AttributeContainer& from = mr_slot_container(s, slot);
	std::vector<std::pair<const AttributeBase*, std::shared_ptr<AttributeBase>>> copies;
	for (const auto& a : from.attributes())
		if (a.get() != &from.key() && a->name().rfind("__", 0) != 0)
		{
			if (!is_indexed<CELL>(flat))
				index_cells<CELL>(flat);
			copies.emplace_back(a.get(), a->clone_empty(container_of<O>(flat)));
		}
	if (copies.empty())
		return;
	foreach_cell(flat, [&](CELL c) {
		const uint32 src = mr_line_of(s, l, slot, source[c.dart.index]);
		const uint32 dst = index_of(flat, c);
		for (auto& [a, b] : copies)
			b->copy_line_from(dst, *a, src);
	});
}
} // namespace

template <typename S>
void mr_copy_cell_attributes(const S& s, uint32 slot, uint32 l, typename MRDim<S>::Flat& flat,
							 const std::vector<Dart>& source)
{
	using D = MRDim<S>;
	[&]<std::size_t... I>(std::index_sequence<I...>)
	{
		(void)((slot == I ? (copy_cells<S, D::orbits[I]>(s, l, flat, source), true) : false) || ...);
	}
	(std::make_index_sequence<D::orbits.size()>{});
}

template void mr_foreach_cell_of_slot(const MRState2&, uint32, uint32, const std::function<void(Dart)>&);
template uint32 mr_add_line(MRState2&, uint32, uint32, Dart, uint32);
template void mr_add_slot_attributes(MRState2&, uint32);
template void mr_index_cells_at(MRState2&, uint32, uint32);
template void mr_unindex_cells_at(MRState2&, uint32, uint32);
template void mr_take_over_indexing(MRState2&);
template void mr_index_new_orbit(MRState2&, Orbit);
template void mr_copy_cell_attributes(const MRState2&, uint32, uint32, CMap2&, const std::vector<Dart>&);
template void mr_write_line(MRState2&, uint32, Dart, uint32);
template void mr_ensure_vertex_line(MRState2&, Dart, uint32);
template void mr_drop_vertex_line(MRState2&, Dart, uint32);

template void mr_foreach_cell_of_slot(const MRState3&, uint32, uint32, const std::function<void(Dart)>&);
template uint32 mr_add_line(MRState3&, uint32, uint32, Dart, uint32);
template void mr_add_slot_attributes(MRState3&, uint32);
template void mr_index_cells_at(MRState3&, uint32, uint32);
template void mr_unindex_cells_at(MRState3&, uint32, uint32);
template void mr_take_over_indexing(MRState3&);
template void mr_index_new_orbit(MRState3&, Orbit);
template void mr_copy_cell_attributes(const MRState3&, uint32, uint32, CMap3&, const std::vector<Dart>&);
template void mr_write_line(MRState3&, uint32, Dart, uint32);
template void mr_ensure_vertex_line(MRState3&, Dart, uint32);
template void mr_drop_vertex_line(MRState3&, Dart, uint32);

} // namespace cgogn::detail
