// Tests of add_gaussian_noise(), add_impulsive_noise(), add_isotropic_gaussian_noise() and add_depth_scan_noise().

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>

#include <denoising_support/synthetic_meshes.h>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

template <typename M>
std::vector<K::Point_3> positions(const M& mesh)
{
  std::vector<K::Point_3> p;
  for(auto v : vertices(mesh))
    p.push_back(get(CGAL::vertex_point, mesh, v));
  return p;
}

double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  for(auto e : edges(mesh))
    sum += std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
  return sum / num_edges(mesh);
}

// Applies `add_noise(mesh, seed)` to copies of `mesh` with seeds `seed`,
// `seed` and `seed + 1`, and to `polyhedron` (the same mesh) with `seed`:
// the same seed gives the same points, another seed others, and a
// Polyhedron_3 the points of the Surface_mesh. Returns the first copy's points.
template <typename AddNoise>
std::vector<K::Point_3> expect_seeded(const Mesh& mesh, Polyhedron polyhedron, unsigned int seed,
                                      const AddNoise& add_noise)
{
  Mesh a = mesh, b = mesh, c = mesh;
  add_noise(a, seed);
  add_noise(b, seed);
  add_noise(c, seed + 1);
  add_noise(polyhedron, seed);
  const auto after = positions(a);
  EXPECT_EQ(after, positions(b));
  EXPECT_NE(after, positions(c));
  EXPECT_EQ(after, positions(polyhedron));
  return after;
}

TEST(AddNoise, SameSeedSameNoiseOtherSeedOtherNoise)
{
  const Mesh mesh = denoising_support::cube<Mesh>(5);
  const auto after = expect_seeded(mesh, denoising_support::cube<Polyhedron>(5), 11, [](auto& m, unsigned int seed) {
    PMP::add_gaussian_noise(m, 0.3, CGAL::parameters::random_seed(seed));
  });
  EXPECT_NE(after, positions(mesh));
}

TEST(AddNoise, GaussianAlongNormalsWithRelativeSigma)
{
  // plane grid with cells of side 1/40: mean edge length (1 + 1 + sqrt 2)/3 / 40 on
  // interior cells; noise is along +-z only
  Mesh mesh = denoising_support::plane_grid<Mesh>(40);
  const auto before = positions(mesh);
  const double mean_edge = mean_edge_length(mesh);
  PMP::add_gaussian_noise(mesh, 0.2, CGAL::parameters::random_seed(3));
  const auto after = positions(mesh);
  double sum = 0, sum2 = 0;
  for(std::size_t i = 0; i < after.size(); ++i)
  {
    EXPECT_EQ(after[i].x(), before[i].x());
    EXPECT_EQ(after[i].y(), before[i].y());
    sum += after[i].z();
    sum2 += after[i].z() * after[i].z();
  }
  const double n = double(after.size());
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  // 1681 samples: the sample deviation is within 5% of sigma with overwhelming probability
  EXPECT_NEAR(sd, 0.2 * mean_edge, 0.05 * 0.2 * mean_edge);
  EXPECT_NEAR(mean, 0., 4 * 0.2 * mean_edge / std::sqrt(n));
}

TEST(AddNoise, ImpulsiveNoiseMovesAboutTheGivenFraction)
{
  Mesh mesh = denoising_support::plane_grid<Mesh>(40);
  const auto before = positions(mesh);
  PMP::add_impulsive_noise(mesh, 0.1, 1.0, CGAL::parameters::random_seed(8));
  const auto after = positions(mesh);
  std::size_t moved = 0;
  for(std::size_t i = 0; i < after.size(); ++i)
    moved += after[i] != before[i];
  const double fraction = double(moved) / after.size();
  EXPECT_NEAR(fraction, 0.1, 0.025);
}

TEST(AddNoise, BadArgumentsThrowAndLeaveTheMesh)
{
  Mesh mesh = denoising_support::plane_grid<Mesh>(4);
  const auto before = positions(mesh);
  EXPECT_THROW(PMP::add_gaussian_noise(mesh, -0.1), std::invalid_argument);
  EXPECT_THROW(PMP::add_impulsive_noise(mesh, 1.5, 0.1), std::invalid_argument);
  EXPECT_EQ(before, positions(mesh));
  Mesh empty;
  EXPECT_NO_THROW(PMP::add_gaussian_noise(empty, 0.3));
}

