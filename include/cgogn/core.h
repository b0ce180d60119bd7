// SPDX-License-Identifier: MIT
// The core layer of cgogn: maps, attributes, markers, traversals, views,
// properties, operators, builders. Include <cgogn/cgogn.h> for every layer.
// Its folders are its concepts: map (darts, relations, orbits, cells, the map
// types, indexing), attributes, marking, traversals, views, properties,
// operators, build, parallel; utils and detail serve them.
#pragma once

#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/build/conversion.h>
#include <cgogn/core/build/generators.h>
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/build/nmap_boundary.h>
#include <cgogn/core/build/nmap_builder.h>
#include <cgogn/core/build/nmap_generators.h>
#include <cgogn/core/map/betas.h>
#include <cgogn/core/map/darts.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/map/graph.h>
#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/map/mrmap2.h>
#include <cgogn/core/map/mrmap2_attributes.h>
#include <cgogn/core/map/mrmap3.h>
#include <cgogn/core/map/mrmap3_attributes.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/operators/cmap1.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/operators/creation.h>
#include <cgogn/core/operators/dimension_guards.h>
#include <cgogn/core/operators/gmap1.h>
#include <cgogn/core/operators/gmap2.h>
#include <cgogn/core/operators/gmap3.h>
#include <cgogn/core/operators/graph.h>
#include <cgogn/core/operators/incidence_graph.h>
#include <cgogn/core/operators/maintenance.h>
#include <cgogn/core/operators/mrmap2.h>
#include <cgogn/core/operators/mrmap3.h>
#include <cgogn/core/operators/nmap.h>
#include <cgogn/core/parallel/thread_pool.h>
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/properties/incidence_graph_properties.h>
#include <cgogn/core/properties/integrity.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/incidence_cache.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/local_dimension.h>
#include <cgogn/core/traversals/local_gmap2.h>
#include <cgogn/core/traversals/local_gmap3.h>
#include <cgogn/core/traversals/local_graph.h>
#include <cgogn/core/traversals/local_incidence_graph.h>
#include <cgogn/core/traversals/local_mrmap2.h>
#include <cgogn/core/traversals/local_mrmap3.h>
#include <cgogn/core/traversals/local_views.h>
#include <cgogn/core/traversals/parallel.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/core/views/cell_cache.h>
#include <cgogn/core/views/cell_filter.h>
