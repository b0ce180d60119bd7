// SPDX-License-Identifier: MIT
// The body of the libFuzzer targets of the readers, compiled once for all of
// them (fuzz_target.cpp chooses the reader of each target): any input must
// either throw io::Error or give data that builds into a map passing
// check_integrity (a surface into both a CMap2 and a GMap2, a volume mesh into
// both a CMap3 and a GMap3).
// Crashes, leaks and sanitizer reports are bugs.
//
// In append mode the first byte of the input chooses the reader and the rest
// is the file, loaded into a map that already holds a mesh and attributes
// whose names the formats use, with other types: a load that throws must
// leave that map exactly as it was, and one that succeeds must give a map
// passing check_integrity.
#include "fuzz_reader.h"

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/build/generators.h>
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/properties/gmap_properties.h>
#include <cgogn/core/properties/integrity.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/error.h>

#include "formats.h"
#include "map_transfer.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

using namespace cgogn;
using namespace cgogn::io;

namespace
{

enum Kind
{
	OFF,
	OBJ,
	PLY,
	STL,
	MEDIT,
	VTK,
	VTU,
	GMSH,
	TETGEN,
	OVM
};

io::detail::MeshData parse(int kind, std::string_view in, const std::string& path)
{
	switch (kind)
	{
	case OFF:
		return io::detail::read_off(in, path);
	case OBJ:
		return io::detail::read_obj(in, path);
	case PLY:
		return io::detail::read_ply(in, path);
	case STL:
		return io::detail::read_stl(in, path);
	case MEDIT:
		return io::detail::read_medit(in, path);
	case VTK:
		return io::detail::read_vtk(in, path);
	case VTU:
		return io::detail::read_vtu(in, path);
	case GMSH:
		return io::detail::read_gmsh(in, path);
	case OVM:
		return io::detail::read_ovm(in, path);
	default: {
		// the .node and .ele contents, separated by the first NUL byte
		const std::size_t sep = in.find('\0');
		const std::string_view node = in.substr(0, sep);
		const std::string_view ele = sep == std::string_view::npos ? std::string_view() : in.substr(sep + 1);
		return io::detail::read_tetgen(node, path + ".node", ele, path + ".ele");
	}
	}
}

// Attribute names the readers produce, each given a type no file gives it
// (and `position` on faces and volumes, where loading never puts it).
template <typename MAP>
void add_colliding_attributes(MAP& m)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Top =
		std::conditional_t<MAP::dimension == 2, typename mesh_traits<MAP>::Face, typename mesh_traits<MAP>::Volume>;
	add_attribute<double, Vertex>(m, "normal");
	add_attribute<Vec2, Vertex>(m, "color");
	add_attribute<Vec3, Vertex>(m, "tex_coord");
	add_attribute<Vec3, Vertex>(m, "q");
	add_attribute<double, Vertex>(m, "original_vertex");
	add_attribute<uint32, Vertex>(m, "ref");
	add_attribute<Vec2, Top>(m, "normal");
	add_attribute<double, Top>(m, "color");
	add_attribute<Vec3, Top>(m, "q");
	add_attribute<uint32, Top>(m, "ref");
	add_attribute<double, Top>(m, "position");
}

// What a failed load must not change.
template <typename MAP>
struct State
{
	uint32 darts = 0, vertices = 0;
	std::vector<std::string> attributes;
	std::vector<double> positions;
	explicit State(const MAP& m)
	{
		using Vertex = typename mesh_traits<MAP>::Vertex;
		darts = nb_darts(m);
		vertices = nb_cells<Vertex>(m);
		for (const auto& c : cgogn::detail::state_of(m).cells) // every orbit's container
			if (c != nullptr)
				for (const auto& a : c->attributes())
					attributes.push_back(a->name() + ":" + a->type().name());
		auto pos = get_attribute<Vec3, Vertex>(m, "position");
		foreach_cell(m, [&](Vertex v) {
			const Vec3& p = (*pos)[index_of(m, v)];
			positions.insert(positions.end(), {p[0], p[1], p[2]});
		});
	}
	bool operator==(const State&) const = default;
};

