// SPDX-License-Identifier: MIT
#include "value_type_names.h"

#include <cgogn/io/error.h>

#include <cmath>
#include <limits>

namespace cgogn::io::detail
{

namespace
{

struct Names
{
	ValueType type;
	const char* vtk_legacy;
	const char* vtu;
	const char* plain;
};

// The canonical names, by ValueType (Float64 first).
constexpr Names NAMES[] = {
	{ValueType::Float64, "double", "Float64", "float64"},      {ValueType::Int8, "char", "Int8", "int8"},
	{ValueType::UInt8, "unsigned_char", "UInt8", "uint8"},     {ValueType::Int16, "short", "Int16", "int16"},
	{ValueType::UInt16, "unsigned_short", "UInt16", "uint16"}, {ValueType::Int32, "int", "Int32", "int32"},
	{ValueType::UInt32, "unsigned_int", "UInt32", "uint32"},   {ValueType::Int64, "vtktypeint64", "Int64", "int64"},
	{ValueType::UInt64, "vtktypeuint64", "UInt64", "uint64"}};

const Names& names_of(ValueType t)
{
	return NAMES[uint32(t)];
}

} // namespace

std::optional<ValueType> vtk_legacy_value_type(std::string_view name)
{
	if (name == "float")
		return ValueType::Float64;
	if (name == "bit")
		return ValueType::UInt8;
	if (name == "vtkIdType")
		return ValueType::Int32;
	if (name == "long")
		return ValueType::Int64;
	if (name == "unsigned_long")
		return ValueType::UInt64;
	for (const Names& n : NAMES)
		if (name == n.vtk_legacy)
			return n.type;
	return std::nullopt;
}

const char* vtk_legacy_type_name(ValueType t)
{
	return names_of(t).vtk_legacy;
}

std::optional<ValueType> vtu_value_type(std::string_view name)
{
	if (name == "Float32")
		return ValueType::Float64;
	for (const Names& n : NAMES)
		if (name == n.vtu)
			return n.type;
	return std::nullopt;
}

const char* vtu_type_name(ValueType t)
{
	return names_of(t).vtu;
}

const char* value_type_name(ValueType t)
{
	return names_of(t).plain;
}

bool holds_value(ValueType t, double v)
{
	if (t == ValueType::Float64)
		return true;
	if (v != std::floor(v)) // NaN and infinities too
		return false;
	return visit_value_type(t, [&]<typename T>() {
		const double lo = std::max(double(std::numeric_limits<T>::lowest()), -MAX_EXACT_INTEGER);
		const double hi = std::min(double(std::numeric_limits<T>::max()), MAX_EXACT_INTEGER);
		return v >= lo && v <= hi;
	});
}

std::vector<int32> int32_tags(const std::vector<Column>& columns, std::initializer_list<const char*> names,
							  std::size_t rows, int32 fallback, const std::string& path)
{
	for (const char* name : names)
		for (const Column& c : columns)
			if (c.name == name && c.dim == 1 && c.values.size() == rows)
			{
				std::vector<int32> tags(rows);
				for (std::size_t i = 0; i < rows; ++i)
				{
					if (!holds_value(ValueType::Int32, c.values[i]))
						throw Error(path, "the attribute '" + c.name + "' holds " + std::to_string(c.values[i]) +
											  ", which is not a 32-bit integer tag");
					tags[i] = int32(c.values[i]);
				}
				return tags;
			}
	return std::vector<int32>(rows, fallback);
}

} // namespace cgogn::io::detail
