// SPDX-License-Identifier: MIT
// The names that PLY, VTK legacy and VTK XML give the value types of columns
// (ValueType), both ways.
#pragma once

#include "mesh_data.h"

#include <optional>
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

} // namespace cgogn::io::detail
