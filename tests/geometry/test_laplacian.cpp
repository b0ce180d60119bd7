// SPDX-License-Identifier: MIT
#include "geometry_test_meshes.h"

#include <gtest/gtest.h>

namespace cgogn_test_laplacian
{

using namespace cgogn;
using namespace cgogn::geometry;
using cgogn::test::build_with_positions;
using Vertex = CMap2::Vertex;

namespace
{
void expect_symmetric_zero_rows(const SparseMatrix& L)
{
	const SparseMatrix T = L.transpose();
	EXPECT_NEAR((L - T).norm(), 0.0, 1e-12 * L.norm());
	const Eigen::VectorXd rows = L * Eigen::VectorXd::Ones(L.cols());
	EXPECT_NEAR(rows.cwiseAbs().maxCoeff(), 0.0, 1e-12);
	for (int i = 0; i < L.rows(); ++i)
		EXPECT_LT(L.coeff(i, i), 0.0);
}

Eigen::MatrixXd positions_matrix(const CMap2& m, const AttributeArray<Vec3>& pos, const VertexNumbering& num)
{
	Eigen::MatrixXd x(num.size(), 3);
	foreach_cell(m, [&](Vertex v) { x.row(num[index_of(m, v)]) = value<Vec3>(m, pos, v).transpose(); });
	return x;
}
} // namespace

TEST(Laplacian, NumberingIsDense)
{
	CMap2 m;
	build_with_positions(m, sphere_soup(8, 5));
	const VertexNumbering num = vertex_numbering(m);
	EXPECT_EQ(num.size(), nb_cells<Vertex>(m));
	std::vector<bool> seen(num.size(), false);
	foreach_cell(m, [&](Vertex v) {
		const uint32 i = num[index_of(m, v)];
		ASSERT_LT(i, num.size());
		EXPECT_FALSE(seen[i]);
		seen[i] = true;
		EXPECT_EQ(num.line_of_dense_[i], index_of(m, v));
	});
}

TEST(Laplacian, MatricesAreSymmetricWithZeroRowSums)
{
	for (const SurfaceSoup& s : {sphere_soup(12, 7, true), sphere_soup(12, 7), torus_soup(9, 6), grid_soup(4, 3),
								 grid_soup(4, 3, true), cylinder_soup(7, 3, true)})
	{
		CMap2 m;
		auto pos = build_with_positions(m, s);
		const VertexNumbering num = vertex_numbering(m);
		const SparseMatrix L = cotan_laplacian(m, *pos, num);
		expect_symmetric_zero_rows(L);
		const SparseMatrix U = uniform_laplacian(m, num);
		expect_symmetric_zero_rows(U);
		foreach_cell(m, [&](Vertex v) {
			const int i = int(num[index_of(m, v)]);
			EXPECT_EQ(U.coeff(i, i), -double(degree(m, v)));
		});
		const SparseMatrix M = mass_matrix(m, *pos, num);
		EXPECT_NEAR(M.diagonal().sum(), surface_area(m, *pos), 1e-12);
	}
	CMap3 v;
	build_with_positions(v, tet_grid_soup(2, 2, 2));
	const SparseMatrix U = uniform_laplacian(v, vertex_numbering(v));
	expect_symmetric_zero_rows(U);
}

TEST(Laplacian, CotanIsNegativeSemiDefiniteOnNoisyMeshes)
{
	for (bool triangles : {true, false})
	{
		CMap2 m;
		auto pos = build_with_positions(m, torus_soup(12, 8, triangles));
		uint32 i = 0;
		for (Vec3& p : *pos)
			p += 0.08 * Vec3(test::noise(i), test::noise(i + 300), test::noise(i + 600)), ++i;
		const VertexNumbering num = vertex_numbering(m);
		const SparseMatrix L = cotan_laplacian(m, *pos, num);
		bool some_negative_weight = false;
		for (int c = 0; c < L.outerSize(); ++c)
			for (SparseMatrix::InnerIterator e(L, c); e; ++e)
				some_negative_weight = some_negative_weight || (e.row() != e.col() && e.value() < 0.0);
		EXPECT_TRUE(some_negative_weight); // obtuse angles are present
		for (uint32 k = 0; k < 20; ++k)
		{
			Eigen::VectorXd f(num.size());
			for (uint32 j = 0; j < num.size(); ++j)
				f(j) = test::noise(1000 * k + j);
			EXPECT_LE(f.dot(L * f), 1e-12);
		}
	}
}

TEST(Laplacian, CotanWeightsOfAKnownGrid)
{
	// each unit square split along (i, j)-(i+1, j+1): the diagonals face right
	// angles (weight 0), the axis edges 45-degree angles (1/2 per triangle)
	CMap2 m;
	auto pos = build_with_positions(m, grid_soup(3, 3, true));
	const VertexNumbering num = vertex_numbering(m);
	const SparseMatrix L = cotan_laplacian(m, *pos, num);
	foreach_cell(m, [&](CMap2::Edge e) {
		const int a = int(num[index_of(m, Vertex(e.dart))]);
		const int b = int(num[index_of(m, Vertex(phi1(m, e.dart)))]);
		const Vec3 d = value<Vec3>(m, pos, Vertex(phi1(m, e.dart))) - value<Vec3>(m, pos, Vertex(e.dart));
		const double expected = std::abs(d.x()) > 0.5 && std::abs(d.y()) > 0.5 ? 0.0 : 0.5 * degree(m, e);
		EXPECT_NEAR(L.coeff(a, b), expected, 1e-15);
	});
}

TEST(Laplacian, ReproducesLinearFunctionsAndTheirEnergy)
{
	// on planar meshes the cotangent Laplacian of a linear function vanishes
	// inside, and -f^T L f is its Dirichlet energy (area x |grad f|^2)
	for (bool triangles : {false, true})
	{
		CMap2 m;
		auto pos = build_with_positions(m, grid_soup(5, 4, triangles));
		uint32 i = 0;
		for (Vec3& p : *pos) // a non-uniform but still planar grid
			p += 0.2 * Vec3(test::noise(i), test::noise(i + 77), 0.0), ++i;
		const VertexNumbering num = vertex_numbering(m);
		const SparseMatrix L = cotan_laplacian(m, *pos, num);
		const Eigen::MatrixXd x = positions_matrix(m, *pos, num);
		const Eigen::VectorXd f = 2.0 * x.col(0) - 3.0 * x.col(1) + Eigen::VectorXd::Constant(x.rows(), 1.5);
		const Eigen::VectorXd lf = L * f;
		foreach_cell(m, [&](Vertex v) {
			if (!is_incident_to_boundary(m, v))
			{
				EXPECT_NEAR(lf(num[index_of(m, v)]), 0.0, 1e-12);
			}
		});
		EXPECT_NEAR(-f.dot(lf), 13.0 * surface_area(m, *pos), 1e-10);
	}
}

TEST(Laplacian, PolygonsGiveTheSameAsTheirRefinement)
{
	// a quad mesh versus the same mesh where each quad is fanned around its centroid:
	// the quad matrix is the refined one with the centroids eliminated
	CMap2 q;
	auto qpos = build_with_positions(q, sphere_soup(8, 5));
	const VertexNumbering qn = vertex_numbering(q);
	const Eigen::MatrixXd x = positions_matrix(q, *qpos, qn);
	const Eigen::VectorXd ex = (cotan_laplacian(q, *qpos, qn) * x.col(2));

	SurfaceSoup s = sphere_soup(8, 5);
	SurfaceSoup r;
	r.nb_vertices = s.nb_vertices;
	r.positions = s.positions;
	std::vector<std::vector<uint32>> quads;
	uint32 k = 0;
	for (uint32 sz : s.face_sizes)
	{
		const uint32* fv = &s.face_vertices[k];
		k += sz;
		if (sz == 3)
		{
			r.face_sizes.push_back(3);
			r.face_vertices.insert(r.face_vertices.end(), fv, fv + 3);
			continue;
		}
		std::array<double, 3> c = {0, 0, 0};
		for (uint32 j = 0; j < sz; ++j)
			for (int a = 0; a < 3; ++a)
				c[a] += s.positions[fv[j]][a] / sz;
		const uint32 ci = r.nb_vertices++;
		r.positions.push_back(c);
		for (uint32 j = 0; j < sz; ++j)
		{
			r.face_sizes.push_back(3);
			r.face_vertices.insert(r.face_vertices.end(), {fv[j], fv[(j + 1) % sz], ci});
		}
	}
	CMap2 t;
	auto tpos = build_with_positions(t, r);
	const VertexNumbering tn = vertex_numbering(t);
	const SparseMatrix Lt = cotan_laplacian(t, *tpos, tn);
	// prolongation: original vertices keep their value, centroids take the mean
	Eigen::VectorXd z = Eigen::VectorXd::Zero(tn.size());
	foreach_cell(t, [&](Vertex v) { z(tn[index_of(t, v)]) = value<Vec3>(t, tpos, v).z(); });
	Eigen::VectorXd lz = Lt * z;
	// restriction: each centroid's row goes back to its quad's vertices by 1/4
	k = 0;
	uint32 centroid_id = s.nb_vertices;
	for (uint32 sz : s.face_sizes)
	{
		const uint32* fv = &s.face_vertices[k];
		k += sz;
		if (sz == 3)
			continue;
		const double share = lz(tn[centroid_id++]) / sz;
		for (uint32 j = 0; j < sz; ++j)
			lz(tn[fv[j]]) += share;
	}
	// both maps number the original soup vertices 0..n-1 the same way
	for (uint32 v = 0; v < s.nb_vertices; ++v)
		EXPECT_NEAR(ex(qn[v]), lz(tn[v]), 1e-12);
}

} // namespace cgogn_test_laplacian
