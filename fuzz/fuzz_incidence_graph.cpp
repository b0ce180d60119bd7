// SPDX-License-Identifier: MIT
// The libFuzzer target of the incidence graph's `.ig` reader. Any input must
// either throw io::Error or give a complex that passes check_integrity with
// the counts read, whether loaded into an empty incidence graph or appended
// to one. Loading into one whose `position` has another type must throw and
// leave it as it was. Crashes, leaks and sanitizer reports are bugs.
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/operators/incidence_graph.h>
#include <cgogn/core/properties/integrity.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/io/error.h>

#include "incidence_graph_data.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

using namespace cgogn;
using IG = IncidenceGraph;

namespace
{

void require(bool ok)
{
	if (!ok)
		std::abort();
}

void check_load(IG& ig, const io::detail::IgData& d)
{
	const uint32 v = nb_cells<IG::Vertex>(ig), e = nb_cells<IG::Edge>(ig), f = nb_cells<IG::Face>(ig);
	const io::IncidenceGraphLoadReport r = io::detail::build_incidence_graph(ig, d, "fuzz");
	require(check_integrity(ig).ok());
	require(nb_cells<IG::Vertex>(ig) == v + r.nb_vertices_read);
	require(nb_cells<IG::Edge>(ig) == e + r.nb_edges_read);
	require(nb_cells<IG::Face>(ig) == f + r.nb_faces_read);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const std::string_view text(reinterpret_cast<const char*>(data), size);
	io::detail::IgData d;
	try
	{
		d = io::detail::read_ig(text, "fuzz");
	}
	catch (const io::Error&)
	{
		return 0;
	}
	{
		IG ig;
		check_load(ig, d);
	}
	{
		// appended to a complex with a triangle, a wire and a lone vertex
		IG ig;
		add_attribute<int, IG::Face>(ig, "tag");
		std::vector<IG::Vertex> v;
		for (int i = 0; i < 5; ++i)
			v.push_back(add_vertex(ig));
		const std::vector<IG::Vertex> tri = {v[0], v[1], v[2]};
		add_face_through_vertices(ig, tri);
		add_edge(ig, v[2], v[3]);
		check_load(ig, d);
	}
	{
		IG ig;
		add_attribute<double, IG::Vertex>(ig, "position");
		add_vertex(ig);
		bool thrown = false;
		try
		{
			io::detail::build_incidence_graph(ig, d, "fuzz");
		}
		catch (const io::Error&)
		{
			thrown = true;
		}
		require(thrown && nb_cells<IG::Vertex>(ig) == 1 && check_integrity(ig).ok());
	}
	return 0;
}
