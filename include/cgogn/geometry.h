// SPDX-License-Identifier: MIT
// The geometry layer of cgogn (Eigen): vector types and geometric functions.
#pragma once

#include <cgogn/core.h>
#include <cgogn/geometry/algos/angle.h>
#include <cgogn/geometry/algos/area.h>
#include <cgogn/geometry/algos/bilateral_normal_filtering.h>
#include <cgogn/geometry/algos/bounding_box.h>
#include <cgogn/geometry/algos/centroid.h>
#include <cgogn/geometry/algos/dart_geometry.h>
#include <cgogn/geometry/algos/gaussian_curvature.h>
#include <cgogn/geometry/algos/implicit_smoothing.h>
#include <cgogn/geometry/algos/laplacian.h>
#include <cgogn/geometry/algos/laplacian_smoothing.h>
#include <cgogn/geometry/algos/length.h>
#include <cgogn/geometry/algos/mean_curvature.h>
#include <cgogn/geometry/algos/morton.h>
#include <cgogn/geometry/algos/normal.h>
#include <cgogn/geometry/algos/principal_curvature.h>
#include <cgogn/geometry/algos/vertex_numbering.h>
#include <cgogn/geometry/algos/volume.h>
#include <cgogn/geometry/algos/voronoi_area.h>
#include <cgogn/geometry/types/vector_traits.h>
