// SPDX-License-Identifier: MIT
#pragma once

#include <tuple>
#include <type_traits>

namespace cgogn
{

/// \cond INTERNAL
// Parameter and result types of a callable (lambda, function object,
// function pointer) with one non-template call operator. Traversals use it to
// deduce the cell type they visit from the callable's parameter.
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

/// \endcond

/// The type of parameter I of callable F (lambda, function object, function
/// pointer with one non-template call operator), without cv-qualifiers or
/// reference. Traversals deduce the cell type they visit from it.
template <typename F, std::size_t I = 0>
using func_parameter_type =
	std::remove_cvref_t<std::tuple_element_t<I, typename function_traits<std::remove_cvref_t<F>>::args>>;

/// The result type of callable F.
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

/// How a traversal holds the callable it calls in its loop: a copy in a local
/// when the callable is small and trivially copyable (a lambda capturing
/// references, pointers or numbers), a reference otherwise. The compiler keeps
/// a local copy's captures in registers for the whole loop; through a
/// reference it reloads them at every cell, since any store or call in the
/// loop might have changed the caller's object. Like the standard algorithms,
/// the traversals may therefore call a copy of f: state kept in a mutable
/// member of a function object is not seen by the caller afterwards (capture
/// a variable by reference instead).
template <typename F>
constexpr bool held_by_copy()
{
	if constexpr (std::is_trivially_copyable_v<F>) // never a function type, whose size is not defined
		return sizeof(F) <= 64;
	else
		return false;
}
template <typename F>
using held_callable_t = std::conditional_t<held_by_copy<F>(), const F, const F&>;

} // namespace cgogn
