// Tests of fast_feature_preserving_denoising() (Sun et al. 2007).

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/fast_feature_preserving_denoising.h>

#include "classic_test_helpers.h"

#include <stdexcept>

using namespace classic_test;

TEST(FastFeaturePreservingDenoising, NoisyPlaneBecomesFlat)
{
  const Errors e = noisy_plane("SRML07", [](Mesh& m) { PMP::fast_feature_preserving_denoising(m); });
  EXPECT_GT(e.before, 15.);
  EXPECT_LT(e.after, e.before / 10.);
}

TEST(FastFeaturePreservingDenoising, NoiseFreeCubeKeepsItsEdges)
{
  const Errors e = noise_free_cube("SRML07", [](Mesh& m) { PMP::fast_feature_preserving_denoising(m); });
  // n_i . n_j = 0 <= T across an edge: the two sides never mix
  EXPECT_LT(e.before, 1e-9);
  EXPECT_LT(e.after, 1e-9);
}

TEST(FastFeaturePreservingDenoising, EdgeNeighborhoodAlsoSmooths)
{
  const Errors e = noisy_plane("SRML07 (edge neighbours)", [](Mesh& m) {
    PMP::fast_feature_preserving_denoising(m, CGAL::parameters::use_vertex_neighborhood(false));
  });
  EXPECT_LT(e.after, e.before / 5.);
}

TEST(FastFeaturePreservingDenoising, BadThresholdThrowsAndLeavesTheMeshUnchanged)
{
  Mesh m = denoising_support::cube<Mesh>(3);
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

TEST(FastFeaturePreservingDenoising, FaceNormalMapReceivesUnitFilteredNormals)
{
  Mesh mesh = denoising_support::cube<Mesh>(6);
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

// Two faces folded by 60 degrees (n_0 . n_1 = 0.5): with T = 0.4 the neighbour
// weighs (0.5 - 0.4)^2 = 0.01 against (1 - 0.4)^2 = 0.36 for the face itself;
// with T = 0.5 it weighs 0. Checked on the filtered normals of one pass.
TEST(FastFeaturePreservingDenoising, ThresholdWeightsByHand)
{
  const double pi = 3.14159265358979323846;
  const K::Point_3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  const K::Vector_3 n0(0, 0, 1);
  const K::Vector_3 e = (p2 - p1) / std::sqrt((p2 - p1).squared_length());
  const K::Vector_3 away = CGAL::cross_product(e, n0); // in face 0's plane, away from it
  // face 1 = face 0's plane turned by 60 degrees about the shared edge p1 p2
  const K::Point_3 p3 = p1 + 0.5 * (p2 - p1) + 0.7 * (std::cos(pi / 3) * away + std::sin(pi / 3) * n0);
  Mesh mesh;
  const auto v0 = mesh.add_vertex(p0), v1 = mesh.add_vertex(p1), v2 = mesh.add_vertex(p2), v3 = mesh.add_vertex(p3);
  const auto f0 = mesh.add_face(v0, v1, v2), f1 = mesh.add_face(v1, v3, v2);
  const K::Vector_3 n1 = PMP::compute_face_normal(f1, mesh);
  ASSERT_NEAR(n0 * n1, 0.5, 1e-12);
  auto fnm = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:n", CGAL::NULL_VECTOR).first;

  Mesh copy = mesh; // (the copy has its own "f:n")
  auto copy_fnm = copy.property_map<Mesh::Face_index, K::Vector_3>("f:n").first;
  PMP::fast_feature_preserving_denoising(
      copy,
      CGAL::parameters::normal_threshold(0.4).number_of_iterations(1).vertex_iterations(0).face_normal_map(copy_fnm));
  const K::Vector_3 expected = 0.36 * n0 + 0.01 * n1;
  EXPECT_LT(std::sqrt((get(copy_fnm, f0) - expected / std::sqrt(expected.squared_length())).squared_length()), 1e-12);

  PMP::fast_feature_preserving_denoising(
      mesh, CGAL::parameters::normal_threshold(0.5).number_of_iterations(1).vertex_iterations(0).face_normal_map(fnm));
  EXPECT_LT(std::sqrt((get(fnm, f0) - n0).squared_length()), 1e-12);
}
