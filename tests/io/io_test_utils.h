// SPDX-License-Identifier: MIT
// Shared by the io tests: temporary files, maps with positions.
#pragma once

#include <cgogn/cgogn.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cgogn::io_test
{

/// A fresh directory under the system's temporary folder, removed at exit.
class TempDir
{
public:
	TempDir()
	{
		auto base = std::filesystem::temp_directory_path();
		for (int i = 0;; ++i)
		{
			path_ = base / ("cgogn_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(i));
			if (std::filesystem::create_directory(path_))
				break;
		}
	}
	~TempDir()
	{
		std::error_code ec;
		std::filesystem::remove_all(path_, ec);
	}
	std::string file(const std::string& name) const
	{
		return (path_ / name).string();
	}

private:
	std::filesystem::path path_;
};

inline void write_text(const std::string& path, const std::string& content)
{
	std::ofstream f(path, std::ios::binary);
	f << content;
}

inline std::string read_text(const std::string& path)
{
	std::ifstream f(path, std::ios::binary);
	return std::string(std::istreambuf_iterator<char>(f), {});
}

/// Builds a soup into m and sets the `position` attribute from its positions.
template <typename MAP, typename SOUP>
BuildReport build_with_positions(MAP& m, const SOUP& s)
{
	BuildReport r;
	if constexpr (MAP::dimension == 2)
		r = build_surface(m, s);
	else if constexpr (std::same_as<SOUP, PolyhedronSoup>)
		r = build_polyhedra(m, s);
	else
		r = build_volume(m, s);
	using Vertex = typename mesh_traits<MAP>::Vertex;
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	if (!pos)
		pos = add_attribute<Vec3, Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		if (container_of<Vertex::ORBIT>(m).is_live(r.vertex_offset + i))
			(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return r;
}

/// What must not change when a load fails: counts, the attributes of the
/// vertices and of the top cells (faces of a surface, volumes of a volume
/// mesh), and every position.
template <typename MAP>
struct MapSnapshot
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Top =
		std::conditional_t<MAP::dimension == 2, typename mesh_traits<MAP>::Face, typename mesh_traits<MAP>::Volume>;
	uint32 darts, vertices, top_cells;
	std::vector<std::string> vertex_attributes, top_attributes;
	std::vector<Vec3> positions;
	explicit MapSnapshot(const MAP& m)
		: darts(nb_darts(m)), vertices(nb_cells<Vertex>(m)), top_cells(nb_cells<Top>(m)),
		  vertex_attributes(names(container_of<Vertex::ORBIT>(m))), top_attributes(names(container_of<Top::ORBIT>(m)))
	{
		if (auto pos = get_attribute<Vec3, Vertex>(m, "position"))
			foreach_cell(m, [&](Vertex v) { positions.push_back(value<Vec3>(m, *pos, v)); });
	}
	bool operator==(const MapSnapshot&) const = default;

private:
	static std::vector<std::string> names(const AttributeContainer& c)
	{
		std::vector<std::string> out;
		for (const auto& a : c.attributes())
			out.push_back(a->name() + ":" + a->type().name());
		return out;
	}
};

#ifdef CGOGN_TOOL_PATH
/// What a run of the `cgogn` program produced.
struct ToolRun
{
	int status = -1;
	std::string out;
	std::string err;
};

/// Runs the `cgogn` program with the given arguments (shell-quoted by the
/// caller, see quoted()); stdout and stderr are captured through files in
/// dir, so neither is a terminal (no progress output expected).
inline ToolRun run_tool(const std::string& args, const TempDir& dir)
{
	const std::string out = dir.file("stdout"), err = dir.file("stderr");
	const std::string cmd = std::string("'") + CGOGN_TOOL_PATH + "' " + args + " >'" + out + "' 2>'" + err + "'";
	ToolRun r;
	const int s = std::system(cmd.c_str());
	r.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
	r.out = read_text(out);
	r.err = read_text(err);
	return r;
}

/// A path quoted for the shell.
inline std::string quoted(const std::string& path)
{
	return "'" + path + "'";
}
#endif

/// One volume format variant written and read back by the round-trip tests.
struct VolumeCase
{
	const char* name;
	const char* file;
	bool binary;
	bool attributes; // the format keeps vertex and volume attributes
	bool tets_only;
};

inline std::string volume_case_name(const testing::TestParamInfo<VolumeCase>& i)
{
	return i.param.name;
}

/// Every volume format variant.
inline std::vector<VolumeCase> volume_cases()
{
	return {{"medit", "m.mesh", false, false, false},     {"vtk_ascii", "m.vtk", false, true, false},
			{"vtk_binary", "m.vtk", true, true, false},   {"vtu_ascii", "m.vtu", false, true, false},
			{"vtu_appended", "m.vtu", true, true, false}, {"msh4_ascii", "m.msh", false, false, false},
			{"msh4_binary", "m.msh", true, false, false}, {"tetgen", "m.ele", false, false, true},
			{"medit_tets", "t.mesh", false, false, true}};
}

} // namespace cgogn::io_test
