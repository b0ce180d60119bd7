// SPDX-License-Identifier: MIT
// What the Python bindings share: the map wrapper (a map, its positions and
// the NumPy views handed out), cell kinds by name, and arrays over attributes.
#pragma once

#include <cgogn/cgogn.h>

#include <algorithm>
#include <memory>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <string>
#include <vector>

namespace py = pybind11;

namespace cgogn::python
{

/// A map as Python sees it: the map, its `position` vertex attribute (created
/// when missing) and weak references to the NumPy arrays that alias its
/// attributes' memory (so that compaction, which gives memory back, can
/// refuse to run while one of them is alive).
template <typename MAP>
struct PyMap
{
	MAP m;
	std::shared_ptr<AttributeArray<Vec3>> pos;
	std::vector<py::object> views; // weakrefs

	PyMap()
	{
		ensure_position();
	}
	PyMap(const PyMap&) = delete;
	PyMap& operator=(const PyMap&) = delete;

	void ensure_position()
	{
		using Vertex = typename mesh_traits<MAP>::Vertex;
		pos = get_attribute<Vec3, Vertex>(m, "position");
		if (!pos)
			pos = add_attribute<Vec3, Vertex>(m, "position");
	}
	/// Throws RuntimeError when a view is alive: `what` (compaction, a
	/// rebuild) gives memory back, and the view would point to it.
	void refuse_while_aliased(const char* what)
	{
		if (const std::size_t n = live_views(); n > 0)
			throw std::runtime_error(std::string(what) + ": " + std::to_string(n) +
									 " NumPy array(s) still alias this map's attributes (positions or attribute "
									 "arrays); they would point to released memory. Delete them (del a) or keep "
									 "copies (a.copy()) first.");
	}
	/// Number of views still alive (drops the dead weakrefs).
	std::size_t live_views()
	{
		std::vector<py::object> alive;
		for (auto& w : views)
			if (!w().is_none())
				alive.push_back(w);
		views = std::move(alive);
		return views.size();
	}
};

using Surface = PyMap<CMap2>;
using VolumeMesh = PyMap<CMap3>;
using GSurface = PyMap<GMap2>;
using GVolumeMesh = PyMap<GMap3>;

/// The cell kinds Python names.
enum class Kind
{
	Vertex,
	Edge,
	Face,
	Volume
};

/// "vertex", "edge", "face" or "volume" (plurals accepted); ValueError otherwise.
Kind kind_of(const std::string& name);
const char* kind_name(Kind k);

/// Calls f.template operator()<CELL>() with the cell type of kind k in MAP.
template <typename MAP, typename FUNC>
decltype(auto) with_kind(Kind k, FUNC&& f)
{
	using T = mesh_traits<MAP>;
	switch (k)
	{
	case Kind::Vertex:
		return f.template operator()<typename T::Vertex>();
	case Kind::Edge:
		return f.template operator()<typename T::Edge>();
	case Kind::Face:
		return f.template operator()<typename T::Face>();
	default:
		return f.template operator()<typename T::Volume>();
	}
}

/// The orbit of kind k is indexed (indexes it when it is not: O(darts)).
template <typename MAP>
void ensure_indexed(MAP& m, Kind k)
{
	with_kind<MAP>(k, [&]<typename CELL>() {
		if (!is_indexed<CELL>(m))
			index_cells<CELL>(m);
	});
}

/// Number of rows of the arrays of kind k: one past the largest cell id.
template <typename MAP>
uint32 id_bound(const MAP& m, Kind k)
{
	return with_kind<MAP>(k, [&]<typename CELL>() { return container_of<CELL::ORBIT>(m).end_index(); });
}

/// The NumPy dtype and per-row shape of an attribute value type.
template <typename T>
struct ValueLayout
{
	using Scalar = T;
	static constexpr int components = 1;
};
template <>
struct ValueLayout<Vec2>
{
	using Scalar = double;
	static constexpr int components = 2;
};
template <>
struct ValueLayout<Vec3>
{
	using Scalar = double;
	static constexpr int components = 3;
};
template <>
struct ValueLayout<Vec4>
{
	using Scalar = double;
	static constexpr int components = 4;
};

/// The values of attribute a, one row per line (cell id) of its container,
/// as a NumPy array. Without a copy (writable, aliasing the attribute, kept
/// alive by the array) when the lines' values are at consecutive addresses,
/// which holds below 2^28 lines (and 2 GiB); otherwise a read-only copy.
/// `views` records the aliasing arrays.
template <typename T>
py::array attribute_array(const std::shared_ptr<AttributeArray<T>>& a, uint32 rows, std::vector<py::object>& views)
{
	using L = ValueLayout<T>;
	using S = typename L::Scalar;
	std::vector<py::ssize_t> shape{py::ssize_t(rows)};
	std::vector<py::ssize_t> strides{py::ssize_t(sizeof(T))};
	if constexpr (L::components > 1)
	{
		shape.push_back(L::components);
		strides.push_back(sizeof(S));
	}
	if (rows == 0)
		return py::array(py::dtype::of<S>(), shape);
	if (a->run_end(0) >= rows)
	{
		auto* holder = new std::shared_ptr<AttributeArray<T>>(a);
		py::capsule owner(holder, [](void* p) { delete static_cast<std::shared_ptr<AttributeArray<T>>*>(p); });
		S* data = reinterpret_cast<S*>(&(*a)[0]);
		py::array arr(py::dtype::of<S>(), shape, strides, data, owner);
		if (views.size() >= 64) // drop the references to arrays that are gone
			views.erase(std::remove_if(views.begin(), views.end(), [](const py::object& w) { return w().is_none(); }),
						views.end());
		views.push_back(py::module_::import("weakref").attr("ref")(arr));
		return arr;
	}
	py::array_t<S> copy(shape);
	S* out = copy.mutable_data();
	for (uint32 i = 0; i < rows; ++i)
	{
		const S* v = reinterpret_cast<const S*>(&(*a)[i]);
		for (int c = 0; c < L::components; ++c)
			out[std::size_t(i) * L::components + c] = v[c];
	}
	copy.attr("setflags")(py::arg("write") = false);
	py::array result = copy;
	return result;
}

/// Writes values (rows x components, any numeric dtype NumPy can cast) into a.
template <typename T>
void assign_attribute(AttributeArray<T>& a, uint32 rows, const py::array& values)
{
	using L = ValueLayout<T>;
	using S = typename L::Scalar;
	auto v = py::array_t<S, py::array::c_style | py::array::forcecast>::ensure(values);
	if (!v)
		throw py::type_error("values cannot be converted to the attribute's type");
	const bool ok = L::components == 1 ? (v.ndim() == 1 && v.shape(0) == rows)
									   : (v.ndim() == 2 && v.shape(0) == rows && v.shape(1) == L::components);
	if (!ok)
		throw py::value_error("values must have shape (" + std::to_string(rows) +
							  (L::components > 1 ? ", " + std::to_string(L::components) : std::string()) + ")");
	const S* in = v.data();
	for (uint32 i = 0; i < rows; ++i)
	{
		S* out = reinterpret_cast<S*>(&a[i]);
		for (int c = 0; c < L::components; ++c)
			out[c] = in[std::size_t(i) * L::components + c];
	}
}

/// A (offsets, indices) pair of uint32 arrays: the rows of a CSR relation.
py::tuple csr(std::vector<uint32>&& offsets, std::vector<uint32>&& indices);

/// A vector moved into a 1-D NumPy array without a copy.
template <typename T>
py::array_t<T> to_numpy(std::vector<T>&& v)
{
	auto* heap = new std::vector<T>(std::move(v));
	py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
	return py::array_t<T>({py::ssize_t(heap->size())}, {py::ssize_t(sizeof(T))}, heap->data(), owner);
}

void bind_maps(py::module_& m);
void bind_attributes(py::module_& m);
void bind_operators(py::module_& m);
void bind_algorithms(py::module_& m);

} // namespace cgogn::python
