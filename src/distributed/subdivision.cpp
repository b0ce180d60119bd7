// SPDX-License-Identifier: MIT
// Distributed volume refinement. Each rank cuts every local volume with the
// serial patterns (refinement_patterns.h) and lists the children it keeps:
// its owned volumes' children, and the children sharing a vertex with them
// (the new ghost layer: all of them are children of the old one). Then it
// rebuilds its map from that list, as distribute() builds a part.
//
// A new cell lies inside one old cell, its carrier. Every rank holding the
// carrier holds the whole volume around it, so it lists all the carrier's
// children, and numbers them the same way: by their sorted vertex ids.
#include <cgogn/core/traversals/global.h>
#include <cgogn/distributed/subdivision.h>
#include <cgogn/modeling/refinement_patterns.h>
#include <cgogn/modeling/subdivision.h>

#include "collective_failure.h"
#include "part_columns.h"
#include "rebuild_part.h"
#include "refinement_scheme.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace cgogn::dist
{

namespace
{

using Vertex = CMap3::Vertex;
using Edge = CMap3::Edge;
using Face = CMap3::Face;
using Volume = CMap3::Volume;
using detail::NO_GID;
using namespace detail::refinement;

class PartRefiner
{
public:
	PartRefiner(const DistributedCMap3& dm, const AttributeArray<Vec3>& pos, const Scheme& scheme,
				const std::array<uint64, 4>& bound)
		: dm_(dm), m_(dm.map()), pos_(pos), scheme_(scheme), hex_(scheme.nb_points == 27),
		  point_mask_(point_masks(hex_))
	{
		for (uint32 j = 0; j < 4; ++j)
			for (uint32 k = 0; k < 4; ++k)
				offset_[j][k] = k == 0 ? 0 : offset_[j][k - 1] + scheme.counts[j][k - 1] * bound[k - 1];
		detail::foreach_cell_type<CMap3>([&](auto cell, uint32 k) {
			vertex_of_[k].assign(container_of<decltype(cell)::ORBIT>(m_).end_index(), INVALID_INDEX);
		});
	}

	/// The part of this rank after refinement, as distribute() sends it.
	detail::PartMessage message(const std::string& position)
	{
		// every point of an owned volume lies in one of its children
		foreach_cell(m_, [&](Volume w) {
			const Local l = refine(w);
			if (dist::is_owned(dm_, w))
				for (uint32 p = 0; p < scheme_.nb_points; ++p)
					near_owned_[l.vertex[p]] = 1;
		});
		detail::PartMessage msg;
		std::vector<uint32> msg_vertex(vertex_gid_.size(), INVALID_INDEX), parent_lines;
		std::vector<Vec3> positions;
		// at most 8 children per volume, their corners
		const std::size_t cells = 8 * std::size_t(nb_cells<Volume>(m_)), corners = cells * (hex_ ? 24 : 12);
		for (auto* v : {&msg.cell_gid, &msg.corner_gid[0], &msg.corner_gid[1]})
			v->reserve(v == &msg.cell_gid ? cells : corners);
		for (auto* v : {&msg.cell_owner, &msg.corner_owner[0], &msg.corner_owner[1]})
			v->reserve(v == &msg.cell_owner ? cells : corners);
		msg.cell_nb_faces.reserve(cells);
		msg.face_sizes.reserve(cells * scheme_.child_faces.size());
		msg.corner_vertex.reserve(corners);
		parent_lines.reserve(cells);
		msg.vertex_gid.reserve(vertex_gid_.size());
		msg.vertex_owner.reserve(vertex_gid_.size());
		positions.reserve(vertex_gid_.size());
		foreach_cell(m_, [&](Volume w) {
			Local l = refine(w);
			bool any_kept = false;
			for (const auto& child : l.children)
				any_kept = any_kept || kept(l, child);
			if (!any_kept)
				return;
			number_children(w, l);
			for (uint32 c = 0; c < 8; ++c)
			{
				if (!kept(l, l.children[c]))
					continue;
				msg.cell_gid.push_back(l.child_gid[c]);
				msg.cell_owner.push_back(dist::owner(dm_, w));
				msg.cell_nb_faces.push_back(uint32(scheme_.child_faces.size()));
				parent_lines.push_back(index_of(m_, w));
				for (const auto& face : scheme_.child_faces)
				{
					const uint32 n = uint32(face.size());
					msg.face_sizes.push_back(n);
					const Child& f = l.find_face(child_face(l, l.children[c], face));
					for (uint32 i = 0; i < n; ++i)
					{
						const uint32 p = l.children[c][face[i]], q = l.children[c][face[(i + 1) % n]];
						const uint32 v = l.vertex[p];
						if (msg_vertex[v] == INVALID_INDEX)
						{
							msg_vertex[v] = uint32(msg.vertex_gid.size());
							msg.vertex_gid.push_back(vertex_gid_[v]);
							msg.vertex_owner.push_back(vertex_owner_[v]);
							positions.push_back(vertex_position_[v]);
						}
						msg.corner_vertex.push_back(msg_vertex[v]);
						const Child& e = l.find_edge(child_edge(l, p, q));
						msg.corner_gid[0].push_back(e.gid);
						msg.corner_owner[0].push_back(l.owner_of(e.mask, dm_));
						msg.corner_gid[1].push_back(f.gid);
						msg.corner_owner[1].push_back(l.owner_of(f.mask, dm_));
					}
				}
			}
		});
		add_position_column(msg, position, positions);
		detail::add_columns(msg, container_of<Volume::ORBIT>(m_), parent_lines, 1, "volume");
		name_other_attributes(msg, position);
		return msg;
	}

private:
	/// The refinement of one old volume.
	struct Local
	{
		std::array<uint32, 27> vertex{}; ///< new vertex of each point
		std::array<uint64, 27> gid{};    ///< its global id
		std::array<std::array<uint32, 8>, 8> children{};
		std::array<uint64, 8> child_gid{};
		/// The old cells of the volume a new cell can lie in (at most 19 for
		/// a hexahedron: its edges, faces and itself), no allocation per volume.
		std::array<Carrier, 32> carriers{};
		uint32 nb_carriers = 0;
		void add_carrier(const Carrier& c)
		{
			carriers[nb_carriers++] = c;
		}
		std::vector<Child> edges, faces;

		const Carrier& carrier(uint8 mask) const
		{
			for (uint32 i = 0; i < nb_carriers; ++i)
				if (const Carrier& c = carriers[i]; c.mask == mask)
					return c;
			throw std::logic_error("distributed subdivision: a new cell lies in no old cell");
		}
		int32 owner_of(uint8 mask, const DistributedCMap3& dm) const
		{
			const Carrier& c = carrier(mask);
			return dm.owners(c.dim)[c.line];
		}
		const Child& find_edge(const Child& e) const
		{
			return *std::lower_bound(edges.begin(), edges.end(), e);
		}
		const Child& find_face(const Child& f) const
		{
			return *std::lower_bound(faces.begin(), faces.end(), f);
		}
	};

	uint32 line_of(const modeling::RefinementPoint& p) const
	{
		switch (p.dim)
		{
		case 0:
			return index_of(m_, Vertex(p.dart));
		case 1:
			return index_of(m_, Edge(p.dart));
		case 2:
			return index_of(m_, Face(p.dart));
		default:
			return index_of(m_, Volume(p.dart));
		}
	}

	/// The mean of the positions of the vertices of `lines`, added in
	/// increasing global id so that every rank gets the same bits.
	Vec3 centroid(std::vector<uint32>& lines) const
	{
		const auto& gid = dm_.global_ids(0);
		std::sort(lines.begin(), lines.end(), [&](uint32 a, uint32 b) { return gid[a] < gid[b]; });
		Vec3 sum = Vec3::Zero();
		for (uint32 l : lines)
			sum += pos_[l];
		return sum / double(lines.size());
	}

	/// The position of the new vertex at point p of volume w.
	Vec3 position_of(const modeling::RefinementPoint& p, const std::array<modeling::RefinementPoint, 27>& points) const
	{
		std::vector<uint32> lines;
		switch (p.dim)
		{
		case 0:
			return pos_[index_of(m_, Vertex(p.dart))];
		case 1:
			return 0.5 * (pos_[index_of(m_, Vertex(p.dart))] + pos_[index_of(m_, Vertex(phi1(m_, p.dart)))]);
		case 2: {
			Dart d = p.dart;
			do
			{
				lines.push_back(index_of(m_, Vertex(d)));
				d = phi1(m_, d);
			} while (d != p.dart);
			return centroid(lines);
		}
		default:
			for (uint32 i = 0; i < scheme_.nb_points; ++i)
				if (points[i].dim == 0)
					lines.push_back(index_of(m_, Vertex(points[i].dart)));
			return centroid(lines);
		}
	}

	/// The points, their new vertices (made on first sight) and the children
	/// of volume w.
	Local refine(Volume w)
	{
		std::array<modeling::RefinementPoint, 27> points;
		if (hex_)
			points = modeling::hex_refinement_points(m_, w);
		else
		{
			const auto tet = modeling::tet_refinement_points(m_, w);
			std::copy(tet.begin(), tet.end(), points.begin());
		}
		Local l;
		for (uint32 p = 0; p < scheme_.nb_points; ++p)
		{
			const uint32 k = points[p].dim, line = line_of(points[p]);
			uint32& v = vertex_of_[k][line];
			if (v == INVALID_INDEX)
			{
				v = uint32(vertex_gid_.size());
				vertex_gid_.push_back(offset_[0][k] + dm_.global_ids(k)[line]);
				vertex_owner_.push_back(dm_.owners(k)[line]);
				vertex_position_.push_back(position_of(points[p], points));
				near_owned_.push_back(0);
			}
			l.vertex[p] = v;
			l.gid[p] = vertex_gid_[v];
			if (k > 0)
				l.add_carrier({point_mask_[p], uint8(k), line});
		}
		if (hex_)
			l.children = modeling::hex_children();
		else
		{
			const auto& children = modeling::tet_children(cut_diagonal(l));
			for (uint32 c = 0; c < 8; ++c)
				std::copy(children[c].begin(), children[c].end(), l.children[c].begin());
			// the faces and the volume hold no point of the tetrahedron's refinement
			const Dart d0 = points[0].dart, d1 = points[2].dart, d2 = points[1].dart;
			for (const Dart f : {d0, phi2(m_, d0), phi2(m_, d1), phi2(m_, d2)})
				l.add_carrier({face_mask(f, points), 2, index_of(m_, Face(f))});
			l.add_carrier({15, 3, index_of(m_, w)});
		}
		return l;
	}

	/// The corners of a tetrahedron's face f.
	uint8 face_mask(Dart f, const std::array<modeling::RefinementPoint, 27>& points) const
	{
		uint8 mask = 0;
		Dart d = f;
		do
		{
			const uint32 line = index_of(m_, Vertex(d));
			for (uint32 i = 0; i < 4; ++i)
				if (index_of(m_, Vertex(points[i].dart)) == line)
					mask = uint8(mask | (1u << i));
			d = phi1(m_, d);
		} while (d != f);
		return mask;
	}

	/// The octahedron diagonal modeling::tet_subdivision cuts along.
	uint32 cut_diagonal(const Local& l) const
	{
		std::array<Vec3, 10> at;
		for (uint32 i = 0; i < 10; ++i)
			at[i] = vertex_position_[l.vertex[i]];
		return modeling::tet_cut_diagonal(at);
	}

	bool kept(const Local& l, const std::array<uint32, 8>& child) const
	{
		for (uint32 i = 0; i < scheme_.child_size; ++i)
			if (near_owned_[l.vertex[child[i]]])
				return true;
		return false;
	}

	Child child_edge(const Local& l, uint32 p, uint32 q) const
	{
		Child e{uint8(point_mask_[p] | point_mask_[q]),
				{std::min(l.gid[p], l.gid[q]), std::max(l.gid[p], l.gid[q]), NO_GID, NO_GID}};
		return e;
	}

	Child child_face(const Local& l, const std::array<uint32, 8>& child, const std::vector<uint32>& face) const
	{
		Child f{0, {NO_GID, NO_GID, NO_GID, NO_GID}};
		for (uint32 i = 0; i < face.size(); ++i)
		{
			f.mask = uint8(f.mask | point_mask_[child[face[i]]]);
			f.vertices[i] = l.gid[child[face[i]]];
		}
		std::sort(f.vertices.begin(), f.vertices.end());
		return f;
	}

	/// Numbers the children of each dimension j inside each carrier k: the
	/// offset of j in k, plus count x the carrier's id, plus the rank among
	/// the carrier's children by sorted vertex ids.
	void number(const Local& l, std::vector<Child>& children, uint32 j) const
	{
		std::sort(children.begin(), children.end());
		children.erase(std::unique(children.begin(), children.end()), children.end());
		for (std::size_t first = 0; first < children.size();)
		{
			std::size_t last = first;
			while (last < children.size() && children[last].mask == children[first].mask)
				++last;
			const Carrier& c = l.carrier(children[first].mask);
			const uint64 count = scheme_.counts[j][c.dim];
			if (last - first != count)
				throw std::logic_error("distributed subdivision: an old cell has the wrong number of children");
			for (std::size_t i = first; i < last; ++i)
				children[i].gid = offset_[j][c.dim] + count * dm_.global_ids(c.dim)[c.line] + (i - first);
			first = last;
		}
	}

	void number_children(Volume w, Local& l) const
	{
		for (const auto& child : l.children)
			for (const auto& face : scheme_.child_faces)
			{
				l.faces.push_back(child_face(l, child, face));
				for (uint32 i = 0; i < face.size(); ++i)
					l.edges.push_back(child_edge(l, child[face[i]], child[face[(i + 1) % face.size()]]));
			}
		number(l, l.edges, 1);
		number(l, l.faces, 2);
		// the volume's children by their sorted vertex ids
		std::array<std::pair<std::array<uint64, 8>, uint32>, 8> keys;
		for (uint32 c = 0; c < 8; ++c)
		{
			keys[c].first.fill(NO_GID);
			for (uint32 i = 0; i < scheme_.child_size; ++i)
				keys[c].first[i] = l.gid[l.children[c][i]];
			std::sort(keys[c].first.begin(), keys[c].first.end());
			keys[c].second = c;
		}
		std::sort(keys.begin(), keys.end());
		const uint64 base = offset_[3][3] + 8 * dist::global_id(dm_, w);
		for (uint32 i = 0; i < 8; ++i)
			l.child_gid[keys[i].second] = base + i;
	}

	static void add_position_column(detail::PartMessage& msg, const std::string& name,
									const std::vector<Vec3>& positions)
	{
		detail::PartMessage::Column& col = msg.columns.emplace_back();
		col.name = name;
		col.of_top_cells = 0;
		col.type = detail::carried_type_index<Vec3>();
		col.values.resize(positions.size() * sizeof(Vec3));
		if (!positions.empty())
			std::memcpy(col.values.data(), positions.data(), col.values.size());
	}

	void name_other_attributes(detail::PartMessage& msg, const std::string& position) const
	{
		msg.not_carried = dm_.not_carried();
		const AttributeContainer& vertices = container_of<Vertex::ORBIT>(m_);
		for (const auto& a : vertices.attributes())
			if (a.get() != &vertices.key() && !cgogn::detail::is_reserved_name(a->name()) && a->name() != position)
				msg.not_carried.push_back("vertex attribute '" + a->name() + "' (no value for the new vertices)");
		std::vector<std::string> names;
		detail::name_attributes_of<Edge>(m_, names, "edge");
		detail::name_attributes_of<Face>(m_, names, "face");
		for (std::string& name : names)
			if (std::find(msg.not_carried.begin(), msg.not_carried.end(), name) == msg.not_carried.end())
				msg.not_carried.push_back(std::move(name));
		std::sort(msg.not_carried.begin(), msg.not_carried.end());
		msg.not_carried.erase(std::unique(msg.not_carried.begin(), msg.not_carried.end()), msg.not_carried.end());
	}

	const DistributedCMap3& dm_;
	const CMap3& m_;
	const AttributeArray<Vec3>& pos_;
	const Scheme& scheme_;
	const bool hex_;
	const std::array<uint8, 27> point_mask_;
	uint64 offset_[4][4] = {};
	std::array<std::vector<uint32>, 4> vertex_of_; ///< by old line, per dimension
	std::vector<uint64> vertex_gid_;
	std::vector<int32> vertex_owner_;
	std::vector<Vec3> vertex_position_;
	std::vector<uint8> near_owned_;
};

void refine(DistributedCMap3& dm, const std::string& position, const Scheme& scheme,
			bool (*every_volume_fits)(const CMap3&))
{
	const CMap3& m = dm.map();
	auto pos = get_attribute<Vec3, Vertex>(m, position);
	if (!detail::on_all_ranks(dm.comm(), pos != nullptr))
		throw std::invalid_argument("distributed subdivision: a rank has no Vec3 vertex attribute '" + position + "'");
	if (!detail::on_all_ranks(dm.comm(), every_volume_fits(m)))
		throw modeling::SubdivisionError(scheme.wrong_cells);

	// the ids of each dimension are below bound[k] on every rank
	std::array<uint64, 4> bound{};
	detail::foreach_cell_type<CMap3>([&](auto cell, uint32 k) {
		foreach_cell(m, [&](decltype(cell) c) { bound[k] = std::max(bound[k], dist::global_id(dm, c) + 1); });
	});
	MPI_Allreduce(MPI_IN_PLACE, bound.data(), 4, MPI_UINT64_T, MPI_MAX, dm.comm());

	detail::PartMessage msg;
	detail::on_every_rank(dm.comm(), [&] { msg = PartRefiner(dm, *pos, scheme, bound).message(position); });
	DistributedCMap3 refined;
	detail::on_every_rank(dm.comm(), [&] { detail::build_part(refined, dm.rank(), msg); });
	msg = detail::PartMessage();
	refined.finish(dm.comm());
	dm = std::move(refined);
}

} // namespace

void tet_subdivision(DistributedCMap3& dm, const std::string& position)
{
	refine(dm, position, tet_scheme, &modeling::is_tet_mesh);
}

void hex_subdivision(DistributedCMap3& dm, const std::string& position)
{
	refine(dm, position, hex_scheme, &modeling::is_hex_mesh);
}

} // namespace cgogn::dist
