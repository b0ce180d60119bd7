// SPDX-License-Identifier: MIT
// PNG output through libpng, written to a temporary file then renamed so that
// a failed write never leaves a truncated picture under the requested name.
#include "scene.h"

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <png.h>
#include <string>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace cgogn::render
{

namespace
{

/// libpng reports errors by longjmp: this function holds no object with a
/// destructor across setjmp, so that the jump skips nothing. Returns the
/// error text, empty on success.
std::string encode(FILE* f, const Image& img, png_bytep* rows)
{
	static thread_local char message[256];
	message[0] = '\0';
	png_structp png = png_create_write_struct(
		PNG_LIBPNG_VER_STRING, nullptr,
		[](png_structp p, png_const_charp msg) {
			std::snprintf(message, sizeof(message), "%s", msg);
			png_longjmp(p, 1);
		},
		[](png_structp, png_const_charp) {});
	if (png == nullptr)
		return "cannot create the PNG encoder";
	png_infop info = png_create_info_struct(png);
	if (info == nullptr)
	{
		png_destroy_write_struct(&png, nullptr);
		return "cannot create the PNG encoder";
	}
	if (setjmp(png_jmpbuf(png)))
	{
		png_destroy_write_struct(&png, &info);
		return message[0] != '\0' ? message : "PNG encoding failed";
	}
	png_init_io(png, f);
	png_set_IHDR(png, info, img.width, img.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
				 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	png_set_compression_level(png, 6);
	png_write_info(png, info);
	png_write_image(png, rows);
	png_write_end(png, nullptr);
	png_destroy_write_struct(&png, &info);
	return {};
}

} // namespace

void write_png(const Image& img, const std::string& path)
{
	if (img.width == 0 || img.height == 0 || img.rgb.size() != std::size_t(img.width) * img.height * 3)
		throw RenderError(path + ": cannot write an empty or malformed image");
	std::vector<png_bytep> rows(img.height);
	for (uint32_t y = 0; y < img.height; ++y)
		rows[y] = const_cast<png_bytep>(img.rgb.data() + std::size_t(y) * img.width * 3);

	detail::write_file(path, [&](FILE* f) { return encode(f, img, rows.data()); });
}

namespace detail
{

void write_file(const std::string& path, const std::function<std::string(FILE*)>& body)
{
	// the temporary file is in the target's folder, so that the rename stays
	// on one file system and is atomic
	const std::string tmp = path + ".tmp" + std::to_string(::getpid());
	FILE* f = std::fopen(tmp.c_str(), "wb");
	if (f == nullptr)
		throw RenderError(path + ": cannot write (" + std::strerror(errno) + ")");
	std::string error = body(f);
	if (std::fflush(f) != 0 && error.empty())
		error = std::strerror(errno);
	if (std::fclose(f) != 0 && error.empty())
		error = std::strerror(errno);
	std::error_code ec;
	if (error.empty())
	{
		std::filesystem::rename(tmp, path, ec);
		if (ec)
			error = ec.message();
	}
	if (!error.empty())
	{
		std::filesystem::remove(tmp, ec);
		throw RenderError(path + ": cannot write (" + error + ")");
	}
}

} // namespace detail

} // namespace cgogn::render
