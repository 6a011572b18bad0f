// Tests of non_iterative_denoising() (Jones et al. 2003).

#include <CGAL/Polygon_mesh_processing/non_iterative_denoising.h>

#include "classic_test_helpers.h"

#include <stdexcept>

using namespace classic_test;

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
  Mesh m = denoising_test::cube<Mesh>(3);
  const auto before = positions(m);
  EXPECT_THROW(PMP::non_iterative_denoising(m, CGAL::parameters::sigma_range(-1.)), std::invalid_argument);
  EXPECT_EQ(max_distance(before, positions(m)), 0.);
  Mesh empty;
  PMP::non_iterative_denoising(empty);
  EXPECT_TRUE(empty.is_empty());
}
