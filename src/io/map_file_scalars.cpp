// SPDX-License-Identifier: MIT
// The .cgmap attributes of the scalar value types (a TU of its own: each type
// instantiates its attribute class for every orbit).
#include "map_file_typed.h"

namespace cgogn::io::detail
{
template struct AttributeValues<ScalarValueTypes>;
} // namespace cgogn::io::detail