// Depth-scan noise: seeded; every vertex moves along the line from one
// camera point to it (the lines meet in a point, found here by least
// squares); the displacement is of the order of sigma_E times the mean edge
// length; the same for Surface_mesh and Polyhedron_3; bad sigma throws.
TEST(AddNoise, DepthScanNoiseAlongRaysFromOneCamera)
{
  const Mesh a = denoising_support::cube<Mesh>(8);
  const auto before = positions(a);
  const double mean_edge = mean_edge_length(a);
  const auto after = expect_seeded(a, denoising_support::cube<Polyhedron>(8), 5, [](auto& m, unsigned int seed) {
    PMP::add_depth_scan_noise(m, 0.3, CGAL::parameters::random_seed(seed));
  });

  // the camera: the point nearest to every displacement line
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> lines;
  double sum2 = 0.;
  for(std::size_t i = 0; i < after.size(); ++i)
  {
    const Eigen::Vector3d p0(before[i].x(), before[i].y(), before[i].z());
    const Eigen::Vector3d d(after[i].x() - before[i].x(), after[i].y() - before[i].y(), after[i].z() - before[i].z());
    sum2 += d.squaredNorm();
    if(d.norm() == 0.)
      continue;
    const Eigen::Vector3d u = d.normalized();
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - u * u.transpose();
    A += P;
    rhs += P * p0;
    lines.emplace_back(p0, u);
  }
  ASSERT_GT(lines.size(), after.size() / 2);
  const Eigen::Vector3d camera = A.ldlt().solve(rhs);
  for(const auto& l : lines)
  {
    const Eigen::Vector3d w = camera - l.first;
    EXPECT_LT((w - w.dot(l.second) * l.second).norm(), 1e-6 * w.norm());
  }
  const double rms = std::sqrt(sum2 / double(after.size()));
  EXPECT_GT(rms, 0.5 * 0.3 * mean_edge);
  EXPECT_LT(rms, 2. * 0.3 * mean_edge);

  Mesh d = denoising_support::cube<Mesh>(3);
  const auto d_before = positions(d);
  EXPECT_THROW(PMP::add_depth_scan_noise(d, -0.1), std::invalid_argument);
  EXPECT_THROW(PMP::add_depth_scan_noise(d, std::nan("")), std::invalid_argument);
  EXPECT_EQ(d_before, positions(d));
}

// Isotropic noise: seeded and the same for Surface_mesh and Polyhedron_3;
// the RMS length of the moves is sigma_E times the mean edge length, a third
// of it (in energy) along each axis, so two thirds along a plane's surface;
// a constrained vertex does not move and the others get the same noise as
// without the constraint; bad sigma throws and leaves the mesh.
TEST(AddNoise, IsotropicNoiseHasTheRelativeRmsAndNoPreferredDirection)
{
  const Mesh mesh = denoising_support::plane_grid<Mesh>(40);
  const auto before = positions(mesh);
  const double mean_edge = mean_edge_length(mesh);
  const auto after =
      expect_seeded(mesh, denoising_support::plane_grid<Polyhedron>(40), 4, [](auto& m, unsigned int seed) {
        PMP::add_isotropic_gaussian_noise(m, 0.2, CGAL::parameters::random_seed(seed));
      });

  double axis2[3] = {0., 0., 0.};
  for(std::size_t i = 0; i < after.size(); ++i)
  {
    const K::Vector_3 d = after[i] - before[i];
    for(int c = 0; c < 3; ++c)
      axis2[c] += d[c] * d[c];
  }
  const double n = double(after.size()), total = axis2[0] + axis2[1] + axis2[2];
  // 3 x 1681 samples: within 5% of sigma in RMS, each axis within 10% of a third
  EXPECT_NEAR(std::sqrt(total / n), 0.2 * mean_edge, 0.05 * 0.2 * mean_edge);
  for(int c = 0; c < 3; ++c)
    EXPECT_NEAR(axis2[c] / total, 1. / 3., 0.1 / 3.);

  Mesh pinned = denoising_support::plane_grid<Mesh>(40);
  auto constrained = pinned.add_property_map<Mesh::Vertex_index, bool>("v:pinned", false).first;
  const Mesh::Vertex_index v0(7);
  put(constrained, v0, true);
  PMP::add_isotropic_gaussian_noise(pinned, 0.2,
                                    CGAL::parameters::random_seed(4).vertex_is_constrained_map(constrained));
  const auto pinned_after = positions(pinned);
  for(std::size_t i = 0; i < after.size(); ++i)
    EXPECT_EQ(pinned_after[i], i == 7 ? before[i] : after[i]);

  Mesh other = mesh;
  EXPECT_THROW(PMP::add_isotropic_gaussian_noise(other, -0.1), std::invalid_argument);
  EXPECT_THROW(PMP::add_isotropic_gaussian_noise(other, std::nan("")), std::invalid_argument);
  EXPECT_EQ(before, positions(other));
  Mesh empty;
  EXPECT_NO_THROW(PMP::add_isotropic_gaussian_noise(empty, 0.3));
}
