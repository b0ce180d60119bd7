// SPDX-License-Identifier: MIT
// `cgogn partition`: splits a volume mesh (a surface) into parts with METIS
// and writes one .vtu file per part, with the global ids of the vertices and
// cells, for a distributed run or for ParaView.
#include <cgogn/core.h>
#include <cgogn/distributed/partition.h>
#include <cgogn/io/map_file.h>

#include "commands.h"

#include <cstdio>
#include <filesystem>

namespace cgogn::tool
{

namespace
{

struct PartitionArgs
{
	std::string in, out_dir;
	uint32 parts = 2;
	int seed = 0;
	double tolerance = 1.03;
	bool binary = false;
};

// A uint64 attribute `name` numbering the cells of type CELL 0, 1, ... in
// traversal order; an input attribute of this name is an error.
template <typename CELL, typename MAP>
void number_globally(MAP& m, const std::string& name)
{
	auto id = add_attribute<uint64, CELL>(m, name);
	if (id == nullptr)
		throw std::invalid_argument("the input already has an attribute " + name);
	uint64 k = 0;
	foreach_cell(m, [&](CELL c) { (*id)[c] = k++; });
}

template <typename MAP>
int run_partition(MAP& m, const PartitionArgs& a, Progress& progress)
{
	constexpr bool volumes = MAP::dimension == 3;
	using Cell = std::conditional_t<volumes, typename MAP::Volume, typename MAP::Face>;
	const char* cells = volumes ? "volumes" : "faces";
	// VTK's names, which ParaView shows and its filters use
	number_globally<typename MAP::Vertex>(m, "GlobalNodeIds");
	number_globally<Cell>(m, "GlobalCellIds");

	progress.stage("partitioning");
	dist::PartitionOptions o;
	o.seed = a.seed;
	o.imbalance_tolerance = a.tolerance;
	const dist::PartitionReport r = dist::partition(m, a.parts, o);

	// each part from an exact copy of the map, without the other parts' cells
	const std::string bytes = io::save_map_to_bytes(m);
	std::filesystem::create_directories(a.out_dir);
	const std::string stem = std::filesystem::path(a.in).stem().string();
	io::SaveOptions save;
	save.binary = a.binary;
	std::vector<std::string> files;
	for (uint32 p = 0; p < a.parts; ++p)
	{
		progress.stage("writing part " + std::to_string(p));
		MAP piece;
		io::load_map_from_bytes(piece, bytes);
		auto part = get_attribute<uint32, Cell>(piece, o.attribute);
		std::vector<Cell> others;
		foreach_cell(piece, [&](Cell c) {
			if ((*part)[c] != p)
				others.push_back(c);
		});
		for (Cell c : others)
		{
			if constexpr (volumes)
				remove_volume(piece, c);
			else
				remove_face(piece, c);
		}
		const std::string file =
			(std::filesystem::path(a.out_dir) / (stem + "_" + std::to_string(p) + ".vtu")).string();
		if constexpr (volumes)
			io::save_volume(piece, file, save);
		else
			io::save_surface(piece, file, save);
		files.push_back(file);
	}
	std::printf("%u %s in %u parts:", uint32(nb_cells<Cell>(m)), cells, a.parts);
	for (uint64 s : r.part_sizes)
		std::printf(" %llu", static_cast<unsigned long long>(s));
	std::printf("\nimbalance (largest part / mean): %.4f\n", r.imbalance);
	std::printf("cut: %llu of %llu interior %s (%.2f%%)\n", static_cast<unsigned long long>(r.nb_cut_facets),
				static_cast<unsigned long long>(r.nb_interior_facets), volumes ? "faces" : "edges",
				100.0 * r.cut_ratio());
	std::printf("every part in one piece: %s", r.parts_connected() ? "yes" : "no");
	if (r.nb_map_components > 1)
		std::printf(" (the mesh itself is in %u pieces)", r.nb_map_components);
	std::printf("\n");
	for (const std::string& f : files)
		std::printf("wrote %s\n", f.c_str());
	return 0;
}

} // namespace

Command add_partition_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("partition", "Split a volume mesh (or a surface) into parts with METIS and write "
												"one .vtu per part, with global vertex and cell ids");
	auto a = std::make_shared<PartitionArgs>();
	sub->add_option("IN", a->in, "Input mesh file")->required()->check(CLI::ExistingFile);
	sub->add_option("OUT_DIR", a->out_dir, "Folder of the parts: IN's name followed by _0.vtu, _1.vtu, ...")
		->required();
	sub->add_option("--parts", a->parts, "Number of parts")->required()->check(CLI::Range(1u, 1u << 20));
	sub->add_option("--seed", a->seed, "METIS's random seed (the same seed gives the same parts)");
	sub->add_option("--tolerance", a->tolerance, "Largest part allowed, over the mean part (at least 1.001)")
		->check(CLI::Range(1.001, 100.0));
	sub->add_flag("--binary", a->binary, "Write binary .vtu files");
	return {sub, [a] {
				Progress progress;
				int status = EXIT_ERROR;
				with_loaded(a->in, progress,
							[&](auto& m, const io::LoadReport&) { status = run_partition(m, *a, progress); });
				return status;
			}};
}

} // namespace cgogn::tool
