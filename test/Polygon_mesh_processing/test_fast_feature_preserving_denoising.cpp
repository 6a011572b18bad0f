// Tests of fast_feature_preserving_denoising() (Sun et al. 2007).

#include <CGAL/Polygon_mesh_processing/fast_feature_preserving_denoising.h>

#include "classic_test_helpers.h"

#include <stdexcept>

using namespace classic_test;

TEST(FastFeaturePreservingDenoising, NoisyPlaneBecomesFlat)
{
  const Errors e = noisy_plane("SRML07", [](Mesh &m) { PMP::fast_feature_preserving_denoising(m); });
  EXPECT_GT(e.before, 15.);
  EXPECT_LT(e.after, e.before / 10.);
}

TEST(FastFeaturePreservingDenoising, NoiseFreeCubeKeepsItsEdges)
{
  const Errors e = noise_free_cube("SRML07", [](Mesh &m) { PMP::fast_feature_preserving_denoising(m); });
  // n_i . n_j = 0 <= T across an edge: the two sides never mix
  EXPECT_LT(e.before, 1e-9);
  EXPECT_LT(e.after, 1e-9);
}

TEST(FastFeaturePreservingDenoising, EdgeNeighborhoodAlsoSmooths)
{
  const Errors e =
      noisy_plane("SRML07 (edge neighbours)", [](Mesh &m)
                  { PMP::fast_feature_preserving_denoising(m, CGAL::parameters::use_vertex_neighborhood(false)); });
  EXPECT_LT(e.after, e.before / 5.);
}

TEST(FastFeaturePreservingDenoising, SurfaceMeshAndPolyhedronGiveTheSameResult)
{
  EXPECT_LE(surface_mesh_vs_polyhedron([](auto &m) { PMP::fast_feature_preserving_denoising(m); }), 1e-12);
}

TEST(FastFeaturePreservingDenoising, BadThresholdThrowsAndLeavesTheMeshUnchanged)
{
  Mesh m = denoising_test::cube<Mesh>(3);
  const auto before = positions(m);
  EXPECT_THROW(PMP::fast_feature_preserving_denoising(m, CGAL::parameters::normal_threshold(1.)),
               std::invalid_argument);
  EXPECT_THROW(PMP::fast_feature_preserving_denoising(m, CGAL::parameters::normal_threshold(-0.1)),
               std::invalid_argument);
  EXPECT_EQ(max_distance(before, positions(m)), 0.);
  Mesh empty;
  PMP::fast_feature_preserving_denoising(empty);
  EXPECT_TRUE(empty.is_empty());
}

TEST(FastFeaturePreservingDenoising, ConstrainedVerticesDoNotMove)
{
  constrained_vertices_do_not_move(
      [](Mesh &m, auto pinned)
      { PMP::fast_feature_preserving_denoising(m, CGAL::parameters::vertex_is_constrained_map(pinned)); });
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(FastFeaturePreservingDenoising, ParallelEqualsSequential)
{
  EXPECT_EQ(parallel_vs_sequential([](Mesh &m) { PMP::fast_feature_preserving_denoising<CGAL::Sequential_tag>(m); },
                                   [](Mesh &m) { PMP::fast_feature_preserving_denoising<CGAL::Parallel_tag>(m); }),
            0.);
}
#endif

TEST(FastFeaturePreservingDenoising, FaceNormalMapReceivesUnitFilteredNormals)
{
  Mesh mesh = denoising_test::cube<Mesh>(6);
  PMP::add_gaussian_noise(mesh, 0.2, CGAL::parameters::random_seed(4));
  auto fnm = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:filtered", CGAL::NULL_VECTOR).first;
  PMP::fast_feature_preserving_denoising(mesh, CGAL::parameters::face_normal_map(fnm));
  for(auto f : faces(mesh))
  {
    const K::Vector_3 n = get(fnm, f);
    EXPECT_NEAR(n.squared_length(), 1., 1e-12);
    const double mx = (std::max)({std::abs(n.x()), std::abs(n.y()), std::abs(n.z())});
    EXPECT_GT(mx, 0.9); // close to one axis of the cube
  }
}
