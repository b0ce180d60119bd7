// SPDX-License-Identifier: MIT
// The attribute classes of the arrays of doubles, the points of the maps of
// any dimension (see attribute_instances.h).
#include <cgogn/core/attributes/attribute_container.h>

CGOGN_ATTRIBUTE_CLASSES(, std::array<double, 1>)
CGOGN_ATTRIBUTE_CLASSES(, std::array<double, 2>)
CGOGN_ATTRIBUTE_CLASSES(, std::array<double, 3>)
CGOGN_ATTRIBUTE_CLASSES(, std::array<double, 4>)
CGOGN_ATTRIBUTE_CLASSES(, std::array<double, 5>)
CGOGN_ATTRIBUTE_CLASSES(, std::array<double, 6>)
CGOGN_ATTRIBUTE_CLASSES(, std::array<double, 7>)
CGOGN_ATTRIBUTE_CLASSES(, std::array<double, 8>)
