// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/map/graph.h>
#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/core/map/nmap.h>

#include <concepts>
#include <tuple>
#include <utility>

namespace cgogn
{

/// Everything generic code needs to know about a mesh type: its dimension,
/// its cell types and its attribute type. Specialized for every map and view.
template <typename MESH>
struct mesh_traits;

/// The traits of a 1-map.
template <>
struct mesh_traits<CMap1>
{
	static constexpr uint32 dimension = 1; ///< The dimension of the map.
	using MapType = CMap1;                 ///< The map type (for a view: the type of the map under it).
	using Vertex = CMap1::Vertex;          ///< See CMap1::Vertex.
	using Edge = CMap1::Edge;              ///< See CMap1::Edge.
	using Face = CMap1::Face;              ///< See CMap1::Face.
	/// The distinct cell types (Edge is Vertex): views keep one predicate or
	/// cell set per entry.
	using Cells = std::tuple<Vertex, Face>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// The traits of a 2-map.
template <>
struct mesh_traits<CMap2>
{
	static constexpr uint32 dimension = 2; ///< The dimension of the map.
	using MapType = CMap2;                 ///< The map type (for a view: the type of the map under it).
	using HalfEdge = CMap2::HalfEdge;      ///< See CMap2::HalfEdge.
	using Vertex = CMap2::Vertex;          ///< See CMap2::Vertex.
	using Edge = CMap2::Edge;              ///< See CMap2::Edge.
	using Face = CMap2::Face;              ///< See CMap2::Face.
	using Volume = CMap2::Volume;          ///< See CMap2::Volume.
	/// The cell types: views keep one predicate or cell set per entry.
	using Cells = std::tuple<HalfEdge, Vertex, Edge, Face, Volume>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// The traits of a 3-map.
template <>
struct mesh_traits<CMap3>
{
	static constexpr uint32 dimension = 3; ///< The dimension of the map.
	using MapType = CMap3;                 ///< The map type (for a view: the type of the map under it).
	using HalfEdge = CMap3::HalfEdge;      ///< See CMap3::HalfEdge.
	using Vertex = CMap3::Vertex;          ///< See CMap3::Vertex.
	using Vertex2 = CMap3::Vertex2;        ///< See CMap3::Vertex2.
	using Edge = CMap3::Edge;              ///< See CMap3::Edge.
	using Edge2 = CMap3::Edge2;            ///< See CMap3::Edge2.
	using Face = CMap3::Face;              ///< See CMap3::Face.
	using Face2 = CMap3::Face2;            ///< See CMap3::Face2.
	using Volume = CMap3::Volume;          ///< See CMap3::Volume.
	using CC = CMap3::CC;                  ///< See CMap3::CC.
	/// The cell types: views keep one predicate or cell set per entry.
	using Cells = std::tuple<HalfEdge, Vertex, Vertex2, Edge, Edge2, Face, Face2, Volume, CC>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// The traits of a 1-G-map.
template <>
struct mesh_traits<GMap1>
{
	static constexpr uint32 dimension = 1; ///< The dimension of the map.
	using MapType = GMap1;                 ///< The map type.
	using Vertex = GMap1::Vertex;          ///< See GMap1::Vertex.
	using Edge = GMap1::Edge;              ///< See GMap1::Edge.
	using Face = GMap1::Face;              ///< See GMap1::Face.
	/// The cell types: views keep one predicate or cell set per entry.
	using Cells = std::tuple<Vertex, Edge, Face>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// The traits of a 2-G-map.
template <>
struct mesh_traits<GMap2>
{
	static constexpr uint32 dimension = 2; ///< The dimension of the map.
	using MapType = GMap2;                 ///< The map type.
	using Vertex = GMap2::Vertex;          ///< See GMap2::Vertex.
	using Edge = GMap2::Edge;              ///< See GMap2::Edge.
	using Face = GMap2::Face;              ///< See GMap2::Face.
	using Volume = GMap2::Volume;          ///< See GMap2::Volume.
	/// The cell types: views keep one predicate or cell set per entry.
	using Cells = std::tuple<Vertex, Edge, Face, Volume>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// The traits of a 3-G-map.
template <>
struct mesh_traits<GMap3>
{
	static constexpr uint32 dimension = 3; ///< The dimension of the map.
	using MapType = GMap3;                 ///< The map type.
	using Vertex = GMap3::Vertex;          ///< See GMap3::Vertex.
	using Vertex2 = GMap3::Vertex2;        ///< See GMap3::Vertex2.
	using Edge = GMap3::Edge;              ///< See GMap3::Edge.
	using Edge2 = GMap3::Edge2;            ///< See GMap3::Edge2.
	using Face = GMap3::Face;              ///< See GMap3::Face.
	using Face2 = GMap3::Face2;            ///< See GMap3::Face2.
	using Volume = GMap3::Volume;          ///< See GMap3::Volume.
	using CC = GMap3::CC;                  ///< See GMap3::CC.
	/// The cell types: views keep one predicate or cell set per entry.
	using Cells = std::tuple<Vertex, Vertex2, Edge, Edge2, Face, Face2, Volume, CC>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// The traits of a graph.
template <>
struct mesh_traits<Graph>
{
	static constexpr uint32 dimension = 1; ///< The dimension of the map.
	using MapType = Graph;                 ///< The map type.
	using Vertex = Graph::Vertex;          ///< See Graph::Vertex.
	using Edge = Graph::Edge;              ///< See Graph::Edge.
	/// The cell types: views keep one predicate or cell set per entry.
	using Cells = std::tuple<Vertex, Edge>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// The traits of an incidence graph.
template <>
struct mesh_traits<IncidenceGraph>
{
	static constexpr uint32 dimension = 2; ///< The dimension of the complex.
	using MapType = IncidenceGraph;        ///< The map type.
	using Vertex = IncidenceGraph::Vertex; ///< See IncidenceGraph::Vertex.
	using Edge = IncidenceGraph::Edge;     ///< See IncidenceGraph::Edge.
	using Face = IncidenceGraph::Face;     ///< See IncidenceGraph::Face.
	/// The cell types: views keep one predicate or cell set per entry.
	using Cells = std::tuple<Vertex, Edge, Face>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

namespace detail
{
template <uint32 D, typename IS>
struct dimension_cells;
template <uint32 D, std::size_t... I>
struct dimension_cells<D, std::index_sequence<I...>>
{
	using type = std::tuple<CellD<uint32(I)>...>;
};
} // namespace detail

/// The traits of a map of any dimension, combinatorial or generalized.
template <typename MAP>
requires is_nmap_v<MAP>
struct mesh_traits<MAP>
{
	static constexpr uint32 dimension = MAP::dimension; ///< The dimension of the map.
	using MapType = MAP;                                ///< The map type.
	using Vertex = CellD<0>;                            ///< A vertex.
	using Edge = CellD<1>;                              ///< An edge.
	/// The cell types, CellD<0> ... CellD<D>: views keep one predicate or cell set per entry.
	using Cells = typename detail::dimension_cells<MAP::dimension, std::make_index_sequence<MAP::dimension + 1>>::type;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// True for the generalized maps (GMap1, GMap2, GMap3, GMapN), whose relations are the
/// involutions beta_i; false for the combinatorial maps and the views.
template <typename M>
inline constexpr bool is_gmap_v = std::derived_from<M, GMap1> || is_gmapn<M>::value;

namespace detail
{
template <typename MAP, uint32 I>
struct cell_of_dimension;
template <typename MAP, uint32 I>
requires is_nmap_v<MAP>
struct cell_of_dimension<MAP, I>
{
	using type = CellD<I>;
};
template <typename MAP, uint32 I>
requires(!is_nmap_v<MAP> && std::derived_from<MAP, CMapBase>) struct cell_of_dimension<MAP, I>
{
	static_assert(I <= MAP::dimension, "no cell of this dimension in this map");
	using type = std::tuple_element_t<
		I, std::tuple<typename MAP::Vertex, typename MAP::Edge, typename MAP::Face, typename MAP::Volume>>;
};
template <typename MAP>
requires(!is_nmap_v<MAP> && std::derived_from<MAP, CMapBase> && MAP::dimension == 1) struct cell_of_dimension<MAP, 0>
{
	using type = typename MAP::Vertex;
};
template <typename MAP>
requires(!is_nmap_v<MAP> && std::derived_from<MAP, CMapBase> && MAP::dimension == 1) struct cell_of_dimension<MAP, 1>
{
	using type = typename MAP::Edge;
};
} // namespace detail

/// The cell type of dimension I of a map: CellD<I> in a CMapN or GMapN;
/// Vertex, Edge, Face, Volume (I = 0 ... 3) in the maps of dimension 1 to 3,
/// up to their dimension. Generic code written with it runs on every map.
template <typename MAP, uint32 I>
using cell_of_dimension_t = typename detail::cell_of_dimension<MAP, I>::type;

/// A type usable as a mesh by generic algorithms: a map or a view on one.
template <typename M>
concept MeshType = requires
{
	{
		mesh_traits<M>::dimension
		} -> std::convertible_to<uint32>;
	typename mesh_traits<M>::Vertex;
	typename mesh_traits<M>::MapType;
};

/// One of the combinatorial map types (not a view).
template <typename M>
concept MapType = std::derived_from<M, CMapBase> && MeshType<M>;

template <typename M>
concept SurfaceMesh = MeshType<M> && mesh_traits<M>::dimension == 2;
template <typename M>
concept VolumeMesh = MeshType<M> && mesh_traits<M>::dimension == 3;

/// True when CELL is one of the cell types of MESH.
template <typename MESH, typename CELL>
inline constexpr bool has_cell_type_v = []<typename... C>(std::tuple<C...>*) {
	return (std::is_same_v<CELL, C> || ...);
}(static_cast<typename mesh_traits<MESH>::Cells*>(nullptr));

} // namespace cgogn
