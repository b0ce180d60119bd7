// SPDX-License-Identifier: MIT
// The .cgmap attributes of the scalar value types.
#include "map_file_typed.h"

namespace cgogn::io::detail
{
template struct AttributeValues<ScalarValueTypes>;
} // namespace cgogn::io::detail