template <typename MAP, typename SOUP>
void load_into_non_empty_map(const io::detail::MeshData& d, const SOUP& soup, const std::string& path)
{
	MAP m;
	if constexpr (MAP::dimension == 2)
		build_surface(m, soup);
	else
		build_volume(m, soup);
	using Vertex = typename mesh_traits<MAP>::Vertex;
	auto pos = add_attribute<Vec3, Vertex>(m, "position");
	uint32 i = 0;
	foreach_cell(m, [&](Vertex v) { (*pos)[index_of(m, v)] = Vec3(i, 2.0 * i, 3.0 * i), ++i; });
	add_colliding_attributes(m);
	const State<MAP> before(m);
	try
	{
		io::detail::build_map(m, d, path);
	}
	catch (const io::Error&)
	{
		if (!(State<MAP>(m) == before))
			std::abort(); // a failed load changed the map
	}
	if (!check_integrity(m).ok())
		std::abort();
}

} // namespace

int cgogn_fuzz::run_one_input(int format, const std::uint8_t* data, std::size_t size)
{
	const std::string path = "fuzz-input";
	std::string_view in(reinterpret_cast<const char*>(data), size);
	const bool append = format == append_mode;
	int kind = format;
	if (append)
	{
		if (in.empty())
			return 0;
		kind = int(uint8_t(in[0])) % (OVM + 1);
		in.remove_prefix(1);
	}
	io::detail::MeshData d;
	try
	{
		d = parse(kind, in, path);
		io::detail::validate(d, path);
	}
	catch (const io::Error&)
	{
		return 0;
	}
	const bool volume = kind >= MEDIT;
	if (volume)
		io::detail::orient_cells(d);
	if (append)
	{
		if (volume)
		{
			load_into_non_empty_map<CMap3>(d, tet_grid_soup(1, 1, 1), path);
			load_into_non_empty_map<GMap3>(d, hex_grid_soup(1, 1, 1), path);
		}
		else
		{
			load_into_non_empty_map<CMap2>(d, grid_soup(2, 1, true), path);
			load_into_non_empty_map<GMap2>(d, mobius_soup(3), path);
		}
		return 0;
	}
	try
	{
		if (volume)
		{
			CMap3 m;
			const io::LoadReport rm = io::detail::build_map(m, d, path);
			if (!check_integrity(m).ok())
				std::abort();
			GMap3 g;
			const io::LoadReport rg = io::detail::build_map(g, d, path);
			if (!check_integrity(g).ok() || rg.orientable != is_orientable(g))
				std::abort();
			if (rg.nb_cells_built != rm.nb_cells_built || nb_cells<GMap3::Volume>(g) != nb_cells<CMap3::Volume>(m))
				std::abort(); // both builders build the same cells
		}
		else
		{
			CMap2 m;
			const io::LoadReport rm = io::detail::build_map(m, d, path);
			if (!check_integrity(m).ok())
				std::abort();
			// the incidence graph keeps the file whole: every vertex, the same faces
			IncidenceGraph ig;
			io::detail::build_map(ig, d, path);
			if (!check_integrity(ig).ok() || nb_cells<IncidenceGraph::Face>(ig) != rm.nb_cells_built ||
				nb_cells<IncidenceGraph::Vertex>(ig) != d.nb_vertices())
				std::abort();
			GMap2 g;
			const io::LoadReport rg = io::detail::build_map(g, d, path);
			if (!check_integrity(g).ok() || rg.orientable != is_orientable(g))
				std::abort(); // the report's orientability is the G-map's
		}
	}
	catch (const io::Error&)
	{
		// e.g. too large for 32-bit indices
	}
	return 0;
}
