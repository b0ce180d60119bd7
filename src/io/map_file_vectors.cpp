// SPDX-License-Identifier: MIT
// The .cgmap attributes of the vector, array and string value types.
#include "map_file_typed.h"

namespace cgogn::io::detail
{
template struct AttributeValues<VectorValueTypes>;
} // namespace cgogn::io::detail
