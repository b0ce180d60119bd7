// SPDX-License-Identifier: MIT
// The geometry layer of cgogn (Eigen): vector types and geometric functions.
#pragma once

#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>
