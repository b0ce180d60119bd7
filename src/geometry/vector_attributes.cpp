// SPDX-License-Identifier: MIT
// The attribute classes of the geometry layer's vector types, which
// vector_traits.h declares extern (see attribute_instances.h).
#include <cgogn/geometry/types/vector_traits.h>

CGOGN_ATTRIBUTE_CLASSES(, cgogn::Vec2)
CGOGN_ATTRIBUTE_CLASSES(, cgogn::Vec3)
CGOGN_ATTRIBUTE_CLASSES(, cgogn::Vec4)
