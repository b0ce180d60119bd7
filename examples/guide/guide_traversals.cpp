// The CGoGN API guide's "Global traversals", "Early stop" and "Parallelism"
// sections, written as a user writes them.
#include <cgogn/cgogn.h>

#include <iostream>
#include <vector>

using namespace cgogn;

using Mesh = CMap2;
using Vertex = typename mesh_traits<Mesh>::Vertex;
using Edge = typename mesh_traits<Mesh>::Edge;
template <typename T>
using Attribute = typename mesh_traits<Mesh>::template Attribute<T>;

int main()
{
	Mesh m;
	build_surface(m, grid_soup(8, 8));
	auto position = add_attribute<Vec3, Vertex>(m, "position");
	auto displacement = add_attribute<Vec3, Vertex>(m, "displacement");
	uint32 k = 0;
	foreach_cell(m, [&](Vertex v) {
		value<Vec3>(m, position, v) = Vec3(double(k % 9) - 4.0, double(k / 9), 0.0);
		value<Vec3>(m, displacement, v) = Vec3(0.0, 0.0, 1.0);
		++k;
	});

	uint32 nb_vertices = 0;
	foreach_cell(m, [&](Vertex v) {
		// do something with v
		(void)v;
		++nb_vertices;
	});

	// early stop: the first vertex on the negative side of the x = 0 plane
	Vertex looked_up_v;
	foreach_cell(m, [&](Vertex v) -> bool {
		if (value<Vec3>(m, position, v)[0] < 0.0)
		{
			looked_up_v = v;
			return false;
		}
		return true;
	});
	if (!looked_up_v.is_valid())
	{
		// no such vertex was found
		return 1;
	}

	// parallel: add the displacement of each vertex to its position
	parallel_foreach_cell(m, [&](Vertex v) { value(m, position, v) += value(m, displacement, v); });

	// parallel reduction: the average of an Edge attribute
	auto length_attribute = add_attribute<double, Edge>(m, "length");
	Attribute<double>& length = *length_attribute;
	foreach_cell(m, [&](Edge e) { length[e] = 1.0; });
	std::vector<double> sum_per_thread(thread_pool()->nb_workers(), 0.0);
	std::vector<uint32> nb_per_thread(thread_pool()->nb_workers(), 0);
	parallel_foreach_cell(m, [&](Edge e) {
		uint32 thread_index = current_thread_index();
		sum_per_thread[thread_index] += length[e];
		nb_per_thread[thread_index]++;
	});
	double sum = 0.0;
	for (double d : sum_per_thread)
		sum += d;
	uint32 nb = 0;
	for (uint32 n : nb_per_thread)
		nb += n;
	double average = sum / double(nb);

	bool moved = true;
	foreach_cell(m, [&](Vertex v) { moved = moved && value<Vec3>(m, position, v)[2] == 1.0; });
	std::cout << nb_vertices << " vertices, average edge length " << average << "\n";
	return nb_vertices == 81 && nb == nb_cells<Edge>(m) && average == 1.0 && moved ? 0 : 1;
}
