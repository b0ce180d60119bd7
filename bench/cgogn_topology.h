// SPDX-License-Identifier: MIT
#pragma once

// REGISTRATION POINT for cgogn's topology-changing workloads (surface
// subdivision, collapse, dynamic; volume split, collapse). They are written
// against the planned operator signatures
//   cut_edge, flip_edge(CMap2&, Edge), edge_can_flip(const CMap2&, Edge),
//   triangulate_face(CMap2&, Face) -> Vertex   (fan around a new vertex),
//   collapse_edge(CMap2&, Edge) -> Vertex,
//   split_tetra(CMap3&, Volume) -> Vertex, collapse_edge(CMap3&, Edge) -> Vertex,
//   compact(m)
// (the operators issue provides them in the headers below).

#if __has_include(<cgogn/core/operators/maintenance.h>) && __has_include(<cgogn/core/operators/cmap2.h>) && \
	__has_include(<cgogn/core/operators/cmap3.h>)
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/operators/maintenance.h>
#define CGOGN_BENCH_HAS_TOPOLOGY 1
#else
#define CGOGN_BENCH_HAS_TOPOLOGY 0
#endif

// The "cgogn_quick" mode: the read-only workloads run again with the quick
// incidence caches built (IncidenceCache), their build time reported as the
// separate benchmarks surface|volume/cache_build/cgogn_quick.
#include <cgogn/core/functions/incidence_cache.h>
