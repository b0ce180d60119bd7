// SPDX-License-Identifier: MIT
// Where the tests and benchmarks find their meshes.
//
// The small meshes (under about 1 MB each) are part of the repository, in
// tests/data (CGOGN_DATA_DIR). The large ones are not: they are looked up in
// CGOGN_LARGE_DATA_DIR, taken from the environment when set there, else from
// the CMake variable of the same name (empty by default). A test that needs a
// large file skips, naming the file, when it is not found; a test that needs
// a small file fails when it is missing (it is part of the sources).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#ifndef CGOGN_DATA_DIR
#error "CGOGN_DATA_DIR must name the in-repository test data folder"
#endif
#ifndef CGOGN_LARGE_DATA_DIR
#define CGOGN_LARGE_DATA_DIR ""
#endif

namespace cgogn_test_data
{

/// The meshes too large for the repository, relative to a data folder.
inline bool is_large(std::string_view rel)
{
	constexpr std::string_view large[] = {"surface/nefertiti.obj",         "surface/refined_elephant.off",
										  "surface/stanford-bunny.obj",    "volume/armadillo_tet_461k.mesh",
										  "volume/heart_tet_205k.mesh",    "volume/elephant_tet_27k.mesh",
										  "volume/elephant_hex_110k.mesh", "volume/elephant_poly_4k.ovm"};
	for (std::string_view l : large)
		if (l == rel)
			return true;
	return false;
}

/// The folder of the large meshes: the environment's CGOGN_LARGE_DATA_DIR,
/// else the build's; empty when neither is set.
inline std::string large_dir()
{
	if (const char* env = std::getenv("CGOGN_LARGE_DATA_DIR"); env != nullptr && *env != '\0')
		return env;
	return CGOGN_LARGE_DATA_DIR;
}

/// The path of a data mesh ("surface/hemisphere.off", "volume/armadillo_tet_4k.mesh"):
/// the in-repository folder for a small one, the large-data folder for a large
/// one. Empty when a large mesh is not found (a small one always has a path,
/// whether or not it exists, so that a missing one fails the test).
inline std::string path(std::string_view rel)
{
	if (!is_large(rel))
		return std::string(CGOGN_DATA_DIR) + "/" + std::string(rel);
	const std::string dir = large_dir();
	if (dir.empty())
		return {};
	std::string p = dir + "/" + std::string(rel);
	return std::filesystem::exists(p) ? p : std::string();
}

/// The message of a skipped test whose large mesh was not found.
inline std::string missing_large(std::string_view rel)
{
	return "large data file " + std::string(rel) + " not found: set CGOGN_LARGE_DATA_DIR to the folder holding it";
}

} // namespace cgogn_test_data

/// Sets `var` (a std::string) to the path of the data mesh `rel`, or skips
/// the test when `rel` is a large mesh that is not available.
#define CGOGN_DATA_PATH_OR_SKIP(var, rel)                                                                              \
	const std::string var = ::cgogn_test_data::path(rel);                                                              \
	if (var.empty())                                                                                                   \
	GTEST_SKIP() << ::cgogn_test_data::missing_large(rel)
