// SPDX-License-Identifier: MIT
// The io layer of cgogn: surface, volume, graph and n-map files in and out.
#pragma once

#include <cgogn/geometry.h>
#include <cgogn/io/error.h>
#include <cgogn/io/graph.h>
#include <cgogn/io/incidence_graph.h>
#include <cgogn/io/map_file.h>
#include <cgogn/io/nmap.h>
#include <cgogn/io/options.h>
#include <cgogn/io/surface.h>
#include <cgogn/io/volume.h>
