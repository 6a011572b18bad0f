// Tests of non_iterative_denoising() (Jones et al. 2003).

#include <CGAL/Polygon_mesh_processing/non_iterative_denoising.h>

#include "classic_test_helpers.h"
#include "flat_setup.h"

#include <cstdint>
#include <stdexcept>

using namespace classic_test;

// The faces around each vertex that JDD03 averages
// (vertex_face_neighborhoods()) are, in the breadth-first order of its
// search, exactly the faces whose centroid lies within the radius and that
// are connected to the vertex through such faces: checked against a plain
// search written here from that definition, on a noisy graded octahedron,
// with both concurrency tags.
TEST(NonIterativeDenoising, VertexNeighborhoodsAreTheConnectedFacesWithinTheRadius)
{
  // 8 x 33^2 faces: above the parallel grain of the search (2048 vertices)
  Mesh mesh = denoising_support::graded_octahedron<Mesh>(33, 1.4);
  PMP::add_gaussian_noise(mesh, 0.3, CGAL::parameters::random_seed(3));
  const Flat_setup<> setup(mesh);
  const D::Flat_mesh& m = setup.m;
  const std::vector<D::Vec3>& c = setup.fd.centroids;
  const double radius = 0.75 * setup.r;
  const D::Csr sequential = D::vertex_face_neighborhoods<CGAL::Sequential_tag>(m, m.points, c, radius);
  const D::Csr parallel = D::vertex_face_neighborhoods<CGAL::Parallel_if_available_tag>(m, m.points, c, radius);
  EXPECT_EQ(sequential.offsets, parallel.offsets);
  EXPECT_EQ(sequential.items, parallel.items);
  ASSERT_EQ(sequential.size(), m.number_of_vertices());
  std::size_t total = 0;
  for(std::uint32_t v = 0; v < m.number_of_vertices(); ++v)
  {
    // plain: a face joins when it is within the radius and shares a vertex
    // with v or with a face that joined before; faces in the order reached
    std::vector<std::uint32_t> expected;
    std::vector<char> reached(m.number_of_faces(), 0);
    auto within = [&](std::uint32_t f) { return D::squared_norm(c[f] - m.points[v]) <= radius * radius; };
    auto visit_vertex = [&](std::uint32_t w) {
      for(std::uint32_t k = m.vertex_face_offsets[w]; k < m.vertex_face_offsets[w + 1]; ++k)
      {
        const std::uint32_t f = m.vertex_faces[k];
        if(!reached[f] && within(f))
        {
          reached[f] = 1;
          expected.push_back(f);
        }
      }
    };
    std::vector<char> visited(m.number_of_vertices(), 0);
    visited[v] = 1;
    visit_vertex(v);
    for(std::size_t q = 0; q < expected.size(); ++q)
      for(std::uint32_t w : m.triangles[expected[q]])
        if(!visited[w])
        {
          visited[w] = 1;
          visit_vertex(w);
        }
    const std::vector<std::uint32_t> found(sequential.items.begin() + sequential.begin(v),
                                           sequential.items.begin() + sequential.end(v));
    ASSERT_EQ(found, expected) << "vertex " << v;
    total += found.size();
  }
  // a few rings of faces on average, not the whole mesh nor nothing
  EXPECT_GT(double(total) / double(m.number_of_vertices()), 6.);
  EXPECT_LT(double(total) / double(m.number_of_vertices()), 200.);
}

TEST(NonIterativeDenoising, NoisyPlaneBecomesFlat)
{
  const Errors e = noisy_plane("JDD03", [](Mesh& m) { PMP::non_iterative_denoising(m); });
  EXPECT_GT(e.before, 15.);
  EXPECT_LT(e.after, e.before / 4.);
}

// A cube's edge vertex lies on the planes of both sides, so its predictions
// would be itself; but the mollified normals (of a copy smoothed with
// sigma_f / 2) are tilted next to the edges, so JDD03 rounds them a little.
// Measured on the 12 x 12 cube: with sigma_g = 0.1 l, E_n 1.00 deg, E_v
// 3.0e-3; with the default sigma_g = l/2, E_n 4.12 deg, E_v 1.58e-2.
TEST(NonIterativeDenoising, NoiseFreeCubeKeepsItsEdgesWithASmallSigmaG)
{
  const Errors e = noise_free_cube(
      "JDD03 (sigma_g 0.1 l)", [](Mesh& m) { PMP::non_iterative_denoising(m, CGAL::parameters::sigma_range(0.1)); });
  EXPECT_LT(e.before, 1.05);
  EXPECT_LT(e.after, 3.2e-3);
}

TEST(NonIterativeDenoising, NoiseFreeCubeWithDefaultsMeasured)
{
  const Errors e = noise_free_cube("JDD03", [](Mesh& m) { PMP::non_iterative_denoising(m); });
  EXPECT_LT(e.before, 4.5);
  EXPECT_LT(e.after, 1.7e-2);
}

TEST(NonIterativeDenoising, BadParameterThrowsAndLeavesTheMeshUnchanged)
{
  Mesh m = denoising_support::cube<Mesh>(3);
  const auto before = positions(m);
  EXPECT_THROW(PMP::non_iterative_denoising(m, CGAL::parameters::sigma_range(-1.)), std::invalid_argument);
  EXPECT_EQ(max_distance(before, positions(m)), 0.);
  Mesh empty;
  PMP::non_iterative_denoising(empty);
  EXPECT_TRUE(empty.is_empty());
}
