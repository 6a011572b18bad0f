// Tests of the automatic mode of intrinsic_denoising(): the noise estimate,
// the parameters it derives, the stopping rule, the report and the progress
// callback.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/noise_estimate.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "synthetic_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace D = CGAL::Polygon_mesh_processing::internal::Denoising;

const Mesh& fandisk()
{
  static const Mesh m = [] {
    Mesh f;
    if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), f) || f.is_empty())
      throw std::runtime_error("cannot read fandisk");
    return f;
  }();
  return m;
}

double estimate(const Mesh& m)
{
  const D::Flat_mesh flat =
      D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters>(m, CGAL::parameters::default_values())
          .flat(m, "test");
  return D::estimate_noise<CGAL::Sequential_tag>(flat).relative_noise;
}

// The largest angle (degrees) between a face normal of `m` and of `reference`.
double max_normal_angle(const Mesh& m, const Mesh& reference)
{
  double worst = 0.;
  for(Mesh::Face_index f : faces(m))
  {
    const K::Vector_3 a = PMP::compute_face_normal(f, m), b = PMP::compute_face_normal(f, reference);
    worst = std::max(worst, std::acos(std::max(-1., std::min(1., a * b))) * 180. / CGAL_PI);
  }
  return worst;
}

} // namespace

// The estimate follows sigma_E on a fixed mesh: increasing, within 15% of it
// from 0.1 up, and near zero without noise (fandisk's flat and smooth parts
// and its sharp edges; the cube's flat faces).
TEST(AutomaticParameters, NoiseEstimateGrowsWithNoiseAndVanishesWithout)
{
  const std::vector<double> sigmas = {0., 0.025, 0.05, 0.1, 0.2, 0.3, 0.4};
  double last = -1.;
  for(double sigma : sigmas)
  {
    Mesh noisy = fandisk();
    if(sigma > 0.)
      PMP::add_gaussian_noise(noisy, sigma, CGAL::parameters::random_seed(3));
    const double e = estimate(noisy);
    EXPECT_GT(e, last) << "sigma_E " << sigma;
    if(sigma == 0.)
    {
      EXPECT_LT(e, 0.005);
    }
    if(sigma >= 0.1)
    {
      EXPECT_NEAR(e, sigma, 0.15 * sigma) << "sigma_E " << sigma;
    }
    last = e;
  }
  EXPECT_LT(estimate(denoising_test::cube<Mesh>(12)), 1e-6);
  Mesh noisy_cube = denoising_test::cube<Mesh>(12);
  PMP::add_gaussian_noise(noisy_cube, 0.2, CGAL::parameters::random_seed(3));
  EXPECT_NEAR(estimate(noisy_cube), 0.2, 0.03);
}

// The estimate does not depend on the mesh's scale (it is relative to the
// mean edge length).
TEST(AutomaticParameters, NoiseEstimateIsScaleFree)
{
  Mesh noisy = fandisk();
  PMP::add_gaussian_noise(noisy, 0.2, CGAL::parameters::random_seed(3));
  Mesh big = noisy;
  for(auto v : vertices(big))
    big.point(v) = CGAL::ORIGIN + 1000. * (big.point(v) - CGAL::ORIGIN);
  EXPECT_NEAR(estimate(big), estimate(noisy), 1e-9);
}

// On a noise-free mesh the stopping rule ends the iterations at once, and the
// cube's edges stay sharp: every face keeps its normal.
TEST(AutomaticParameters, NoiseFreeCubeStopsAtOnceAndStaysSharp)
{
  const Mesh reference = denoising_test::cube<Mesh>(10);
  Mesh m = reference;
  const PMP::Intrinsic_denoising_report r = PMP::intrinsic_denoising(m);
  EXPECT_TRUE(r.automatic_parameters);
  EXPECT_TRUE(r.noise_level_estimated);
  EXPECT_LT(r.noise_level, 1e-6);
  EXPECT_LE(r.iterations, 3u);
  EXPECT_NE(r.stop_reason, PMP::Intrinsic_stop_reason::ITERATION_LIMIT);
  EXPECT_LT(max_normal_angle(m, reference), 1e-3);
  EXPECT_LT(PMP::vertex_position_error(m, reference), 1e-6 * 0.2); // edge length 0.2
}

