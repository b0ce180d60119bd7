// The "Parallelism" section of the CGoGN API guide: a parallel displacement of the
// vertices, then the average edge length reduced with per-thread slots
// indexed by current_thread_index().
#include <cgogn/cgogn.h>

#include <cmath>
#include <iostream>
#include <vector>

using namespace cgogn;

int main()
{
	using Vertex = CMap2::Vertex;
	using Edge = CMap2::Edge;

	CMap2 m;
	SurfaceSoup soup = torus_soup(200, 100, true);
	BuildReport report = build_surface(m, soup);
	auto position = add_attribute<Vec3, Vertex>(m, "position");
	auto displacement = add_attribute<Vec3, Vertex>(m, "displacement");
	for (uint32 i = 0; i < soup.nb_vertices; ++i)
	{
		const auto& p = soup.positions[i];
		(*position)[report.vertex_offset + i] = Vec3(p[0], p[1], p[2]);
	}
	parallel_foreach_cell(m, [&](Vertex v) { value(m, displacement, v) = 0.1 * value(m, position, v); });

	// given two AttributeArray<Vec3> position, displacement on VERTEX
	parallel_foreach_cell(m, [&](Vertex v) { value(m, position, v) += value(m, displacement, v); });

	auto length = add_attribute<double, Edge>(m, "length");
	parallel_foreach_cell(m, [&](Edge e) {
		value(m, length, e) = (value(m, position, Vertex(e.dart)) - value(m, position, Vertex(phi2(m, e.dart)))).norm();
	});

	// given a Mesh m, given an attribute of type double on Edge length
	std::vector<double> sum_per_thread(thread_pool()->nb_workers(), 0.0);
	std::vector<uint32> nb_per_thread(thread_pool()->nb_workers(), 0);
	parallel_foreach_cell(m, [&](Edge e) {
		uint32 thread_index = current_thread_index();
		sum_per_thread[thread_index] += value<double>(m, length, e);
		nb_per_thread[thread_index]++;
	});
	double sum = 0.0;
	for (double d : sum_per_thread)
		sum += d;
	uint32 nb = 0;
	for (uint32 n : nb_per_thread)
		nb += n;
	double average = sum / double(nb);

	// the same, sequentially
	double seq_sum = 0.0;
	uint32 seq_nb = 0;
	foreach_cell(m, [&](Edge e) {
		seq_sum += value<double>(m, length, e);
		++seq_nb;
	});
	std::cout << thread_pool()->nb_workers() << " workers, " << nb << " edges, average length " << average
			  << " (sequential: " << seq_sum / seq_nb << ")\n";
	return nb == seq_nb && std::abs(average - seq_sum / seq_nb) < 1e-12 ? 0 : 1;
}
