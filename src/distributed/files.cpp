// SPDX-License-Identifier: MIT
#include <cgogn/core/traversals/global.h>
#include <cgogn/distributed/files.h>
#include <cgogn/io/error.h>
#include <cgogn/io/pvtu.h>
#include <cgogn/io/surface.h>
#include <cgogn/io/volume.h>

#include "collective_failure.h"

#include <filesystem>

namespace cgogn
{

namespace
{

// An array a piece carries while it is written: the map's attribute of
// that name and type, or one added for the write and removed after it.
template <typename T, typename CELL, typename MAP>
class PieceArray
{
public:
	PieceArray(MAP& m, const std::string& name, const std::string& path) : m_(m), attr_(get_attribute<T, CELL>(m, name))
	{
		if (attr_ == nullptr)
		{
			attr_ = add_attribute<T, CELL>(m, name);
			added_ = true;
		}
		if (attr_ == nullptr)
			throw io::Error(path, "the map has an attribute named " + name + " of another type");
	}
	PieceArray(const PieceArray&) = delete;
	PieceArray& operator=(const PieceArray&) = delete;
	~PieceArray()
	{
		if (added_)
			remove_attribute(m_, attr_);
	}
	T& operator[](CELL c)
	{
		return (*attr_)[c];
	}

private:
	MAP& m_;
	std::shared_ptr<CellAttribute<T, CELL::ORBIT>> attr_;
	bool added_ = false;
};

template <typename MAP>
void save_pieces(dist::DistributedMap<MAP>& dm, const std::string& path, const io::SaveOptions& options)
{
	using Vertex = typename MAP::Vertex;
	using Top = typename dist::DistributedMap<MAP>::TopCell;
	MAP& m = dm.map();
	const std::filesystem::path p(path);
	auto piece_name = [&](int r) { return p.stem().string() + "_" + std::to_string(r) + ".vtu"; };
	dist::detail::on_every_rank(dm.comm(), [&] {
		PieceArray<uint64, Vertex, MAP> node_ids(m, "GlobalNodeIds", path);
		PieceArray<uint8, Vertex, MAP> node_ghost(m, "vtkGhostType", path);
		PieceArray<uint64, Top, MAP> cell_ids(m, "GlobalCellIds", path);
		PieceArray<uint8, Top, MAP> cell_ghost(m, "vtkGhostType", path);
		foreach_cell(m, [&](Vertex v) {
			node_ids[v] = dist::global_id(dm, v);
			node_ghost[v] = dist::is_owned(dm, v) ? 0 : 1;
		});
		foreach_cell(m, [&](Top c) {
			cell_ids[c] = dist::global_id(dm, c);
			cell_ghost[c] = dist::is_owned(dm, c) ? 0 : 1;
		});
		io::SaveOptions piece = options;
		piece.format = io::Format::Vtu;
		const std::string piece_path = (p.parent_path() / piece_name(dm.rank())).string();
		if constexpr (MAP::dimension == 3)
			io::save_volume(m, piece_path, piece);
		else
			io::save_surface(m, piece_path, piece);
	});
	dist::detail::on_every_rank(dm.comm(), [&] {
		if (dm.rank() != 0)
			return;
		std::vector<std::string> sources;
		for (int r = 0; r < dm.nb_ranks(); ++r)
			sources.push_back(piece_name(r));
		io::write_pvtu_index(path, sources, 1);
	});
}

template <typename MAP>
dist::DistributedMap<MAP> load_and_distribute(MPI_Comm comm, const std::string& path,
											  const dist::DistributeOptions& options, int root)
{
	int rank = 0;
	MPI_Comm_rank(comm, &rank);
	MAP serial;
	dist::detail::on_every_rank(comm, [&] {
		if (rank != root)
			return;
		if constexpr (MAP::dimension == 3)
			io::load_volume(serial, path);
		else
			io::load_surface(serial, path);
	});
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
