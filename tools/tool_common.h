// SPDX-License-Identifier: MIT
// What the subcommands of the `cgogn` program share: exit codes, progress on
// a terminal, format dispatch, loading and saving.
#pragma once

#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/surface.h>
#include <cgogn/io/volume.h>
#include <cgogn/modeling/progress.h>

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace cgogn::tool
{

// Exit codes: 0 success, 1 `check` found a broken map, 2 any error.
constexpr int EXIT_BROKEN = 1;
constexpr int EXIT_ERROR = 2;

/// A subcommand: its CLI11 parser, and what runs once it was chosen.
struct Command
{
	CLI::App* parser;
	std::function<int()> run;
};

/// Progress on stderr, only when it is a terminal: named stages and, for the
/// modeling algorithms, a percentage.
class Progress
{
public:
	Progress();
	~Progress();
	Progress(const Progress&) = delete;
	Progress& operator=(const Progress&) = delete;

	void stage(const std::string& what);
	/// A callback for the modeling algorithms showing "what... N%"; never cancels.
	modeling::ProgressCallback percent(const std::string& what);

private:
	bool on_;
	bool shown_ = false;
};

/// Whether f holds volume meshes (.mesh .vtk .vtu .msh .node/.ele .ovm).
bool is_volume_format(io::Format f);
/// Whether f holds surfaces: every format but .node/.ele and .ovm.
bool holds_surfaces(io::Format f);

/// Whether path names a .nmap file, a map of any dimension (by its
/// extension, any case).
bool is_nmap_file(const std::string& path);

/// Whether path names a whole-map file (.cgmap, any case).
bool is_map_file(const std::string& path);

/// Whether path names a graph file (.cg, .cgr, .skel; any case).
bool is_graph_file(const std::string& path);
/// True for an incidence graph's own file (.ig, any case).
bool is_incidence_graph_file(const std::string& path);

/// The format of path by its extension; throws io::Error when unknown.
io::Format format_of(const std::string& path);

/// Loads path into a CMap3 when it is a volume mesh, else into a CMap2, and
/// calls f(map, report). A file of a format of both (.mesh .vtk .vtu .msh)
/// without volume cells is a surface: it is read twice.
template <typename FUNC>
void with_loaded(const std::string& path, Progress& progress, const FUNC& f)
{
	progress.stage("loading " + path);
	const io::Format format = format_of(path);
	if (is_volume_format(format))
	{
		CMap3 m;
		const io::LoadReport r = io::load_volume(m, path);
		if (r.nb_cells_read > 0 || !holds_surfaces(format))
		{
			f(m, r);
			return;
		}
	}
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, path);
	f(m, r);
}

/// As with_loaded, except that a mesh that cannot be oriented is loaded into
/// a G-map, which keeps it whole: a surface into a GMap2 (a CMap2 cuts it),
/// and a volume mesh that the CMap3 reports not manifold into a GMap3, kept
/// when that one is not orientable. f must also take a GMap2 and a GMap3. The file
/// is read twice in those cases.
template <typename FUNC>
void with_loaded_whole(const std::string& path, Progress& progress, const FUNC& f)
{
	with_loaded(path, progress, [&](auto& m, const io::LoadReport& r) {
		if constexpr (std::decay_t<decltype(m)>::dimension == 2)
		{
			if (!r.orientable)
			{
				progress.stage("not orientable: loading " + path + " as a GMap2");
				GMap2 g;
				const io::LoadReport rg = io::load_surface(g, path);
				f(g, rg);
				return;
			}
		}
		else if (!r.manifold())
		{
			// faces the CMap3 could not glue (listed the same way by two
			// cells) split their vertices: the GMap3 glues them
			progress.stage("not manifold as a CMap3: loading " + path + " as a GMap3");
			GMap3 g;
			io::LoadReport rg;
			bool loaded = true;
			try
			{
				rg = io::load_volume(g, path);
			}
			catch (const io::Error&)
			{
				loaded = false; // cells a GMap3 does not take (polyhedra): the CMap3 it is
			}
			if (loaded && !rg.orientable)
			{
				f(g, rg);
				return;
			}
		}
		f(m, r);
	});
}

/// Loads a surface file (throws io::Error naming the file when it is a
/// volume mesh).
io::LoadReport load_surface_file(CMap2& m, const std::string& path, Progress& progress);

/// Loads a surface file into a CMap2 and calls f(map), or, when the surface
/// cannot be oriented, into a GMap2, which keeps it whole (a CMap2 cuts it):
/// f must also take a GMap2. The file is read twice in that case.
template <typename FUNC>
void with_surface_whole(const std::string& path, Progress& progress, const FUNC& f)
{
	{
		CMap2 m;
		if (load_surface_file(m, path, progress).orientable)
		{
			f(m);
			return;
		}
	}
	progress.stage("not orientable: loading " + path + " as a GMap2");
	GMap2 g;
	io::load_surface(g, path);
	f(g);
}

/// Saves a surface (throws io::Error when out names a volume-only format).
void save_surface_file(const CMap2& m, const std::string& path, bool binary, Progress& progress);
/// The same for a GMap2.
void save_surface_file(const GMap2& m, const std::string& path, bool binary, Progress& progress);

/// The input/output options every editing subcommand has: IN, OUT,
/// --binary; and --origin NAME for those that change the connectivity (see
/// record_origins_if_asked).
struct EditFiles
{
	std::string in, out;
	bool binary = false;
	std::string origin;
};
void add_edit_files(CLI::App& sub, EditFiles& files);
void add_origin_option(CLI::App& sub, EditFiles& files);

/// With --origin NAME, records in a face attribute NAME (a volume attribute
/// for volume meshes) the input face (volume) each output cell comes from:
/// its index among the input's cells as loaded, 4294967295 for a cell that
/// comes from none (a face filling a hole). Call it right after loading.
template <typename MAP>
void record_origins_if_asked(MAP& m, const EditFiles& files)
{
	if (files.origin.empty())
		return;
	using Cell = std::conditional_t<MAP::dimension == 3, typename MAP::Volume, typename MAP::Face>;
	if (!record_origins<Cell>(m, files.origin))
		throw std::invalid_argument("--origin " + files.origin + ": the input already has an attribute of this name");
}

/// The "position" attribute of a loaded surface (every reader creates it).
std::shared_ptr<AttributeArray<Vec3>> positions(CMap2& m);
/// The same for a GMap2.
std::shared_ptr<AttributeArray<Vec3>> positions(GMap2& m);

} // namespace cgogn::tool
