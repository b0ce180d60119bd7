// SPDX-License-Identifier: MIT
#pragma once

#include <tuple>
#include <type_traits>

namespace cgogn
{

/// Parameter and result types of a callable (lambda, function object,
/// function pointer) with one non-template call operator. Traversals use it to
/// deduce the cell type they visit from the callable's parameter.
template <typename F>
struct function_traits : function_traits<decltype(&std::remove_cvref_t<F>::operator())>
{
};
template <typename R, typename... A>
struct function_traits<R (*)(A...)>
{
	using result_type = R;
	using args = std::tuple<A...>;
	static constexpr std::size_t arity = sizeof...(A);
};
template <typename R, typename... A>
struct function_traits<R(A...)> : function_traits<R (*)(A...)>
{
};
template <typename C, typename R, typename... A>
struct function_traits<R (C::*)(A...) const> : function_traits<R (*)(A...)>
{
};
template <typename C, typename R, typename... A>
struct function_traits<R (C::*)(A...)> : function_traits<R (*)(A...)>
{
};
template <typename C, typename R, typename... A>
struct function_traits<R (C::*)(A...) const noexcept> : function_traits<R (*)(A...)>
{
};
template <typename C, typename R, typename... A>
struct function_traits<R (C::*)(A...) noexcept> : function_traits<R (*)(A...)>
{
};

template <typename F, std::size_t I = 0>
using func_parameter_type =
	std::remove_cvref_t<std::tuple_element_t<I, typename function_traits<std::remove_cvref_t<F>>::args>>;

template <typename F>
using func_result_type = typename function_traits<std::remove_cvref_t<F>>::result_type;

/// Calls f(args...) and says whether a traversal should go on: a callable
/// returning void always goes on, one returning bool stops on false.
template <typename F, typename... A>
inline bool call_and_continue(F&& f, A&&... args)
{
	if constexpr (std::is_same_v<std::invoke_result_t<F, A...>, void>)
	{
		std::forward<F>(f)(std::forward<A>(args)...);
		return true;
	}
	else
	{
		static_assert(std::is_convertible_v<std::invoke_result_t<F, A...>, bool>,
					  "a traversal callable must return void or bool");
		return static_cast<bool>(std::forward<F>(f)(std::forward<A>(args)...));
	}
}

} // namespace cgogn
