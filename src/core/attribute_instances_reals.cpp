// SPDX-License-Identifier: MIT
// The attribute classes of the floating-point and string value types (see
// attribute_instances.h).
#include <cgogn/core/attributes/attribute_container.h>

CGOGN_ATTRIBUTE_CLASSES(, float)
CGOGN_ATTRIBUTE_CLASSES(, double)
CGOGN_ATTRIBUTE_CLASSES(, std::string)
