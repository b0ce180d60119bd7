// SPDX-License-Identifier: MIT
// `cgogn subdivide`: uniform subdivision of a surface (Loop, Catmull-Clark,
// sqrt3) or a volume mesh (hexahedra or tetrahedra, 1-to-8; tetrahedra and
// octahedra, tetra-octa); with --keep-levels, every level of a surface, a
// hexahedral or a tetrahedral-octahedral mesh in one multiresolution map.
#include <cgogn/core/operators/mrmap2.h>
#include <cgogn/core/operators/mrmap3.h>
#include <cgogn/io/map_file.h>
#include <cgogn/modeling/multiresolution.h>
#include <cgogn/modeling/subdivision.h>

#include "commands.h"

#include <map>
#include <stdexcept>

namespace cgogn::tool
{

namespace
{

enum class Scheme
{
	Loop,
	CatmullClark,
	Sqrt3,
	Hex,
	Tet,
	TetraOcta
};

struct SubdivideOptions
{
	EditFiles files;
	Scheme scheme = Scheme::CatmullClark;
	uint32 iterations = 1;
	bool keep_levels = false;
};

bool is_volume_scheme(Scheme s)
{
	return s == Scheme::Hex || s == Scheme::Tet || s == Scheme::TetraOcta;
}

// The volume mesh `base` (from file `in`) as level 0 of an MRMap3 with
// `levels` levels of pattern r, the new vertices at the centroids of the
// edges, faces and volumes they are the middle of (hex: the positions of
// hex_subdivision; tetra-octa: edge midpoints and octahedron centres).
MRMap3 volume_levels(CMap3&& base, Refinement r, uint32 levels, const std::string& in, Progress& progress)
{
	auto pos = get_attribute<Vec3, CMap3::Vertex>(base, "position");
	if (!pos)
		throw std::runtime_error(in + ": the mesh has no vertex positions");
	// the scheme's points are the means of the corners, whatever the file said
	set_attribute_rule(base, pos, AttributeRule::Interpolate);
	MRMap3 m(std::move(base));
	try
	{
		for (uint32 i = 0; i < levels; ++i)
		{
			progress.stage("adding level " + std::to_string(i + 1));
			add_level(m, r);
		}
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument(in + ": " + e.what());
	}
	return m;
}

// --keep-levels with hex or tetra-octa: the input volume mesh as level 0 of
// an MRMap3, one level per step (volume_levels), written to a .cgmap file.
int run_volume_subdivide_keeping_levels(const SubdivideOptions& o, Progress& progress)
{
	progress.stage("loading " + o.files.in);
	CMap3 base;
	const io::LoadReport report = io::load_volume(base, o.files.in);
	if (report.nb_cells_read == 0)
		throw io::Error(o.files.in, "--keep-levels: the file holds no volume cells");
	record_origins_if_asked(base, o.files);
	const MRMap3 m =
		volume_levels(std::move(base), o.scheme == Scheme::Hex ? Refinement::Hexahedral : Refinement::TetraOcta,
					  o.iterations, o.files.in, progress);
	progress.stage("saving " + o.files.out);
	io::save_map(m, o.files.out);
	return 0;
}

// --keep-levels: the input surface as level 0 of an MRMap2, one level per
// step (Loop: Triangular levels, Catmull-Clark: Quadrangular ones), the
// positions of every level those of the scheme (a synthesis without
// details), written to a .cgmap file; or, with hex and tetra-octa, the
// levels of a volume mesh.
int run_subdivide_keeping_levels(const SubdivideOptions& o)
{
	if (o.scheme == Scheme::Sqrt3 || o.scheme == Scheme::Tet)
		throw std::invalid_argument("--keep-levels: the scheme " +
									std::string(o.scheme == Scheme::Sqrt3 ? "sqrt3" : "tet") +
									" makes no multiresolution levels (loop, catmull-clark, hex and tetra-octa do)");
	if (!is_map_file(o.files.out))
		throw io::Error(o.files.out, "--keep-levels writes a multiresolution map: the output must be a .cgmap file");
	Progress progress;
	if (is_volume_scheme(o.scheme))
		return run_volume_subdivide_keeping_levels(o, progress);
	CMap2 base;
	if (!load_surface_file(base, o.files.in, progress).orientable)
		throw io::Error(o.files.in, "--keep-levels: the surface is not orientable (a multiresolution map is made of "
									"a CMap2)");
	record_origins_if_asked(base, o.files);
	if (!positions(base))
		throw std::runtime_error(o.files.in + ": the mesh has no vertex positions");
	MRMap2 m(std::move(base));
	const Refinement r = o.scheme == Scheme::Loop ? Refinement::Triangular : Refinement::Quadrangular;
	try
	{
		for (uint32 i = 0; i < o.iterations; ++i)
		{
			progress.stage("adding level " + std::to_string(i + 1));
			add_level(m, r);
		}
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument(o.files.in + ": " + e.what() + " (loop takes triangle meshes)");
	}
	progress.stage("positions of the levels");
	auto pos = get_attribute<Vec3, MRMap2::Vertex>(m, "position");
	auto details = add_attribute<Vec3, MRMap2::Vertex>(m, "details");
	if (!details)
		throw std::invalid_argument(o.files.in + ": the mesh has a vertex attribute named 'details' already");
	modeling::synthesis(m, *pos, *details,
						o.scheme == Scheme::Loop ? modeling::MRBank::Loop : modeling::MRBank::CatmullClark);
	remove_attribute(m, details);
	progress.stage("saving " + o.files.out);
	io::save_map(m, o.files.out);
	return 0;
}

int run_subdivide(const SubdivideOptions& o)
{
	if (o.keep_levels)
		return run_subdivide_keeping_levels(o);
	Progress progress;
	const io::Format in_format = format_of(o.files.in);
	const auto wrong_scheme = [&] {
		return std::invalid_argument(
			o.files.in + ": the schemes loop, catmull-clark and sqrt3 take surfaces, hex, tet and tetra-octa "
						 "take volume meshes");
	};
	try
	{
		// a file of a format of both (.mesh .vtk .vtu .msh) is a volume mesh
		// when it has volume cells: loaded once as such to find out
		if (is_volume_format(in_format) && (is_volume_scheme(o.scheme) || holds_surfaces(in_format)))
		{
			progress.stage("loading " + o.files.in);
			CMap3 m;
			const io::LoadReport r = io::load_volume(m, o.files.in);
			if (r.nb_cells_read > 0 || !holds_surfaces(in_format))
			{
				if (!is_volume_scheme(o.scheme))
					throw wrong_scheme();
				if (!is_volume_format(format_of(o.files.out)))
					throw io::Error(o.files.out, "not a volume format");
				record_origins_if_asked(m, o.files);
				if (o.scheme == Scheme::TetraOcta)
				{
					// the finest level of the hierarchy, as a flat map
					const MRMap3 h =
						volume_levels(std::move(m), Refinement::TetraOcta, o.iterations, o.files.in, progress);
					m = extract_level(h, max_level(h));
				}
				else
				{
					auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
					if (!pos)
						throw std::runtime_error("the mesh has no vertex positions");
					for (uint32 i = 0; i < o.iterations; ++i)
					{
						const auto callback = progress.percent("subdividing, step " + std::to_string(i + 1));
						if (o.scheme == Scheme::Hex)
							modeling::hex_subdivision(m, *pos, callback);
						else
							modeling::tet_subdivision(m, *pos, callback);
					}
				}
				progress.stage("saving " + o.files.out);
				io::SaveOptions so;
				so.binary = o.files.binary;
				io::save_volume(m, o.files.out, so);
				return 0;
			}
		}
		if (is_volume_scheme(o.scheme))
			throw wrong_scheme();
		const modeling::SurfaceScheme scheme = o.scheme == Scheme::Loop    ? modeling::SurfaceScheme::Loop
											   : o.scheme == Scheme::Sqrt3 ? modeling::SurfaceScheme::Sqrt3
																		   : modeling::SurfaceScheme::CatmullClark;
		with_surface_whole(o.files.in, progress, [&](auto& m) {
			record_origins_if_asked(m, o.files);
			modeling::subdivide(m, *positions(m), scheme, o.iterations, progress.percent("subdividing"));
			save_surface_file(m, o.files.out, o.files.binary, progress);
		});
		return 0;
	}
	catch (const modeling::SubdivisionError& e)
	{
		throw modeling::SubdivisionError(o.files.in + ": " + e.what());
	}
}

} // namespace

Command add_subdivide_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("subdivide", "Uniform subdivision: loop, catmull-clark, sqrt3 (surfaces), hex, tet "
												"(volume meshes, 1-to-8), tetra-octa (tetrahedra and octahedra)");
	auto o = std::make_shared<SubdivideOptions>();
	add_edit_files(*sub, o->files);
	add_origin_option(*sub, o->files);
	const std::map<std::string, Scheme> schemes = {{"loop", Scheme::Loop},   {"catmull-clark", Scheme::CatmullClark},
												   {"sqrt3", Scheme::Sqrt3}, {"hex", Scheme::Hex},
												   {"tet", Scheme::Tet},     {"tetra-octa", Scheme::TetraOcta}};
	sub->add_option("--scheme", o->scheme,
					"loop (triangles), catmull-clark (any polygons, default), sqrt3 "
					"(triangles), hex (hexahedra), tet (tetrahedra), tetra-octa (tetrahedra and octahedra: a "
					"tetrahedron into 4 and an octahedron, an octahedron into 6 and 8 tetrahedra; octahedra are "
					"written as polyhedra)")
		->transform(CLI::CheckedTransformer(schemes, CLI::ignore_case));
	sub->add_option("--iterations,--levels,-n", o->iterations, "number of steps (default 1)")
		->check(CLI::Range(1u, 20u));
	sub->add_flag("--keep-levels", o->keep_levels,
				  "loop, catmull-clark, hex and tetra-octa: write every step as a level of a multiresolution map "
				  "(OUT: a .cgmap file holding an MRMap2, or an MRMap3 for hex and tetra-octa; its current level "
				  "is the finest)");
	return {sub, [o] { return run_subdivide(*o); }};
}

} // namespace cgogn::tool
