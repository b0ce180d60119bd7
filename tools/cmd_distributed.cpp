// SPDX-License-Identifier: MIT
// `cgogn` under mpiexec: with more than one rank, `info`, `smooth`,
// `subdivide` (volume schemes) and `convert` run on the distributed map (the file read on rank 0 and spread
// over the ranks); with one rank, every command runs as without mpiexec.
#include <cgogn/core/parallel/thread_pool.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/distributed/files.h>
#include <cgogn/distributed/reductions.h>
#include <cgogn/distributed/smoothing.h>
#include <cgogn/distributed/subdivision.h>
#include <cgogn/io/error.h>

#include "commands.h"
#include "mesh_info.h"

#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <memory>

namespace cgogn::tool
{

namespace
{

using nlohmann::json;

// Runs f on the distributed map of path: rank 0 reads the file once, as a
// volume mesh when its format holds volumes and it has volume cells, else
// as a surface (the formats of both are read twice for a surface only, as
// with_loaded reads them).
template <typename FUNC>
void with_distributed(MPI_Comm comm, const std::string& path, const FUNC& f)
{
	int rank = 0;
	MPI_Comm_rank(comm, &rank);
	auto volume = std::make_unique<CMap3>();
	int is_volume = 0; // -1: the volume file could not be read
	std::string error;
	if (rank == 0)
	{
		try
		{
			const io::Format format = format_of(path);
			if (is_volume_format(format))
				is_volume = io::load_volume(*volume, path).nb_cells_read > 0 || !holds_surfaces(format);
		}
		catch (const std::exception& e)
		{
			// a format of both is read as a surface below, which reports its errors
			is_volume = -1;
			error = e.what();
		}
		if (is_volume == -1 && holds_surfaces(io::format_from_extension(path)))
			is_volume = 0;
	}
	MPI_Bcast(&is_volume, 1, MPI_INT, 0, comm);
	if (is_volume == -1) // rank 0 prints the error
		throw std::runtime_error(rank == 0 ? error : "rank 0 could not read the file");
	if (is_volume == 1)
	{
		dist::DistributedCMap3 dm = dist::distribute(comm, rank == 0 ? volume.get() : nullptr);
		f(dm);
	}
	else
	{
		volume.reset();
		dist::DistributedCMap2 dm = dist::load_surface(comm, path);
		f(dm);
	}
}

template <typename MAP>
json distributed_info(const dist::DistributedMap<MAP>& dm, const std::string& path)
{
	using Vertex = typename MAP::Vertex;
	using Edge = typename MAP::Edge;
	using Face = typename MAP::Face;
	const MAP& m = dm.map();
	json j;
	j["file"] = path;
	j["format"] = io::format_name(io::format_from_extension(path));
	j["dimension"] = MAP::dimension;
	j["map"] = MAP::dimension == 3 ? "CMap3" : "CMap2";
	j["vertices"] = dist::global_nb_cells<Vertex>(dm);
	j["edges"] = dist::global_nb_cells<Edge>(dm);
	j["faces"] = dist::global_nb_cells<Face>(dm);
	if constexpr (MAP::dimension == 3)
	{
		j["volumes"] = dist::global_nb_cells<CMap3::Volume>(dm);
		// an owned face has its volumes here (see DistributedMap)
		j["boundary_faces"] =
			uint64(dist::global_sum_of<Face>(dm, [&](Face x) { return degree(m, x) < 2 ? 1.0 : 0.0; }));
	}
	else
		j["boundary_edges"] =
			uint64(dist::global_sum_of<Edge>(dm, [&](Edge x) { return is_incident_to_boundary(m, x) ? 1.0 : 0.0; }));
	j["euler_characteristic"] = dist::global_euler_characteristic(dm);

	// face degrees: counts per degree, reduced over the ranks
	std::map<uint32, uint64> degrees;
	foreach_cell(m, [&](Face x) {
		if (dist::is_owned(dm, x))
			++degrees[codegree(m, x)];
	});
	uint32 largest = degrees.empty() ? 0 : degrees.rbegin()->first, max_degree = 0;
	MPI_Allreduce(&largest, &max_degree, 1, MPI_UINT32_T, MPI_MAX, dm.comm());
	std::vector<uint64> local(max_degree + 1, 0), global(max_degree + 1, 0);
	for (auto [d, n] : degrees)
		local[d] = n;
	MPI_Allreduce(local.data(), global.data(), int(local.size()), MPI_UINT64_T, MPI_SUM, dm.comm());
	json h = json::object();
	for (uint32 d = 0; d <= max_degree; ++d)
		if (global[d] != 0)
			h[std::to_string(d)] = global[d];
	j["face_degrees"] = h;

	if (auto pos = get_attribute<Vec3, Vertex>(m, "position"))
	{
		const dist::BoundingBox box = dist::global_bounding_box(dm, *pos);
		j["bbox"] = {{"min", {box.min[0], box.min[1], box.min[2]}}, {"max", {box.max[0], box.max[1], box.max[2]}}};
		double lo = std::numeric_limits<double>::infinity(), hi = 0.0, low = 0.0, high = 0.0;
		auto length = [&](Edge e) { return ((*pos)[Vertex(e.dart)] - (*pos)[Vertex(phi1(m, e.dart))]).norm(); };
		foreach_cell(m, [&](Edge e) {
			if (!dist::is_owned(dm, e))
				return;
			lo = std::min(lo, length(e));
			hi = std::max(hi, length(e));
		});
		MPI_Allreduce(&lo, &low, 1, MPI_DOUBLE, MPI_MIN, dm.comm());
		MPI_Allreduce(&hi, &high, 1, MPI_DOUBLE, MPI_MAX, dm.comm());
		const double sum = dist::global_sum_of<Edge>(dm, length);
		j["edge_length"] = {{"min", low}, {"max", high}, {"mean", sum / double(j["edges"].get<uint64>())}};
	}

	// how the map is spread
	using Top = typename dist::DistributedMap<MAP>::TopCell;
	uint64 owned_ghost[2] = {0, 0};
	foreach_cell(m, [&](Top c) { ++owned_ghost[dist::is_owned(dm, c) ? 0 : 1]; });
	std::vector<uint64> all(2 * std::size_t(dm.nb_ranks()));
	MPI_Allgather(owned_ghost, 2, MPI_UINT64_T, all.data(), 2, MPI_UINT64_T, dm.comm());
	json owned = json::array(), ghosts = json::array();
	for (int r = 0; r < dm.nb_ranks(); ++r)
	{
		owned.push_back(all[2 * std::size_t(r)]);
		ghosts.push_back(all[2 * std::size_t(r) + 1]);
	}
	j["ranks"] = dm.nb_ranks();
	j["owned_cells_per_rank"] = owned;
	j["ghost_cells_per_rank"] = ghosts;
	return j;
}

struct DistributedOptions
{
	std::string in, out;
	bool json = false, binary = false, deterministic = false, move_boundary = false;
	std::string method = "taubin", scheme;
	uint32 iterations = 10;
	double lambda = 0.5, mu = -0.53;
};

void require_pvtu(const std::string& out)
{
	if (io::format_from_extension(out) != io::Format::Pvtu)
		throw io::Error(out, "under mpiexec the output is a .pvtu (one .vtu piece per rank)");
}

int run_distributed(MPI_Comm comm, const std::string& command, const DistributedOptions& o)
{
	int rank = 0;
	MPI_Comm_rank(comm, &rank);
	if (command == "info")
	{
		with_distributed(comm, o.in, [&](auto& dm) {
			const json j = distributed_info(dm, o.in);
			if (rank == 0)
				std::cout << (o.json ? j.dump(2) + "\n" : info_text(j));
		});
		return 0;
	}
	require_pvtu(o.out);
	io::SaveOptions save;
	save.binary = o.binary;
	with_distributed(comm, o.in, [&](auto& dm) {
		if (command == "smooth")
		{
			using Vertex = typename std::decay_t<decltype(dm.map())>::Vertex;
			auto pos = get_attribute<Vec3, Vertex>(dm.map(), "position");
			if (pos == nullptr)
				throw std::runtime_error("the mesh has no vertex positions");
			dist::SmoothingOptions s;
			s.lambda = o.lambda;
			s.fix_boundary = !o.move_boundary;
			s.deterministic = o.deterministic;
			if (o.method == "laplacian")
				dist::laplacian_smoothing(dm, *pos, o.iterations, s);
			else
				dist::taubin_smoothing(dm, *pos, o.iterations, o.mu, s);
		}
		if (command == "subdivide")
		{
			if constexpr (std::is_same_v<std::decay_t<decltype(dm)>, dist::DistributedCMap3>)
			{
				for (uint32 i = 0; i < o.iterations; ++i)
					if (o.scheme == "hex")
						dist::hex_subdivision(dm);
					else
						dist::tet_subdivision(dm);
			}
			else
				throw std::invalid_argument(o.in + ": under mpiexec, subdivide refines volume meshes (hex, tet); "
												   "run surface schemes without mpiexec");
		}
		io::save_pvtu(dm, o.out, save);
	});
	return 0;
}

} // namespace

bool launched_by_mpiexec()
{
	for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
		if (std::getenv(v) != nullptr)
			return true;
	return false;
}

int distributed_main(int argc, char** argv, int (*serial_main)(int, char**))
{
	int provided = 0;
	MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
	int rank = 0, size = 1;
	MPI_Comm_rank(MPI_COMM_WORLD, &rank);
	MPI_Comm_size(MPI_COMM_WORLD, &size);
	int status = EXIT_ERROR;
	if (size == 1)
		status = serial_main(argc, argv);
	else
	{
		// the ranks of one node share its cores
		MPI_Comm node;
		MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
		int node_size = 1;
		MPI_Comm_size(node, &node_size);
		MPI_Comm_free(&node);
		set_nb_workers(std::max(1u, ThreadPool::default_nb_workers() / uint32(node_size)));

		const std::string command = argc > 1 ? argv[1] : "";
		if (command != "info" && command != "smooth" && command != "subdivide" && command != "convert" &&
			command != "--help" && command != "-h")
		{
			if (rank == 0)
				std::cerr << "cgogn: under mpiexec with " << size
						  << " ranks, the commands are info, smooth, subdivide and convert; run the others without "
							 "mpiexec "
							 "(or with one rank)\n";
			MPI_Finalize();
			return EXIT_ERROR;
		}
		CLI::App app{"cgogn under mpiexec: info, smooth, subdivide and convert on a mesh spread over the ranks"};
		app.require_subcommand(1);
		DistributedOptions o;
		auto* info = app.add_subcommand("info", "Global counts and geometry of a mesh, and how it is spread");
		info->add_option("FILE", o.in, "mesh file")->required();
		info->add_flag("--json", o.json, "print one JSON object");
		auto* smooth = app.add_subcommand("smooth", "Laplacian or Taubin smoothing (surfaces and volumes)");
		smooth->add_option("IN", o.in, "mesh file")->required();
		smooth->add_option("OUT", o.out, "output .pvtu")->required();
		smooth->add_option("--method", o.method, "laplacian or taubin (default taubin)")
			->check(CLI::IsMember({"laplacian", "taubin"}));
		smooth->add_option("--iterations,-n", o.iterations, "passes of the filter (default 10)")
			->check(CLI::Range(1u, 1000000u));
		smooth->add_option("--lambda", o.lambda, "step in (0, 1] (default 0.5)")->check(CLI::Range(1e-9, 1.0));
		smooth->add_option("--mu", o.mu, "taubin's negative step, mu < -lambda (default -0.53)");
		smooth->add_flag("--move-boundary", o.move_boundary, "let boundary vertices move too");
		smooth->add_flag("--deterministic", o.deterministic,
						 "add neighbours in global id order: the same bits whatever the number of ranks");
		smooth->add_flag("--binary", o.binary, "write binary pieces");
		auto* subdivide = app.add_subcommand("subdivide", "1-to-8 refinement of a hexahedral or tetrahedral mesh");
		subdivide->add_option("IN", o.in, "volume mesh file")->required();
		subdivide->add_option("OUT", o.out, "output .pvtu")->required();
		subdivide->add_option("--scheme", o.scheme, "hex (hexahedra) or tet (tetrahedra)")
			->required()
			->check(CLI::IsMember({"hex", "tet"}));
		subdivide->add_option("--iterations,-n", o.iterations, "number of steps (default 1)")
			->check(CLI::Range(1u, 20u));
		subdivide->add_flag("--binary", o.binary, "write binary pieces");
		auto* convert = app.add_subcommand("convert", "Spread a mesh over the ranks and write it as .pvtu");
		convert->add_option("IN", o.in, "mesh file")->required();
		convert->add_option("OUT", o.out, "output .pvtu")->required();
		convert->add_flag("--binary", o.binary, "write binary pieces");
		try
		{
			app.parse(argc, argv);
			if (o.method == "taubin" && !(o.mu < -o.lambda))
				throw std::invalid_argument("--mu must be smaller than -lambda");
			const std::string name = app.get_subcommands().front()->get_name();
			if (name == "subdivide" && subdivide->count("--iterations") == 0)
				o.iterations = 1;
			status = run_distributed(MPI_COMM_WORLD, name, o);
		}
		catch (const CLI::ParseError& e)
		{
			if (rank == 0)
				status = app.exit(e) == 0 ? 0 : EXIT_ERROR;
			else
				status = e.get_exit_code() == 0 ? 0 : EXIT_ERROR;
		}
		catch (const std::exception& e)
		{
			if (rank == 0)
				std::cerr << "cgogn: " << e.what() << "\n";
			status = EXIT_ERROR;
		}
	}
	MPI_Finalize();
	return status;
}

} // namespace cgogn::tool
