// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/dart_geometry.h>

#include <vector>

namespace cgogn::geometry
{

/// A dense numbering 0..n-1 of the vertices of a mesh, for matrices and
/// solvers: vertex lines (index_of) may have holes after removals, matrix rows
/// may not. Valid until vertices are added or removed.
struct VertexNumbering
{
	/// Dense number of each vertex line (INVALID_INDEX for free lines).
	std::vector<uint32> dense_of_line_;
	/// Vertex line of each dense number.
	std::vector<uint32> line_of_dense_;

	/// Number of vertices numbered.
	uint32 size() const
	{
		return uint32(line_of_dense_.size());
	}
	/// Dense number of the vertex of line `line`. O(1).
	uint32 operator[](uint32 line) const
	{
		return dense_of_line_[line];
	}
};

/// Numbers the vertices of m densely in the order of their lines (the
/// identity when the vertex container has no free line). O(number of
/// vertices). Precondition: vertices are indexed (e.g. carry positions).
template <GeometricMesh MESH>
VertexNumbering vertex_numbering(const MESH& m)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	VertexNumbering n;
	const uint32 end = container_of<Vertex::ORBIT>(map_of(m)).end_index();
	n.dense_of_line_.assign(end, INVALID_INDEX);
	n.line_of_dense_.reserve(nb_cells<Vertex>(m));
	for (uint32 i = 0; i < end; ++i)
		if (container_of<Vertex::ORBIT>(map_of(m)).is_live(i))
		{
			n.dense_of_line_[i] = uint32(n.line_of_dense_.size());
			n.line_of_dense_.push_back(i);
		}
	return n;
}

} // namespace cgogn::geometry
