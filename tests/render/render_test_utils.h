// SPDX-License-Identifier: MIT
// Shared by the render tests: reading a PNG back with libpng, independently
// of the renderer's writer.
#pragma once

#include <cgogn/render/render.h>

#include <png.h>
#include <string>

namespace cgogn::render_test
{

/// The picture in path as 8-bit RGB; width 0 when it is not a readable PNG.
inline render::Image read_png(const std::string& path)
{
	render::Image img;
	png_image pi{};
	pi.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&pi, path.c_str()))
		return img;
	pi.format = PNG_FORMAT_RGB;
	std::vector<uint8_t> buf(PNG_IMAGE_SIZE(pi));
	if (!png_image_finish_read(&pi, nullptr, buf.data(), 0, nullptr))
	{
		png_image_free(&pi);
		return img;
	}
	img.width = pi.width;
	img.height = pi.height;
	img.rgb = std::move(buf);
	return img;
}

inline int distance(render::Rgb a, render::Rgb b)
{
	return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

} // namespace cgogn::render_test
