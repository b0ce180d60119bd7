// SPDX-License-Identifier: MIT
// NumPy arrays over the library's attributes and vectors, for every binding:
// the dtype and row shape of a value type, attribute values as (aliasing)
// arrays, values written back, and vectors moved into arrays; and the dict
// of an integrity report, which every map class returns.
#pragma once

#include <cgogn/core/attributes/attribute.h>
#include <cgogn/core/properties/integrity.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <string>
#include <type_traits>
#include <vector>

namespace py = pybind11;

namespace cgogn::python
{

/// The NumPy dtype and per-row shape of an attribute value type: a scalar
/// (one value per row), or a vector of `components` values (rows of an
/// (n, components) array) when `vector` is true.
template <typename T>
struct ValueLayout
{
	using Scalar = T;
	static constexpr int components = 1;
	static constexpr bool vector = false;
};
/// Fixed-size arrays of doubles, such as the PointD<K> positions of the maps
/// of any dimension: rows of K float64, even for K = 1.
template <std::size_t K>
struct ValueLayout<std::array<double, K>>
{
	using Scalar = double;
	static constexpr int components = int(K);
	static constexpr bool vector = true;
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
	static_assert(sizeof(T) == L::components * sizeof(S), "the values of a row are not contiguous");
	std::vector<py::ssize_t> shape{py::ssize_t(rows)};
	std::vector<py::ssize_t> strides{py::ssize_t(sizeof(T))};
	if constexpr (L::vector)
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
	const bool ok = !L::vector ? (v.ndim() == 1 && v.shape(0) == rows)
							   : (v.ndim() == 2 && v.shape(0) == rows && v.shape(1) == L::components);
	if (!ok)
		throw py::value_error("values must have shape (" + std::to_string(rows) +
							  (L::vector ? ", " + std::to_string(L::components) : std::string()) + ")");
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

/// The NumPy dtype name of the values of an attribute of type T (a vector
/// type: its components' dtype, float64).
template <typename T>
const char* dtype_name()
{
	if constexpr (std::is_same_v<T, float>)
		return "float32";
	else if constexpr (std::is_same_v<T, int8>)
		return "int8";
	else if constexpr (std::is_same_v<T, uint8>)
		return "uint8";
	else if constexpr (std::is_same_v<T, std::int16_t>)
		return "int16";
	else if constexpr (std::is_same_v<T, uint16>)
		return "uint16";
	else if constexpr (std::is_same_v<T, int32>)
		return "int32";
	else if constexpr (std::is_same_v<T, uint32>)
		return "uint32";
	else if constexpr (std::is_same_v<T, int64>)
		return "int64";
	else if constexpr (std::is_same_v<T, uint64>)
		return "uint64";
	else if constexpr (std::is_same_v<T, bool>)
		return "bool";
	else
		return "float64";
}

/// A check_integrity report as a dict: ok, nb_errors and the messages.
inline py::dict integrity_report(const IntegrityReport& r)
{
	py::list messages;
	for (const auto& e : r.errors)
		messages.append(e.message);
	py::dict d;
	d["ok"] = r.ok();
	d["nb_errors"] = r.nb_errors;
	d["messages"] = messages;
	return d;
}

} // namespace cgogn::python
