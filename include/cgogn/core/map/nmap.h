// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap_base.h>

#include <string>

namespace cgogn
{

/// The i-cell of a map of any dimension (CMapN, GMapN): `CellD<0>` is a
/// vertex, `CellD<1>` an edge, `CellD<2>` a face, `CellD<3>` a volume, ...
template <uint32 I>
requires(I <= MAX_DIMENSION) using CellD = Cell<cell_orbit(I)>;

namespace detail
{

/// The usual names of the cells of a D-dimensional map: Vertex and Edge
/// always, Face from dimension 2 on, Volume from dimension 3 on.
template <uint32 D>
struct NamedCells
{
	using Vertex = CellD<0>; ///< A vertex: CellD<0>.
	using Edge = CellD<1>;   ///< An edge: CellD<1>.
};
template <uint32 D>
requires(D == 2) struct NamedCells<D> : NamedCells<1>
{
	using Face = CellD<2>; ///< A face: CellD<2>.
};
template <uint32 D>
requires(D >= 3) struct NamedCells<D> : NamedCells<2>
{
	using Volume = CellD<3>; ///< A volume: CellD<3>.
};

} // namespace detail

/// A combinatorial map of dimension D (1 <= D <= MAX_DIMENSION), the paper's
/// model for any dimension: phi1 a permutation (the next dart in the face),
/// phi2 ... phiD fixed-point-free involutions gluing cells, with phi1 o phi_j
/// an involution for j >= 3 and phi_i o phi_j one for 2 <= i, i + 2 <= j. For
/// i >= 1 an i-cell is the orbit of the phi_j, j != i; a vertex is the orbit
/// of the phi1 o phi_j, j >= 2 (`CellD<i>`). As the maps of dimension 2 and
/// 3, the map is always closed: the outside is made of boundary D-cells whose
/// darts carry the boundary mark, and global traversals skip them.
///
/// Build one with the builders and generators of cgogn/core/nmap (from
/// simplicial or cubical complexes), or from a CMap2 or CMap3 (to_nmap).
template <uint32 D>
class CMapN : public CMapBase, public detail::NamedCells<D>
{
	static_assert(D >= 1 && D <= MAX_DIMENSION, "CMapN<D>: the dimension must be in [1, MAX_DIMENSION]");

public:
	static constexpr uint32 dimension = D; ///< The dimension of the map.

	/// The i-cells of the map.
	template <uint32 I>
	requires(I <= D) using Cell = CellD<I>;

	CMapN()
	{
		for (uint32 i = 2; i <= D; ++i)
			add_relation("__phi" + std::to_string(i));
	}
};

/// A generalized map of dimension D (1 <= D <= MAX_DIMENSION): D + 1
/// fixed-point-free involutions beta0 ... betaD with beta_i o beta_j an
/// involution for i + 2 <= j, which represents orientable and non-orientable
/// objects alike. An i-cell is the orbit of the beta_j, j != i (`CellD<i>`).
/// As the other G-maps, beta0 is implicit: darts come in pairs (2k, 2k + 1)
/// that are each other's beta0. Closed, with boundary D-cells, as CMapN.
template <uint32 D>
class GMapN : public CMapBase, public detail::NamedCells<D>
{
	static_assert(D >= 1 && D <= MAX_DIMENSION, "GMapN<D>: the dimension must be in [1, MAX_DIMENSION]");

public:
	static constexpr uint32 dimension = D; ///< The dimension of the map.

	/// The i-cells of the map.
	template <uint32 I>
	requires(I <= D) using Cell = CellD<I>;

	GMapN() : CMapBase("__beta1")
	{
		use_key_as_beta1();
		for (uint32 i = 2; i <= D; ++i)
			add_beta_relation("__beta" + std::to_string(i));
	}
};

template <typename M>
struct is_cmapn : std::false_type
{
};
template <uint32 D>
struct is_cmapn<CMapN<D>> : std::true_type
{
};
template <typename M>
struct is_gmapn : std::false_type
{
};
template <uint32 D>
struct is_gmapn<GMapN<D>> : std::true_type
{
};

/// True for the maps of any dimension, CMapN<D> and GMapN<D>.
template <typename M>
inline constexpr bool is_nmap_v = is_cmapn<M>::value || is_gmapn<M>::value;

} // namespace cgogn