TEST(AutomaticParameters, NoiseFreeFandiskStopsWithinAFewIterations)
{
  Mesh m = fandisk();
  const PMP::Intrinsic_denoising_report r = PMP::intrinsic_denoising(m);
  EXPECT_LE(r.iterations, 3u);
  EXPECT_NE(r.stop_reason, PMP::Intrinsic_stop_reason::ITERATION_LIMIT);
  EXPECT_LT(PMP::face_normal_error(m, fandisk()), 0.5);
  EXPECT_EQ(r.flat_edge_fraction, -1.); // no noise: no shape test
  EXPECT_FALSE(r.smooth_surface);
}

// The automatic mode on seeded noisy fandisk: the report names what was
// chosen, the rule stopped before the limit, and the result is close to the
// best of the benchmark's grid search (2.26 degrees at sigma_E = 0.3).
TEST(AutomaticParameters, NoisyFandiskAutomaticMode)
{
  Mesh m = fandisk();
  PMP::add_gaussian_noise(m, 0.3, CGAL::parameters::random_seed(1));
  const PMP::Intrinsic_denoising_report r = PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(m);
  EXPECT_NEAR(r.noise_level, 0.3, 0.03);
  EXPECT_GT(r.sigma_spatial, 0.);
  EXPECT_EQ(r.sigma_spatial, r.sigma_range);
  EXPECT_GT(r.relative_neighbor_radius, 1.);
  EXPECT_GT(r.neighbor_radius, 0.);
  EXPECT_GT(r.iterations, 5u);
  EXPECT_LT(r.iterations, r.maximum_iterations);
  EXPECT_NE(r.stop_reason, PMP::Intrinsic_stop_reason::ITERATION_LIMIT);
  EXPECT_LT(PMP::face_normal_error(m, fandisk()), 2.5);
  // piecewise flat: the shape test keeps the first schedule
  EXPECT_GT(r.flat_edge_fraction, D::Automatic_rules::min_flat_fraction);
  EXPECT_LT(r.flat_edge_fraction, D::Automatic_rules::flat_faced_fraction); // curved parts: not flat-faced
  EXPECT_FALSE(r.smooth_surface);
  EXPECT_FALSE(r.flat_faced);
  EXPECT_EQ(r.discarded_iterations, 0u);
}

// The shape test's measure: every interior edge of a plane grid is flat; on
// the cube(n), all but the 12 n edges along the cube's edges, out of the
// 3F/2 = 18 n^2 edges of the closed mesh; -1 without an interior edge.
TEST(AutomaticParameters, FlatEdgeFraction)
{
  auto fraction = [](const Mesh& mesh) {
    const D::Flat_mesh flat =
        D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters>(mesh, CGAL::parameters::default_values())
            .flat(mesh, "test");
    D::Face_data fd;
    D::compute_face_data<CGAL::Sequential_tag>(flat, flat.points, fd);
    const double f = D::flat_edge_fraction<CGAL::Sequential_tag>(flat, fd.normals, 1.);
#ifdef CGAL_LINKED_WITH_TBB
    EXPECT_EQ(D::flat_edge_fraction<CGAL::Parallel_tag>(flat, fd.normals, 1.), f);
#endif
    return f;
  };
  EXPECT_EQ(fraction(denoising_test::plane_grid<Mesh>(8)), 1.);
  for(int n : {3, 10})
    EXPECT_NEAR(fraction(denoising_test::cube<Mesh>(n)), 1. - 12. * n / (18. * n * n), 1e-12) << n;
  Mesh triangle;
  triangle.add_face(triangle.add_vertex(K::Point_3(0, 0, 0)), triangle.add_vertex(K::Point_3(1, 0, 0)),
                    triangle.add_vertex(K::Point_3(0, 1, 0)));
  EXPECT_EQ(fraction(triangle), -1.);
  // noisy fandisk: well under 1 degree between most neighbours only after
  // denoising
  Mesh noisy = fandisk();
  PMP::add_gaussian_noise(noisy, 0.3, CGAL::parameters::random_seed(1));
  EXPECT_LT(fraction(noisy), 0.1);
}

