// SPDX-License-Identifier: MIT
// The io layer of cgogn: surface and volume mesh files in and out.
#pragma once

#include <cgogn/geometry.h>
#include <cgogn/io/error.h>
#include <cgogn/io/nmap.h>
#include <cgogn/io/options.h>
#include <cgogn/io/surface.h>
#include <cgogn/io/volume.h>
