// SPDX-License-Identifier: MIT
// The attribute classes of the integer value types (see attribute_instances.h).
#include <cgogn/core/attributes/attribute_container.h>

CGOGN_ATTRIBUTE_CLASSES(, bool)
CGOGN_ATTRIBUTE_CLASSES(, cgogn::int8)
CGOGN_ATTRIBUTE_CLASSES(, cgogn::uint8)
CGOGN_ATTRIBUTE_CLASSES(, std::int16_t)
CGOGN_ATTRIBUTE_CLASSES(, cgogn::uint16)
CGOGN_ATTRIBUTE_CLASSES(, cgogn::int32)
CGOGN_ATTRIBUTE_CLASSES(, cgogn::uint32)
CGOGN_ATTRIBUTE_CLASSES(, cgogn::int64)
CGOGN_ATTRIBUTE_CLASSES(, cgogn::uint64)
