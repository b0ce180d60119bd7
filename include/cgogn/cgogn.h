// SPDX-License-Identifier: MIT
// Everything cgogn provides. Each layer also has its own header.
#pragma once

#include <cgogn/core.h>
#include <cgogn/geometry.h>
#include <cgogn/io.h>
#include <cgogn/modeling.h>
#include <cgogn/render.h>
