// SPDX-License-Identifier: MIT
// The core layer of cgogn: maps, attributes, markers, traversals, properties,
// operators, builders. Include <cgogn/cgogn.h> for every layer.
#pragma once

#include <cgogn/core/builder/generators.h>
#include <cgogn/core/builder/map_builder.h>
#include <cgogn/core/functions/attributes.h>
#include <cgogn/core/functions/darts.h>
#include <cgogn/core/functions/incidence_cache.h>
#include <cgogn/core/functions/indexing.h>
#include <cgogn/core/functions/integrity.h>
#include <cgogn/core/functions/orbits.h>
#include <cgogn/core/functions/properties.h>
#include <cgogn/core/functions/traversals/global.h>
#include <cgogn/core/functions/traversals/local_cmap2.h>
#include <cgogn/core/functions/traversals/local_cmap3.h>
#include <cgogn/core/functions/traversals/local_views.h>
#include <cgogn/core/functions/traversals/parallel.h>
#include <cgogn/core/operators/cmap1.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/operators/creation.h>
#include <cgogn/core/operators/dimension_guards.h>
#include <cgogn/core/operators/maintenance.h>
#include <cgogn/core/parallel/thread_pool.h>
#include <cgogn/core/types/error.h>
#include <cgogn/core/types/maps/mesh_traits.h>
#include <cgogn/core/types/marker.h>
#include <cgogn/core/types/views/cell_cache.h>
#include <cgogn/core/types/views/cell_filter.h>
