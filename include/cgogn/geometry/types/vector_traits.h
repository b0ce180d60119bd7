// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attribute_container.h>

#include <Eigen/Core>

namespace cgogn
{

/// The geometry layer's vector types (Eigen). Positions are Vec3 vertex
/// attributes, conventionally named "position".
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;

/// The same types under cgogn::geometry, where code ported from CGoGN_3
/// looks for them (geometry::Vec3).
namespace geometry
{
using cgogn::Mat3;
using cgogn::Vec2;
using cgogn::Vec3;
using cgogn::Vec4;
} // namespace geometry

} // namespace cgogn

// their attribute classes are compiled in the geometry library
// (src/geometry/vector_attributes.cpp, see attribute_instances.h)
CGOGN_ATTRIBUTE_CLASSES(extern, cgogn::Vec2)
CGOGN_ATTRIBUTE_CLASSES(extern, cgogn::Vec3)
CGOGN_ATTRIBUTE_CLASSES(extern, cgogn::Vec4)
