// SPDX-License-Identifier: MIT
#pragma once

// cgogn's topology-changing workloads (surface subdivision, collapse,
// dynamic; volume split, collapse) use the operators of these headers.
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/operators/maintenance.h>

// The "cgogn_quick" mode: the read-only workloads run again with the quick
// incidence caches built (IncidenceCache), their build time reported as the
// separate benchmarks surface|volume/cache_build/cgogn_quick.
#include <cgogn/core/traversals/incidence_cache.h>
