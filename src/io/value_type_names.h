// SPDX-License-Identifier: MIT
// The names that VTK legacy and VTK XML give the value types of columns
// (ValueType), both ways, and what a value of each type may be.
#pragma once

#include "mesh_data.h"

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace cgogn::io::detail
{

/// The ValueType of a VTK legacy data type name (float and double are
/// Float64); nullopt for an unknown name.
std::optional<ValueType> vtk_legacy_value_type(std::string_view name);
/// The VTK legacy name of a value type ("double", "int", "vtktypeint64", ...).
const char* vtk_legacy_type_name(ValueType t);
/// The ValueType of a VTK XML DataArray type (Float32 and Float64 are
/// Float64); nullopt for an unknown name.
std::optional<ValueType> vtu_value_type(std::string_view name);
/// The VTK XML name of a value type ("Float64", "Int32", ...).
const char* vtu_type_name(ValueType t);
/// The name of a value type in errors and reports ("float64", "int32", ...).
const char* value_type_name(ValueType t);

/// Whether v is a value of type t: integral and in t's range for an integer
/// type (and, for 64-bit ones, within +-MAX_EXACT_INTEGER, see Column).
bool holds_value(ValueType t, double v);

/// The values of the first column of `columns` named one of `names` (in
/// that order of preference) that has one component per row, as int32
/// tags; `fallback` on every row when there is none. Throws io::Error
/// naming `path` when a value is not an int32 (a writer's tags: gmsh
/// physical and elementary tags, MEDIT references). O(rows).
std::vector<int32> int32_tags(const std::vector<Column>& columns, std::initializer_list<const char*> names,
							  std::size_t rows, int32 fallback, const std::string& path);

} // namespace cgogn::io::detail
