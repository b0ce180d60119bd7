// SPDX-License-Identifier: MIT
// The attribute classes of the common value types are compiled once, in the
// library (src/core/attribute_instances_*.cpp), not in every file that adds
// or loads an attribute: a value type has a class per orbit, and each class
// compiles its clone and factory functions, which the file readers (any
// orbit, any type of their formats) and the conversions (each class clones
// into the classes of the same cell in the other map families) instantiate
// by the hundred. Included at the end of attribute_container.h.
#pragma once

#include <array>
#include <string>

/// Calls X(PREFIX, O, T...) for every orbit O, T being a value type.
#define CGOGN_FOR_EACH_ORBIT(X, PREFIX, ...)                                                                           \
	X(PREFIX, DART, __VA_ARGS__)                                                                                       \
	X(PREFIX, PHI1, __VA_ARGS__)                                                                                       \
	X(PREFIX, PHI2, __VA_ARGS__)                                                                                       \
	X(PREFIX, PHI21, __VA_ARGS__)                                                                                      \
	X(PREFIX, PHI1_PHI2, __VA_ARGS__)                                                                                  \
	X(PREFIX, PHI1_PHI3, __VA_ARGS__)                                                                                  \
	X(PREFIX, PHI2_PHI3, __VA_ARGS__)                                                                                  \
	X(PREFIX, PHI21_PHI31, __VA_ARGS__)                                                                                \
	X(PREFIX, PHI1_PHI2_PHI3, __VA_ARGS__)                                                                             \
	X(PREFIX, BETA0, __VA_ARGS__)                                                                                      \
	X(PREFIX, BETA1, __VA_ARGS__)                                                                                      \
	X(PREFIX, BETA0_BETA1, __VA_ARGS__)                                                                                \
	X(PREFIX, BETA0_BETA2, __VA_ARGS__)                                                                                \
	X(PREFIX, BETA1_BETA2, __VA_ARGS__)                                                                                \
	X(PREFIX, BETA0_BETA1_BETA2, __VA_ARGS__)                                                                          \
	X(PREFIX, BETA0_BETA1_BETA3, __VA_ARGS__)                                                                          \
	X(PREFIX, BETA0_BETA2_BETA3, __VA_ARGS__)                                                                          \
	X(PREFIX, BETA1_BETA2_BETA3, __VA_ARGS__)                                                                          \
	X(PREFIX, BETA0_BETA1_BETA2_BETA3, __VA_ARGS__)                                                                    \
	X(PREFIX, ALPHA0, __VA_ARGS__)                                                                                     \
	X(PREFIX, ALPHA1, __VA_ARGS__)                                                                                     \
	X(PREFIX, IG_VERTEX, __VA_ARGS__)                                                                                  \
	X(PREFIX, IG_EDGE, __VA_ARGS__)                                                                                    \
	X(PREFIX, CELL0, __VA_ARGS__)                                                                                      \
	X(PREFIX, CELL1, __VA_ARGS__)                                                                                      \
	X(PREFIX, CELL2, __VA_ARGS__)                                                                                      \
	X(PREFIX, CELL3, __VA_ARGS__)                                                                                      \
	X(PREFIX, CELL4, __VA_ARGS__)                                                                                      \
	X(PREFIX, CELL5, __VA_ARGS__)                                                                                      \
	X(PREFIX, CELL6, __VA_ARGS__)                                                                                      \
	X(PREFIX, CELL7, __VA_ARGS__)

static_assert(cgogn::NB_ORBITS == 31, "CGOGN_FOR_EACH_ORBIT names every orbit");

// Of CellAttribute<T, O>, only the functions a class compiles apart from its
// base's: its factory and its clone (the latter instantiates the classes of
// the other orbits of the same cell). Not the whole class, whose explicit
// instantiation would compile out of line the inline accessors of every
// class too.
#define CGOGN_CELL_ATTRIBUTE_MEMBERS(PREFIX, O, ...)                                                                   \
	PREFIX template std::shared_ptr<cgogn::AttributeBase> cgogn::CellAttribute<__VA_ARGS__, cgogn::Orbit::O>::make(    \
		cgogn::AttributeContainer*, std::string, __VA_ARGS__, cgogn::uint64);                                          \
	PREFIX template std::shared_ptr<cgogn::AttributeBase>                                                              \
	cgogn::CellAttribute<__VA_ARGS__, cgogn::Orbit::O>::clone_empty(cgogn::AttributeContainer&) const;

/// `PREFIX template` (PREFIX: extern, or nothing for the definitions) of
/// the class AttributeArray<T> and of the members of CellAttribute<T, O>
/// above for every orbit O.
#define CGOGN_ATTRIBUTE_CLASSES(PREFIX, ...)                                                                           \
	PREFIX template class cgogn::AttributeArray<__VA_ARGS__>;                                                          \
	CGOGN_FOR_EACH_ORBIT(CGOGN_CELL_ATTRIBUTE_MEMBERS, PREFIX, __VA_ARGS__)

/// The value types whose classes the core library compiles (those of the
/// map file formats but the geometry layer's vectors): X(T) for each.
#define CGOGN_FOR_EACH_CORE_VALUE_TYPE(X)                                                                              \
	X(bool)                                                                                                            \
	X(cgogn::int8)                                                                                                     \
	X(cgogn::uint8)                                                                                                    \
	X(std::int16_t)                                                                                                    \
	X(cgogn::uint16)                                                                                                   \
	X(cgogn::int32)                                                                                                    \
	X(cgogn::uint32)                                                                                                   \
	X(cgogn::int64)                                                                                                    \
	X(cgogn::uint64)                                                                                                   \
	X(float)                                                                                                           \
	X(double)                                                                                                          \
	X(std::string)                                                                                                     \
	X(std::array<double, 1>)                                                                                           \
	X(std::array<double, 2>)                                                                                           \
	X(std::array<double, 3>)                                                                                           \
	X(std::array<double, 4>)                                                                                           \
	X(std::array<double, 5>)                                                                                           \
	X(std::array<double, 6>)                                                                                           \
	X(std::array<double, 7>)                                                                                           \
	X(std::array<double, 8>)

#define CGOGN_EXTERN_ATTRIBUTE_CLASSES(...) CGOGN_ATTRIBUTE_CLASSES(extern, __VA_ARGS__)
CGOGN_FOR_EACH_CORE_VALUE_TYPE(CGOGN_EXTERN_ATTRIBUTE_CLASSES)
#undef CGOGN_EXTERN_ATTRIBUTE_CLASSES
