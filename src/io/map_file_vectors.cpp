// SPDX-License-Identifier: MIT
// The .cgmap attributes of the vector, array and string value types (a TU of its
// own: each type instantiates its attribute class for every orbit).
#include "map_file_typed.h"

namespace cgogn::io::detail
{
template struct AttributeValues<VectorValueTypes>;
} // namespace cgogn::io::detail
