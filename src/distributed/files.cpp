// SPDX-License-Identifier: MIT
#include <cgogn/core/traversals/global.h>
#include <cgogn/distributed/files.h>
#include <cgogn/io/error.h>
#include <cgogn/io/pvtu.h>
#include <cgogn/io/surface.h>
#include <cgogn/io/volume.h>

#include <filesystem>

namespace cgogn
{

namespace
{

// Every rank learns whether one failed; all throw io::Error (the failing
// rank's own message, or a pointer to the rank that failed).
void raise_everywhere(MPI_Comm comm, const std::string& path, const std::string& error)
{
	int rank = 0;
	MPI_Comm_rank(comm, &rank);
	const int mine = error.empty() ? -1 : rank;
	int first = -1;
	MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MAX, comm);
	if (first < 0)
		return;
	throw io::Error(path, error.empty() ? "rank " + std::to_string(first) + " failed to write its piece" : error);
}

// An attribute of the given name and type, added when absent (`added` is
// then set); nullptr when the name is taken by another type.
template <typename T, typename CELL, typename MAP>
std::shared_ptr<CellAttribute<T, CELL::ORBIT>> scratch_attribute(MAP& m, const std::string& name, bool& added)
{
	auto a = get_attribute<T, CELL>(m, name);
	added = a == nullptr;
	if (a == nullptr)
		a = add_attribute<T, CELL>(m, name);
	return a;
}

template <typename MAP>
void save_pieces(dist::DistributedMap<MAP>& dm, const std::string& path, const io::SaveOptions& options)
{
	using Vertex = typename MAP::Vertex;
	using Top = typename dist::DistributedMap<MAP>::TopCell;
	MAP& m = dm.map();
	const std::filesystem::path p(path);
	const std::string stem = p.stem().string();
	auto piece_name = [&](int r) { return stem + "_" + std::to_string(r) + ".vtu"; };
	std::string error;
	try
	{
		bool added[4] = {};
		auto node_ids = scratch_attribute<uint64, Vertex>(m, "GlobalNodeIds", added[0]);
		auto node_ghost = scratch_attribute<uint8, Vertex>(m, "vtkGhostType", added[1]);
		auto cell_ids = scratch_attribute<uint64, Top>(m, "GlobalCellIds", added[2]);
		auto cell_ghost = scratch_attribute<uint8, Top>(m, "vtkGhostType", added[3]);
		if (!node_ids || !node_ghost || !cell_ids || !cell_ghost)
			throw io::Error(path, "the map has an attribute named GlobalNodeIds, GlobalCellIds or vtkGhostType of "
								  "another type");
		foreach_cell(m, [&](Vertex v) {
			(*node_ids)[v] = dist::global_id(dm, v);
			(*node_ghost)[v] = dist::is_owned(dm, v) ? 0 : 1;
		});
		foreach_cell(m, [&](Top c) {
			(*cell_ids)[c] = dist::global_id(dm, c);
			(*cell_ghost)[c] = dist::is_owned(dm, c) ? 0 : 1;
		});
		io::SaveOptions piece = options;
		piece.format = io::Format::Vtu;
		const std::string piece_path = (p.parent_path() / piece_name(dm.rank())).string();
		std::exception_ptr failure;
		try
		{
			if constexpr (MAP::dimension == 3)
				io::save_volume(m, piece_path, piece);
			else
				io::save_surface(m, piece_path, piece);
		}
		catch (...)
		{
			failure = std::current_exception();
		}
		if (added[0])
			remove_attribute(m, node_ids);
		if (added[1])
			remove_attribute(m, node_ghost);
		if (added[2])
			remove_attribute(m, cell_ids);
		if (added[3])
			remove_attribute(m, cell_ghost);
		if (failure)
			std::rethrow_exception(failure);
	}
	catch (const std::exception& e)
	{
		error = e.what();
	}
	raise_everywhere(dm.comm(), path, error);
	if (dm.rank() == 0)
	{
		try
		{
			std::vector<std::string> sources;
			for (int r = 0; r < dm.nb_ranks(); ++r)
				sources.push_back(piece_name(r));
			io::write_pvtu_index(path, sources, 1);
		}
		catch (const std::exception& e)
		{
			error = e.what();
		}
	}
	raise_everywhere(dm.comm(), path, error);
}

template <typename MAP>
dist::DistributedMap<MAP> load_and_distribute(MPI_Comm comm, const std::string& path,
											  const dist::DistributeOptions& options, int root)
{
	int rank = 0;
	MPI_Comm_rank(comm, &rank);
	MAP serial;
	std::string error;
	if (rank == root)
	{
		try
		{
			if constexpr (MAP::dimension == 3)
				io::load_volume(serial, path);
			else
				io::load_surface(serial, path);
		}
		catch (const std::exception& e)
		{
			error = e.what();
		}
	}
	raise_everywhere(comm, path, error);
	return dist::distribute(comm, rank == root ? &serial : nullptr, options, root);
}

} // namespace

void io::save_pvtu(dist::DistributedCMap3& dm, const std::string& path, const SaveOptions& options)
{
	save_pieces(dm, path, options);
}

void io::save_pvtu(dist::DistributedCMap2& dm, const std::string& path, const SaveOptions& options)
{
	save_pieces(dm, path, options);
}

void io::save_pvtu(dist::DistributedCMap3& dm, const std::string& path)
{
	SaveOptions binary;
	binary.binary = true;
	save_pieces(dm, path, binary);
}

void io::save_pvtu(dist::DistributedCMap2& dm, const std::string& path)
{
	SaveOptions binary;
	binary.binary = true;
	save_pieces(dm, path, binary);
}

dist::DistributedCMap3 dist::load_volume(MPI_Comm comm, const std::string& path, const DistributeOptions& options,
										 int root)
{
	return load_and_distribute<CMap3>(comm, path, options, root);
}

dist::DistributedCMap2 dist::load_surface(MPI_Comm comm, const std::string& path, const DistributeOptions& options,
										  int root)
{
	return load_and_distribute<CMap2>(comm, path, options, root);
}

dist::DistributedCMap3 dist::load_volume(MPI_Comm comm, const std::string& path)
{
	return load_and_distribute<CMap3>(comm, path, DistributeOptions(), 0);
}

dist::DistributedCMap2 dist::load_surface(MPI_Comm comm, const std::string& path)
{
	return load_and_distribute<CMap2>(comm, path, DistributeOptions(), 0);
}

} // namespace cgogn
