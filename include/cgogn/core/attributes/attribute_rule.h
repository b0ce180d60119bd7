// SPDX-License-Identifier: MIT
// What a cell created by an operator gets in an attribute: the rules, the
// value types they interpolate, and the default rule of a type.
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <array>
#include <concepts>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>

namespace cgogn
{

/// The rule of an attribute (see attribute_rules.h for which operator gives
/// which parents):
/// - None: new cells hold the attribute's default value;
/// - Copy: a new cell takes the value of its parent (of the parent of
///   largest weight when it has several: a new vertex on an edge takes the
///   value of the edge's first end);
/// - Interpolate: the weighted sum of the parents' values (linear on an
///   edge, barycentric in a face or volume) for linear types (floating-point
///   scalars, Eigen vectors and matrices, std::array of floating-point),
///   Copy for the others;
/// - Callback: a function of the parents' values and weights, set with the
///   rule.
enum class AttributeRule : uint8
{
	None,
	Copy,
	Interpolate,
	Callback
};

namespace detail
{
template <typename T>
struct is_float_array : std::false_type
{
};
template <std::floating_point F, std::size_t N>
struct is_float_array<std::array<F, N>> : std::true_type
{
};
} // namespace detail

/// Types whose values interpolate: floating-point scalars, std::array of
/// them, and classes with `+` and a product by a double that give back the
/// type (Eigen's vectors and matrices).
template <typename T>
concept LinearValue = std::floating_point<T> || detail::is_float_array<T>::value ||
	(!std::is_arithmetic_v<T> && requires(const T& a, double w) { T(a * w + a * w); });

namespace detail
{

/// sum_k w[k] * value(k) for k < n, computed in a temporary (so the result
/// may overwrite a parent). O(n).
template <LinearValue T, typename VALUE>
T linear_combination(std::size_t n, const VALUE& value, std::span<const double> w)
{
	if constexpr (std::floating_point<T>)
	{
		double sum = 0.0;
		for (std::size_t k = 0; k < n; ++k)
			sum += w[k] * double(value(k));
		return T(sum);
	}
	else if constexpr (is_float_array<T>::value)
	{
		T sum{};
		for (std::size_t k = 0; k < n; ++k)
			for (std::size_t i = 0; i < sum.size(); ++i)
				sum[i] += typename T::value_type(w[k] * double(value(k)[i]));
		return sum;
	}
	else
	{
		T sum = T(value(0) * w[0]);
		for (std::size_t k = 1; k < n; ++k)
			sum = T(sum + value(k) * w[k]);
		return sum;
	}
}

/// The index of the largest weight, the first of equals. O(size).
inline std::size_t heaviest(std::span<const double> w)
{
	std::size_t best = 0;
	for (std::size_t k = 1; k < w.size(); ++k)
		if (w[k] > w[best])
			best = k;
	return best;
}

} // namespace detail

/// The rule add_attribute gives a new attribute of type T: Copy for
/// integers, booleans and strings (tags: a child cell is in its parent's
/// region), Interpolate for linear types (colours, texture coordinates,
/// fields), None for the rest (their values stay what they were before
/// rules existed: the default value).
template <typename T>
constexpr AttributeRule default_rule()
{
	if constexpr (std::integral<T> || std::is_same_v<T, std::string>)
		return AttributeRule::Copy;
	else if constexpr (LinearValue<T>)
		return AttributeRule::Interpolate;
	else
		return AttributeRule::None;
}

} // namespace cgogn