// A smooth curved surface (CGAL's blobby, 4050 faces, sigma_E 0.2): the
// first schedule's result is not piecewise flat, so the automatic mode
// denoises the input again with the smooth-surface schedule, which gives a
// much lower E_n than the first schedule alone (run here by giving its sigma,
// which turns the shape test off).
TEST(AutomaticParameters, SmoothSurfaceScheduleOnCurvedMesh)
{
  Mesh reference;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/blobby.off"), reference));
  Mesh noisy = reference;
  PMP::add_gaussian_noise(noisy, 0.2, CGAL::parameters::random_seed(1));
  Mesh a = noisy;
  const auto r = PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(a);
  EXPECT_TRUE(r.smooth_surface);
  EXPECT_GE(r.flat_edge_fraction, 0.);
  EXPECT_LT(r.flat_edge_fraction, D::Automatic_rules::min_flat_fraction);
  EXPECT_GT(r.discarded_iterations, 0u);
  EXPECT_EQ(r.sigma_spatial, D::Automatic_rules::smooth_sigma);
  EXPECT_EQ(r.sigma_range, D::Automatic_rules::smooth_sigma);
  EXPECT_NEAR(r.relative_neighbor_radius, D::Automatic_rules::smooth_relative_radius, 1e-12);
  EXPECT_NE(r.stop_reason, PMP::Intrinsic_stop_reason::ITERATION_LIMIT);

  Mesh b = noisy;
  const double first_sigma = D::automatic_choice(r.noise_level).kernel.sigma_spatial;
  const auto rb = PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(
      b, CGAL::parameters::sigma_spatial(first_sigma).sigma_range(first_sigma));
  EXPECT_EQ(rb.flat_edge_fraction, -1.);
  EXPECT_FALSE(rb.smooth_surface);
  EXPECT_EQ(rb.iterations, r.discarded_iterations); // the same first schedule
  const double e_auto = PMP::face_normal_error(a, reference), e_first = PMP::face_normal_error(b, reference);
  EXPECT_LT(e_auto, 0.7 * e_first) << e_auto << " " << e_first;

  // blobby without noise: its curvature alone gives an estimate just above
  // 0.02, so the test is made; the smooth-surface schedule (stopping rule
  // from the first iteration) changes it less than the first schedule would
  Mesh clean = reference, clean_first = reference;
  const auto rc = PMP::intrinsic_denoising(clean);
  ASSERT_GE(rc.noise_level, D::Automatic_rules::min_noise);
  EXPECT_TRUE(rc.smooth_surface);
  const double s = D::automatic_choice(rc.noise_level).kernel.sigma_spatial;
  PMP::intrinsic_denoising(clean_first, CGAL::parameters::sigma_spatial(s).sigma_range(s));
  EXPECT_LT(PMP::face_normal_error(clean, reference), PMP::face_normal_error(clean_first, reference));
}

