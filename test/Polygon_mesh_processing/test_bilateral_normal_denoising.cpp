// Tests of bilateral_normal_denoising() (Zheng et al. 2011, local scheme).

#include <CGAL/Polygon_mesh_processing/bilateral_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include "classic_test_helpers.h"

#include <stdexcept>

using namespace classic_test;

TEST(BilateralNormalDenoising, NoisyPlaneBecomesFlat)
{
  const Errors e = noisy_plane("ZFAT11", [](Mesh& m) { PMP::bilateral_normal_denoising(m); });
  EXPECT_GT(e.before, 15.);
  EXPECT_LT(e.after, e.before / 10.);
}

TEST(BilateralNormalDenoising, NoiseFreeCubeKeepsItsEdges)
{
  const Errors e = noise_free_cube("ZFAT11", [](Mesh& m) { PMP::bilateral_normal_denoising(m); });
  EXPECT_LT(e.before, 0.5);
  EXPECT_LT(e.after, 1e-3);
}

// With a radius, the neighbourhood is the geometric one of intrinsic_denoising().
TEST(BilateralNormalDenoising, GeometricNeighborhoodOption)
{
  const Errors e = noisy_plane("ZFAT11 (radius 2d)", [](Mesh& m) {
    PMP::bilateral_normal_denoising(m, CGAL::parameters::relative_neighbor_radius(2.));
  });
  EXPECT_LT(e.after, e.before / 10.);
}

TEST(BilateralNormalDenoising, SurfaceMeshAndPolyhedronGiveTheSameResult)
{
  EXPECT_LE(surface_mesh_vs_polyhedron([](auto& m) { PMP::bilateral_normal_denoising(m); }), 1e-12);
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
