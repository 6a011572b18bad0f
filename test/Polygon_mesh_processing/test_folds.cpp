// The fold safeguard of the vertex update (prevent_folds): no face of the
// denoised mesh points against its orientation in the input mesh.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/Polygon_mesh_processing/update_vertices_from_face_normals.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <denoising_support/synthetic_meshes.h>
#include <denoising_support/turned_faces.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

Mesh noisy_fandisk(bool impulsive, double sigma)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), mesh) || num_faces(mesh) == 0)
    throw std::runtime_error("cannot read fandisk.off (CGAL data set)");
  if(impulsive)
    PMP::add_impulsive_noise(mesh, 0.1, sigma, CGAL::parameters::random_seed(1));
  else
    PMP::add_gaussian_noise(mesh, sigma, CGAL::parameters::random_seed(1));
  return mesh;
}

struct Fold_case
{
  const char* name;
  bool impulsive;
  double sigma;
};

void check_no_flips(const Fold_case& c)
{
  const Mesh reference = noisy_fandisk(false, 0.);
  const Mesh noisy = noisy_fandisk(c.impulsive, c.sigma);
  Mesh guarded = noisy, unguarded = noisy;
  PMP::intrinsic_denoising(guarded);
  PMP::intrinsic_denoising(unguarded, CGAL::parameters::prevent_folds(false));
  const std::size_t fg = denoising_support::turned_faces(noisy, guarded),
                    fu = denoising_support::turned_faces(noisy, unguarded);
  std::printf("%s: flipped faces (against the noisy input) guarded %zu, unguarded %zu; against the clean mesh: "
              "noisy %zu, guarded %zu, unguarded %zu; E_n guarded %.3f deg, unguarded %.3f deg\n",
              c.name, fg, fu, denoising_support::turned_faces(reference, noisy),
              denoising_support::turned_faces(reference, guarded),
              denoising_support::turned_faces(reference, unguarded), PMP::face_normal_error(guarded, reference),
              PMP::face_normal_error(unguarded, reference));
  EXPECT_EQ(fg, 0u);
}

} // namespace

TEST(FoldSafeguard, NoFlippedFacesOnNoisyFandiskSigma03)
{
  check_no_flips({"fandisk Gaussian sigma_E 0.3", false, 0.3});
}

TEST(FoldSafeguard, NoFlippedFacesOnNoisyFandiskSigma05)
{
  check_no_flips({"fandisk Gaussian sigma_E 0.5", false, 0.5});
}

TEST(FoldSafeguard, NoFlippedFacesOnImpulsiveNoise)
{
  check_no_flips({"fandisk impulsive 10% sigma_E 1.0", true, 1.0});
}

TEST(FoldSafeguard, NoFlippedFacesWithTheLeastSquaresUpdate)
{
  // the global update moves every vertex at once: the safeguard must hold it
  // too, in the fixed setting and in the automatic mode
  const Mesh reference = noisy_fandisk(false, 0.);
  const Mesh noisy = noisy_fandisk(false, 0.5);
  Mesh fixed = noisy, automatic = noisy;
  const PMP::Intrinsic_denoising_report rf = PMP::intrinsic_denoising(
      fixed, CGAL::parameters::automatic_parameters(false).vertex_update(PMP::Vertex_update::LEAST_SQUARES));
  const PMP::Intrinsic_denoising_report ra =
      PMP::intrinsic_denoising(automatic, CGAL::parameters::vertex_update(PMP::Vertex_update::LEAST_SQUARES));
  EXPECT_TRUE(rf.vertex_update == PMP::Vertex_update::LEAST_SQUARES);
  EXPECT_TRUE(ra.vertex_update == PMP::Vertex_update::LEAST_SQUARES);
  std::printf("least squares, fandisk sigma_E 0.5: E_n fixed %.3f, automatic %.3f (noisy %.3f)\n",
              PMP::face_normal_error(fixed, reference), PMP::face_normal_error(automatic, reference),
              PMP::face_normal_error(noisy, reference));
  EXPECT_EQ(denoising_support::turned_faces(noisy, fixed), 0u);
  EXPECT_EQ(denoising_support::turned_faces(noisy, automatic), 0u);
  EXPECT_LT(PMP::face_normal_error(fixed, reference), PMP::face_normal_error(noisy, reference));
}

TEST(FoldSafeguard, MoveIsHalvedUntilTheFaceNoLongerFolds)
{
  // One triangle a = (0,0,0), b = (1,0,0), c = (0,1,0) (normal +z); c is
  // moved by (0,-3,0). The full move folds it (c at y = -2), half the move
  // folds it (y = -0.5), a quarter does not (y = 0.25): c ends at
  // p + move / 4, the moves of the face's three vertices halved twice, none
  // cancelled.
  namespace D = PMP::internal::Denoising;
  D::Flat_mesh m;
  m.points = {{0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}};
  m.triangles = {{0u, 1u, 2u}};
  m.vertex_face_offsets = {0u, 1u, 2u, 3u};
  m.vertex_faces = {0u, 0u, 0u};
  const std::vector<D::Vec3> up = {{0., 0., 1.}};
  std::vector<D::Vec3> next = m.points;
  next[2] = {0., -2., 0.};
  D::Fold_safeguard guard;
  guard.reference = &up;
  D::apply_fold_safeguard<CGAL::Sequential_tag>(m, m.points, next, up, guard);
  EXPECT_EQ(next[2][0], 0.);
  EXPECT_EQ(next[2][1], 0.25);
  EXPECT_EQ(next[2][2], 0.);
  EXPECT_EQ(guard.halved_moves, 3u);
  EXPECT_EQ(guard.frozen_moves, 0u);
  // with a move that still folds after 4 halvings (y = 1 - 48 / 16 = -2),
  // the vertices stay
  next = m.points;
  next[2] = {0., -47., 0.};
  guard.halved_moves = guard.frozen_moves = 0;
  D::apply_fold_safeguard<CGAL::Sequential_tag>(m, m.points, next, up, guard);
  EXPECT_EQ(next[2][1], 1.);
  EXPECT_EQ(guard.frozen_moves, 3u);
  EXPECT_EQ(guard.halved_moves, 0u);
}
