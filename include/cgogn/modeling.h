// SPDX-License-Identifier: MIT
// The modeling layer of cgogn: subdivision, decimation, remeshing, hole
// filling, triangulation, duals (functions of CMap2/CMap3 and Vec3 positions),
// graph resampling.
#pragma once

#include <cgogn/modeling/adaptive_hexahedra.h>
#include <cgogn/modeling/decimation.h>
#include <cgogn/modeling/dual.h>
#include <cgogn/modeling/fairing.h>
#include <cgogn/modeling/graph_resampling.h>
#include <cgogn/modeling/hole_filling.h>
#include <cgogn/modeling/multiresolution.h>
#include <cgogn/modeling/progress.h>
#include <cgogn/modeling/quadric.h>
#include <cgogn/modeling/remeshing.h>
#include <cgogn/modeling/skeleton.h>
#include <cgogn/modeling/subdivision.h>
#include <cgogn/modeling/triangle_tree.h>
#include <cgogn/modeling/triangulation.h>
