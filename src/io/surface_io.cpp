// SPDX-License-Identifier: MIT
#include <cgogn/io/surface.h>

#include "file_io.h"
#include "formats.h"
#include "map_transfer.h"

namespace cgogn::io
{

namespace
{
Format resolve(Format f, const std::string& path)
{
	if (f == Format::Auto)
		f = format_from_extension(path);
	if (f == Format::Auto)
		throw Error(path, "unknown surface format: use .off, .obj, .ply or .stl, or give the format");
	if (f != Format::Off && f != Format::Obj && f != Format::Ply && f != Format::Stl)
		throw Error(path, std::string(format_name(f)) + " is not a surface format (use load_volume/save_volume)");
	return f;
}

template <typename MAP>
LoadReport load_surface_into(MAP& m, const std::string& path, const LoadOptions& options)
{
	const Format f = resolve(options.format, path);
	const std::string data = detail::read_file(path);
	detail::MeshData d;
	switch (f)
	{
	case Format::Off:
		d = detail::read_off(data, path);
		break;
	case Format::Obj:
		d = detail::read_obj(data, path);
		break;
	case Format::Ply:
		d = detail::read_ply(data, path);
		break;
	default:
		d = detail::read_stl(data, path);
		break;
	}
	detail::validate(d, path);
	LoadReport r = detail::build_map(m, d, path);
	r.format = f;
	return r;
}

template <typename MAP>
void save_surface_of(const MAP& m, const std::string& path, const SaveOptions& options)
{
	const Format f = resolve(options.format, path);
	const detail::MeshData d = detail::extract_surface(m, path, options.attributes);
	std::string out;
	switch (f)
	{
	case Format::Off:
		out = detail::write_off(d);
		break;
	case Format::Obj:
		out = detail::write_obj(d);
		break;
	case Format::Ply:
		detail::check_written_names(d, path);
		out = detail::write_ply(d, options.binary, path);
		break;
	default:
		out = detail::write_stl(d, options.binary);
		break;
	}
	detail::write_file(path, out);
}

} // namespace

LoadReport load_surface(CMap2& m, const std::string& path, const LoadOptions& options)
{
	return load_surface_into(m, path, options);
}

LoadReport load_surface(GMap2& m, const std::string& path, const LoadOptions& options)
{
	return load_surface_into(m, path, options);
}

LoadReport load_surface(IncidenceGraph& ig, const std::string& path, const LoadOptions& options)
{
	return load_surface_into(ig, path, options);
}

void save_surface(const IncidenceGraph& ig, const std::string& path, const SaveOptions& options)
{
	save_surface_of(ig, path, options);
}

void save_surface(const CMap2& m, const std::string& path, const SaveOptions& options)
{
	save_surface_of(m, path, options);
}

void save_surface(const GMap2& m, const std::string& path, const SaveOptions& options)
{
	save_surface_of(m, path, options);
}

} // namespace cgogn::io
