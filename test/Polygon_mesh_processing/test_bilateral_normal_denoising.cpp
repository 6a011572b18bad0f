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
  // Across an edge the range kernel weighs exp(-2 / 2 sigma_r^2) ~ 3e-4, not 0,
  // so over 20 passes the edges move a little: measured E_n 0.021 deg, E_v
  // 7.6e-5. A rounded edge would give degrees.
  EXPECT_LT(e.before, 0.025);
  EXPECT_LT(e.after, 1e-4);
}

// With a radius, the neighbourhood is the geometric one of intrinsic_denoising().
TEST(BilateralNormalDenoising, GeometricNeighborhoodOption)
{
  const Errors e = noisy_plane("ZFAT11 (radius 2d)", [](Mesh& m) {
    PMP::bilateral_normal_denoising(m, CGAL::parameters::relative_neighbor_radius(2.));
  });
  EXPECT_LT(e.after, e.before / 10.);
}

TEST(BilateralNormalDenoising, BadSigmaThrowsAndLeavesTheMeshUnchanged)
{
  Mesh m = denoising_support::cube<Mesh>(3);
  const auto before = positions(m);
  EXPECT_THROW(PMP::bilateral_normal_denoising(m, CGAL::parameters::sigma_range(0.)), std::invalid_argument);
  EXPECT_THROW(PMP::bilateral_normal_denoising(m, CGAL::parameters::sigma_spatial(-1.)), std::invalid_argument);
  EXPECT_THROW(PMP::bilateral_normal_denoising(m, CGAL::parameters::relative_neighbor_radius(0.)),
               std::invalid_argument);
  EXPECT_EQ(max_distance(before, positions(m)), 0.);
}

TEST(BilateralNormalDenoising, FaceNormalMapReceivesUnitFilteredNormals)
{
  Mesh mesh = denoising_support::cube<Mesh>(6);
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

// The engine with direct paths, phi = centroid, psi = normal, n = m = 2 gives
// ZFAT11's weights A_j W_s(|c_i - c_j|) W_r(|n_i - n_j|), computed here by hand
// for face 0 with neighbours 1 and 2 (and itself, weight A_0).
TEST(BilateralNormalDenoising, EnginePassGivesTheHandComputedWeights)
{
  namespace D = PMP::internal::Denoising;
  D::Csr neighbors;
  neighbors.offsets = {0, 2, 2, 2};
  neighbors.items = {1, 2};
  const D::Path_forest direct = D::direct_paths(neighbors);
  const double s = std::sqrt(0.5);
  D::Face_data fd;
  fd.normals = {{0, 0, 1}, {0, s, s}, {0, 1, 0}};
  fd.areas = {1., 2., 3.};
  fd.centroids = {{0, 0, 0}, {0.5, 0, 0}, {0, 1.5, 0}};
  const double sigma_s = 0.8, sigma_r = 0.6;
  std::vector<D::Vec3> out;
  D::bilateral_normal_pass<CGAL::Sequential_tag>(direct, fd, fd.normals, sigma_s, sigma_r, out);
  auto g = [](double x2, double sigma) { return std::exp(-x2 / (2 * sigma * sigma)); };
  const double w1 = 2. * g(0.25, sigma_s) * g(2. - std::sqrt(2.), sigma_r); // |n1 - n0|^2 = 2 - sqrt 2
  const double w2 = 3. * g(2.25, sigma_s) * g(2., sigma_r);                 // |n2 - n0|^2 = 2
  const D::Vec3 sum = {0., w1 * s + w2, 1. + w1 * s};
  const double len = D::norm(sum);
  EXPECT_NEAR(out[0][0], 0., 1e-15);
  EXPECT_NEAR(out[0][1], sum[1] / len, 1e-14);
  EXPECT_NEAR(out[0][2], sum[2] / len, 1e-14);
  // faces 1 and 2 have no neighbour: only their own term, their normal
  EXPECT_NEAR(D::norm(out[1] - fd.normals[1]), 0., 1e-15);
  EXPECT_NEAR(D::norm(out[2] - fd.normals[2]), 0., 1e-15);
}
