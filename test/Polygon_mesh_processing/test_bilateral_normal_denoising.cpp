// Tests of bilateral_normal_denoising() (Zheng et al. 2011, local scheme).

#include <CGAL/Polygon_mesh_processing/bilateral_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include "classic_test_helpers.h"

#include <stdexcept>

using namespace classic_test;

TEST(BilateralNormalDenoising, NoisyPlaneBecomesFlat)
{
  const Errors e = noisy_plane("ZFAT11", [](Mesh &m) { PMP::bilateral_normal_denoising(m); });
  EXPECT_GT(e.before, 15.);
  EXPECT_LT(e.after, e.before / 10.);
}

TEST(BilateralNormalDenoising, NoiseFreeCubeKeepsItsEdges)
{
  const Errors e = noise_free_cube("ZFAT11", [](Mesh &m) { PMP::bilateral_normal_denoising(m); });
  // Across an edge the range kernel weighs exp(-2 / 2 sigma_r^2) ~ 3e-4, not 0,
  // so over 20 passes the edges move a little: measured E_n 0.021 deg, E_v
  // 7.6e-5. A rounded edge would give degrees.
  EXPECT_LT(e.before, 0.025);
  EXPECT_LT(e.after, 1e-4);
}

// With a radius, the neighbourhood is the geometric one of intrinsic_denoising().
TEST(BilateralNormalDenoising, GeometricNeighborhoodOption)
{
  const Errors e = noisy_plane("ZFAT11 (radius 2d)", [](Mesh &m)
                               { PMP::bilateral_normal_denoising(m, CGAL::parameters::relative_neighbor_radius(2.)); });
  EXPECT_LT(e.after, e.before / 10.);
}

TEST(BilateralNormalDenoising, SurfaceMeshAndPolyhedronGiveTheSameResult)
{
  EXPECT_LE(surface_mesh_vs_polyhedron([](auto &m) { PMP::bilateral_normal_denoising(m); }), 1e-12);
}

TEST(BilateralNormalDenoising, BadSigmaThrowsAndLeavesTheMeshUnchanged)
{
  Mesh m = denoising_test::cube<Mesh>(3);
  const auto before = positions(m);
  EXPECT_THROW(PMP::bilateral_normal_denoising(m, CGAL::parameters::sigma_range(0.)), std::invalid_argument);
  EXPECT_THROW(PMP::bilateral_normal_denoising(m, CGAL::parameters::sigma_spatial(-1.)), std::invalid_argument);
  EXPECT_THROW(PMP::bilateral_normal_denoising(m, CGAL::parameters::relative_neighbor_radius(0.)),
               std::invalid_argument);
  EXPECT_EQ(max_distance(before, positions(m)), 0.);
}

TEST(BilateralNormalDenoising, ConstrainedVerticesDoNotMove)
{
  constrained_vertices_do_not_move(
      [](Mesh &m, auto pinned)
      { PMP::bilateral_normal_denoising(m, CGAL::parameters::vertex_is_constrained_map(pinned)); });
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(BilateralNormalDenoising, ParallelEqualsSequential)
{
  EXPECT_EQ(parallel_vs_sequential([](Mesh &m) { PMP::bilateral_normal_denoising<CGAL::Sequential_tag>(m); },
                                   [](Mesh &m) { PMP::bilateral_normal_denoising<CGAL::Parallel_tag>(m); }),
            0.);
}
#endif

TEST(BilateralNormalDenoising, FaceNormalMapReceivesUnitFilteredNormals)
{
  Mesh mesh = denoising_test::cube<Mesh>(6);
  PMP::add_gaussian_noise(mesh, 0.2, CGAL::parameters::random_seed(4));
  auto fnm = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:filtered", CGAL::NULL_VECTOR).first;
  PMP::bilateral_normal_denoising(mesh, CGAL::parameters::face_normal_map(fnm));
  for(auto f : faces(mesh))
  {
    const K::Vector_3 n = get(fnm, f);
    EXPECT_NEAR(n.squared_length(), 1., 1e-12);
    const double mx = (std::max)({std::abs(n.x()), std::abs(n.y()), std::abs(n.z())});
    EXPECT_GT(mx, 0.9); // close to one axis of the cube
  }
}
