// Tests of bilateral_mesh_denoising() (Fleishman et al. 2003).

#include <CGAL/Polygon_mesh_processing/bilateral_mesh_denoising.h>

#include "classic_test_helpers.h"

#include <stdexcept>

using namespace classic_test;

TEST(BilateralMeshDenoising, NoisyPlaneBecomesFlat)
{
  const Errors e = noisy_plane("FDC03", [](Mesh& m) { PMP::bilateral_mesh_denoising(m); });
  EXPECT_GT(e.before, 15.);
  EXPECT_LT(e.after, e.before / 8.);
}

// FDC03 moves a vertex along its normal; on a cube edge that normal bisects
// the two sides and every neighbour lies below it, so the edge vertices sink
// whatever the sigmas: FDC03 rounds strong edges, as the paper notes for its
// Fig. 7. With a small fixed sigma_s (0.1 l), in the first iteration the other
// vertices do not move (the points across an edge, about l away along the
// normal, weigh exp(-50)); over the 5 default iterations the rounding spreads
// a little: measured E_n 1.86 deg, E_v 8.6e-3. With the
// paper's adaptive sigma_s (the spread of the offsets, large next to an edge)
// the rounding spreads: measured E_n 15.75 deg, E_v 6.05e-2.
TEST(BilateralMeshDenoising, NoiseFreeCubeKeepsItsEdgesWithASmallSigmaS)
{
  Mesh cube = denoising_support::cube<Mesh>(12);
  const auto before = positions(cube);
  const Errors e = noise_free_cube(
      "FDC03 (sigma_s 0.1 l)", [](Mesh& m) { PMP::bilateral_mesh_denoising(m, CGAL::parameters::sigma_range(0.1)); });
  EXPECT_LT(e.before, 2.0);
  EXPECT_LT(e.after, 9e-3);
  PMP::bilateral_mesh_denoising(cube, CGAL::parameters::sigma_range(0.1).number_of_iterations(1));
  const auto after = positions(cube);
  double off_edge_move = 0.;
  for(std::size_t v = 0; v < before.size(); ++v)
  {
    int on_side = 0; // coordinates at +-1
    for(int k = 0; k < 3; ++k)
      on_side += std::abs(std::abs(before[v][k]) - 1.) < 1e-12 ? 1 : 0;
    if(on_side == 1)
      off_edge_move = (std::max)(off_edge_move, std::sqrt(CGAL::squared_distance(before[v], after[v])));
  }
  std::printf("FDC03 (sigma_s 0.1 l), noise-free cube: one iteration: largest move of a vertex off the edges %.3e\n",
              off_edge_move);
  EXPECT_LT(off_edge_move, 1e-12);
}

TEST(BilateralMeshDenoising, NoiseFreeCubeWithAdaptiveSigmaSMeasured)
{
  const Errors e = noise_free_cube("FDC03", [](Mesh& m) { PMP::bilateral_mesh_denoising(m); });
  EXPECT_LT(e.before, 16.5);
  EXPECT_LT(e.after, 6.5e-2);
}

TEST(BilateralMeshDenoising, BadParameterThrowsAndLeavesTheMeshUnchanged)
{
  Mesh m = denoising_support::cube<Mesh>(3);
  const auto before = positions(m);
  EXPECT_THROW(PMP::bilateral_mesh_denoising(m, CGAL::parameters::sigma_spatial(0.)), std::invalid_argument);
  EXPECT_EQ(max_distance(before, positions(m)), 0.);
  Mesh empty;
  PMP::bilateral_mesh_denoising(empty);
  EXPECT_TRUE(empty.is_empty());
}