// A surface of large flat faces (cube(12), sigma_E 0.2): nearly every edge
// of the first schedule's result is flat, so the automatic mode denoises the
// input again with the flat-faced schedule (the first schedule's sigma, r 8d,
// up to 150 iterations), which gives a much lower E_n than the first
// schedule alone, and keeps the cube's edges: no face normal ends far from
// its axis.
TEST(AutomaticParameters, FlatFacedScheduleOnCube)
{
  const Mesh reference = denoising_test::cube<Mesh>(12);
  Mesh noisy = reference;
  PMP::add_gaussian_noise(noisy, 0.2, CGAL::parameters::random_seed(1));
  Mesh a = noisy;
  const auto r = PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(a);
  EXPECT_TRUE(r.flat_faced);
  EXPECT_FALSE(r.smooth_surface);
  EXPECT_GE(r.flat_edge_fraction, D::Automatic_rules::flat_faced_fraction);
  EXPECT_GT(r.discarded_iterations, 0u);
  const double first_sigma = D::automatic_choice(r.noise_level).kernel.sigma_spatial;
  EXPECT_EQ(r.sigma_spatial, first_sigma);
  EXPECT_NEAR(r.relative_neighbor_radius, D::Automatic_rules::flat_faced_relative_radius, 1e-12);
  EXPECT_EQ(r.maximum_iterations, D::Automatic_rules::flat_faced_max_iterations);
  EXPECT_GT(r.iterations, r.discarded_iterations);
  EXPECT_NE(r.stop_reason, PMP::Intrinsic_stop_reason::NOISE_LEVEL_REACHED); // the displacement test is off

  Mesh b = noisy;
  const auto rb = PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(
      b, CGAL::parameters::sigma_spatial(first_sigma).sigma_range(first_sigma));
  EXPECT_FALSE(rb.flat_faced);
  EXPECT_EQ(rb.iterations, r.discarded_iterations); // the same first schedule
  const double e_auto = PMP::face_normal_error(a, reference), e_first = PMP::face_normal_error(b, reference);
  EXPECT_LT(e_auto, 0.6 * e_first) << e_auto << " " << e_first;
  EXPECT_LT(max_normal_angle(a, reference), 5.);

  // the memory guard: the flat-faced radius holds (8 / r)^2 times the first
  // schedule's nodes (r its relative radius), and is skipped past 2^28 of them
  EXPECT_TRUE(D::flat_faced_affordable(std::size_t(1) << 20, 4.));
  EXPECT_TRUE(D::flat_faced_affordable(std::size_t(1) << 26, 4.));
  EXPECT_FALSE(D::flat_faced_affordable((std::size_t(1) << 26) + 1, 4.));
  EXPECT_TRUE(D::flat_faced_affordable(9 * (std::size_t(1) << 22), 3.));      // 64/9 times: 2^28
  EXPECT_FALSE(D::flat_faced_affordable(9 * (std::size_t(1) << 22) + 9, 3.)); // just over
  EXPECT_FALSE(D::flat_faced_affordable(1, 0.));
}

// The automatic radius follows the noise level: (2 + 10 noise) d, clamped to
// [3d, 4d]. At sigma_E 0.1 the smaller radius keeps fandisk's curved parts:
// E_n 1.270 degrees (seed 1) against 1.368 with r = 4d and the same sigma
// and stopping rule.
TEST(AutomaticParameters, RadiusFollowsTheNoiseLevel)
{
  EXPECT_EQ(D::automatic_choice(0.).kernel.relative_radius, 3.);
  EXPECT_EQ(D::automatic_choice(0.1).kernel.relative_radius, 3.);
  EXPECT_NEAR(D::automatic_choice(0.15).kernel.relative_radius, 3.5, 1e-12);
  EXPECT_EQ(D::automatic_choice(0.2).kernel.relative_radius, 4.);
  EXPECT_EQ(D::automatic_choice(0.5).kernel.relative_radius, 4.);

  Mesh m = fandisk();
  PMP::add_gaussian_noise(m, 0.1, CGAL::parameters::random_seed(1));
  Mesh wide = m;
  const auto r = PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(m);
  EXPECT_FALSE(r.smooth_surface);
  EXPECT_FALSE(r.flat_faced);
  EXPECT_NEAR(r.relative_neighbor_radius, 2. + 10. * r.noise_level, 1e-9);
  EXPECT_LT(r.relative_neighbor_radius, 3.2);
  const double s = r.sigma_spatial;
  PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(
      wide, CGAL::parameters::sigma_spatial(s).sigma_range(s).relative_neighbor_radius(4.));
  const double e_auto = PMP::face_normal_error(m, fandisk()), e_wide = PMP::face_normal_error(wide, fandisk());
  EXPECT_LT(e_auto, 0.95 * e_wide) << e_auto << " " << e_wide;
}

