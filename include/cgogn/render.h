// SPDX-License-Identifier: MIT
// The render layer of cgogn: software rendering of surfaces and of volume
// mesh boundaries into PNG pictures (no GPU, no display).
#pragma once

#include <cgogn/render/render.h>
