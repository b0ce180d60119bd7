// SPDX-License-Identifier: MIT
// Whole-surface operators of 2-maps: closed polyhedra, removal of a
// component, orientation, merge of maps.
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/properties/properties.h>

#include "attribute_copy.h"
#include "index_lines.h"

namespace cgogn
{

namespace
{
constexpr Orbit V = Orbit::PHI21;

std::vector<Dart> new_cycle(CMap2& m, uint32 n)
{
	std::vector<Dart> darts(n);
	for (auto& d : darts)
		d = detail::add_dart(m);
	for (uint32 i = 0; i < n; ++i)
		detail::set_phi1(m, darts[i], darts[(i + 1) % n]);
	return darts;
}

void index_all(CMap2& m, const std::vector<std::vector<Dart>>& faces)
{
	std::vector<Dart> all;
	for (const auto& f : faces)
		all.insert(all.end(), f.begin(), f.end());
	detail::index_new_darts(m, all);
}
} // namespace

CMap2::Volume add_pyramid(CMap2& m, uint32 n, bool set_indices)
{
	assert(n >= 3);
	// base b_i: v_i -> v_i+1; side triangle i: (v_i+1 -> v_i, v_i -> apex, apex -> v_i+1)
	std::vector<std::vector<Dart>> faces;
	faces.push_back(new_cycle(m, n));
	for (uint32 i = 0; i < n; ++i)
		faces.push_back(new_cycle(m, 3));
	for (uint32 i = 0; i < n; ++i)
	{
		phi2_sew(m, faces[0][i], faces[1 + i][0]);
		phi2_sew(m, faces[1 + i][1], faces[1 + (i + n - 1) % n][2]);
	}
	if (set_indices)
		index_all(m, faces);
	return CMap2::Volume(faces[0][0]);
}

CMap2::Volume add_prism(CMap2& m, uint32 n, bool set_indices)
{
	assert(n >= 3);
	// bottom b_i: v_i -> v_i+1; top t_i: w_i+1 -> w_i; quad i: (v_i+1 -> v_i, v_i -> w_i, w_i -> w_i+1, w_i+1 -> v_i+1)
	std::vector<std::vector<Dart>> faces;
	faces.reserve(n + 2);
	faces.push_back(new_cycle(m, n));
	faces.push_back(new_cycle(m, n));
	const std::vector<Dart>& top = faces[1];
	// top cycle order must be t_i -> t_i-1: reverse the cycle
	for (uint32 i = 0; i < n; ++i)
		detail::set_phi1(m, top[i], top[(i + n - 1) % n]);
	for (uint32 i = 0; i < n; ++i)
		faces.push_back(new_cycle(m, 4));
	for (uint32 i = 0; i < n; ++i)
	{
		const std::vector<Dart>& q = faces[2 + i];
		phi2_sew(m, faces[0][i], q[0]);
		phi2_sew(m, q[1], faces[2 + (i + n - 1) % n][3]);
		phi2_sew(m, q[2], top[i]);
	}
	if (set_indices)
		index_all(m, faces);
	return CMap2::Volume(faces[0][0]);
}

CMap2::Volume add_tetra(CMap2& m, bool set_indices)
{
	return add_pyramid(m, 3, set_indices);
}

CMap2::Volume add_hexa(CMap2& m, bool set_indices)
{
	return add_prism(m, 4, set_indices);
}

void remove_volume(CMap2& m, CMap2::Volume w)
{
	std::vector<Dart> darts;
	foreach_dart_of_orbit(m, w, [&](Dart d) { darts.push_back(d); });
	for (uint32 o = 0; o < NB_ORBITS; ++o)
	{
		const AttributeArray<uint32>* idx = detail::state_of(m).cell_index[o];
		if (idx == nullptr)
			continue;
		AttributeContainer& c = *detail::state_of(m).cells[o];
		for (Dart d : darts)
		{
			const uint32 i = (*idx)[d.index];
			if (i != INVALID_INDEX && c.is_live(i))
				c.release_line(i);
		}
	}
	for (Dart d : darts)
		detail::remove_dart(m, d);
}

void reverse_orientation(CMap2& m)
{
	// phi1 becomes phi_1; a dart now starts where its old phi1 started
	std::vector<uint32> prev(detail::state_of(m).darts->end_index(), INVALID_INDEX);
	foreach_dart(m, [&](Dart d) { prev[phi1(m, d).index] = d.index; });
	AttributeArray<uint32>* vidx = detail::state_of(m).cell_index[orbit_index(V)];
	std::vector<uint32> new_vertex;
	if (vidx)
	{
		new_vertex.resize(detail::state_of(m).darts->end_index());
		foreach_dart(m, [&](Dart d) { new_vertex[d.index] = (*vidx)[phi1(m, d).index]; });
	}
	foreach_dart(m, [&](Dart d) { detail::set_phi1(m, d, Dart(prev[d.index])); });
	if (vidx)
	{
		foreach_dart(m, [&](Dart d) { (*vidx)[d.index] = new_vertex[d.index]; });
		// a representative now starts at its old end: its old predecessor starts at the vertex
		AttributeContainer& vc = *detail::state_of(m).cells[orbit_index(V)];
		for (uint32 i = 0; i < vc.end_index(); ++i)
			if (vc.is_live(i))
				vc.key()[i] = phi1(m, Dart(vc.key()[i])).index;
	}
}

std::vector<Dart> merge(CMap2& m, const CMap2& other)
{
	// an orbit indexed in other but not in m: m's cells get lines first, so
	// that once the orbit is indexed every cell of m has one
	[&]<typename... C>(std::tuple<C...>*) {
		(
			[&] {
				if constexpr (C::ORBIT != Orbit::DART)
					if (detail::state_of(other).cell_index[orbit_index(C::ORBIT)] != nullptr &&
						detail::state_of(m).cell_index[orbit_index(C::ORBIT)] == nullptr)
						index_cells<C>(m);
			}(),
			...);
	}(static_cast<mesh_traits<CMap2>::Cells*>(nullptr));
	std::vector<Dart> copy(detail::state_of(other).darts->end_index());
	foreach_dart(other, [&](Dart d) { copy[d.index] = detail::add_dart(m); });
	foreach_dart(other, [&](Dart d) {
		const Dart c = copy[d.index];
		detail::set_phi1(m, c, copy[phi1(other, d).index]);
		detail::set_phi2(m, c, copy[phi2(other, d).index]);
		detail::set_boundary(m, c, is_boundary(other, d));
	});
	// attributes of darts
	detail::copy_attributes(*detail::state_of(other).darts, *detail::state_of(m).darts,
							[&](uint32 i, const auto& put) { put(copy[i].index); });
	// indexed orbits of other: one new line per line, written on the copied darts
	for (uint32 o = 0; o < NB_ORBITS; ++o)
	{
		const AttributeArray<uint32>* oidx = detail::state_of(other).cell_index[o];
		if (oidx == nullptr)
			continue;
		AttributeArray<uint32>& midx = detail::index_attribute(m, Orbit(o));
		const AttributeContainer& oc = *detail::state_of(other).cells[o];
		AttributeContainer& mc = *detail::state_of(m).cells[o];
		std::vector<uint32> line(oc.end_index(), INVALID_INDEX);
		for (uint32 i = 0; i < oc.end_index(); ++i)
			if (oc.is_live(i))
				line[i] = mc.new_line(copy[oc.key()[i]].index);
		foreach_dart(other, [&](Dart d) {
			const uint32 i = (*oidx)[d.index];
			midx[copy[d.index].index] = i == INVALID_INDEX ? INVALID_INDEX : line[i];
		});
		detail::copy_attributes(oc, mc, [&](uint32 i, const auto& put) { put(line[i]); });
	}
	// orbits indexed in m but not in other: index the new cells
	std::vector<Dart> new_darts;
	foreach_dart(other, [&](Dart d) { new_darts.push_back(copy[d.index]); });
	detail::index_new_darts(m, new_darts);
	return copy;
}

} // namespace cgogn