// Every explicit parameter overrides the automatic choice; a given
// number_of_iterations runs exactly (no stopping rule unless asked for).
TEST(AutomaticParameters, ExplicitParametersOverride)
{
  Mesh noisy = fandisk();
  PMP::add_gaussian_noise(noisy, 0.2, CGAL::parameters::random_seed(2));
  Mesh a = noisy;
  const auto r = PMP::intrinsic_denoising(
      a, CGAL::parameters::sigma_spatial(0.3).sigma_range(0.35).relative_neighbor_radius(3.).number_of_iterations(7));
  EXPECT_EQ(r.sigma_spatial, 0.3);
  EXPECT_EQ(r.sigma_range, 0.35);
  EXPECT_NEAR(r.relative_neighbor_radius, 3., 1e-12);
  EXPECT_EQ(r.iterations, 7u);
  EXPECT_EQ(r.maximum_iterations, 7u);
  EXPECT_EQ(r.stop_reason, PMP::Intrinsic_stop_reason::ITERATION_LIMIT);
  EXPECT_EQ(r.flat_edge_fraction, -1.); // no shape test with a given kernel

  // automatic_parameters(false): the fixed defaults, bitwise the old behaviour
  Mesh b = noisy, c = noisy;
  const auto rb = PMP::intrinsic_denoising(b, CGAL::parameters::automatic_parameters(false).number_of_iterations(5));
  PMP::intrinsic_denoising(c, CGAL::parameters::sigma_spatial(0.4).sigma_range(0.4).relative_neighbor_radius(4.)
                                  .number_of_iterations(5).automatic_parameters(false));
  EXPECT_EQ(rb.sigma_spatial, 0.4);
  EXPECT_EQ(rb.relative_neighbor_radius, 4.);
  for(auto v : vertices(b))
    ASSERT_EQ(b.point(v), c.point(v));

  // a given number_of_iterations with the stopping rule asked for is a limit
  Mesh d = noisy;
  const auto rd = PMP::intrinsic_denoising(d, CGAL::parameters::number_of_iterations(200).stop_when_converged(true));
  EXPECT_EQ(rd.maximum_iterations, 200u);
  EXPECT_LT(rd.iterations, 200u);
}

// A given noise level replaces the estimate; 0 means "no noise": one
// iteration, then the rule stops.
TEST(AutomaticParameters, GivenNoiseLevel)
{
  Mesh noisy = fandisk();
  PMP::add_gaussian_noise(noisy, 0.2, CGAL::parameters::random_seed(2));
  Mesh a = noisy;
  const auto r = PMP::intrinsic_denoising(a, CGAL::parameters::noise_level(0.));
  EXPECT_FALSE(r.noise_level_estimated);
  EXPECT_EQ(r.noise_level, 0.);
  EXPECT_EQ(r.iterations, 1u);
  EXPECT_EQ(r.stop_reason, PMP::Intrinsic_stop_reason::NOISE_LEVEL_REACHED);
  Mesh b = noisy;
  EXPECT_THROW(PMP::intrinsic_denoising(b, CGAL::parameters::noise_level(-1.)), std::invalid_argument);
  for(auto v : vertices(b))
    ASSERT_EQ(b.point(v), noisy.point(v));
}

TEST(AutomaticParameters, ProgressCallbackSeesEveryIteration)
{
  Mesh m = fandisk();
  PMP::add_gaussian_noise(m, 0.1, CGAL::parameters::random_seed(2));
  std::vector<std::size_t> seen;
  std::size_t limit = 0;
  const auto r = PMP::intrinsic_denoising(
      m, CGAL::parameters::number_of_iterations(4).progress_callback([&](std::size_t done, std::size_t max) {
        seen.push_back(done);
        limit = max;
      }));
  EXPECT_EQ(r.iterations, 4u);
  EXPECT_EQ(seen, (std::vector<std::size_t>{1, 2, 3, 4}));
  EXPECT_EQ(limit, 4u);
}
