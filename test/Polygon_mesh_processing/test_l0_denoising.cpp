// Tests of l0_denoising() (He and Schaefer 2013).

#include <CGAL/Polygon_mesh_processing/l0_denoising.h>

#include "classic_test_helpers.h"

#include <memory>
#include <stdexcept>

using namespace classic_test;

TEST(L0Denoising, NoisyPlaneBecomesFlat)
{
  const Errors e = noisy_plane("HS13", [](Mesh& m) { PMP::l0_denoising(m); });
  EXPECT_GT(e.before, 15.);
  EXPECT_LT(e.after, e.before / 20.);
}

// A cube's edges are what the L0 norm keeps. While beta is small every delta
// is 0 and the first solves smooth a little; the later ones restore the edges
// but not exactly. Measured on the 12 x 12 cube: with the default lambda
// factor (1.15) E_n 0.41 deg, E_v 2.2e-3; with 0.02, E_n 1.9e-7 deg.
TEST(L0Denoising, NoiseFreeCubeKeepsItsEdges)
{
  const Errors e = noise_free_cube("HS13", [](Mesh& m) { PMP::l0_denoising(m); });
  EXPECT_LT(e.before, 0.45);
  EXPECT_LT(e.after, 2.5e-3);
  const Errors small = noise_free_cube("HS13 (lambda factor 0.02)",
                                       [](Mesh& m) { PMP::l0_denoising(m, CGAL::parameters::l0_weight(0.02)); });
  EXPECT_LT(small.before, 1e-5);
  EXPECT_LT(small.after, 1e-7);
}

// The edge operator is zero on two coplanar triangles and not on a fold.
TEST(L0Denoising, EdgeOperatorVanishesOnCoplanarTriangles)
{
  namespace D = PMP::internal::Denoising;
  std::vector<D::Vec3> p = {{0., 0., 0.}, {0.3, -1., 0.}, {1., 0., 0.}, {0.6, 2., 0.}};
  const D::Interior_edge e = {0, 1, 2, 3};
  std::array<double, 4> c;
  ASSERT_TRUE(D::edge_operator(p, e, c));
  D::Vec3 value = {0., 0., 0.};
  for(int k = 0; k < 4; ++k)
    value = value + c[k] * p[k];
  EXPECT_LT(D::norm(value), 1e-15);
  EXPECT_NEAR(c[0] + c[1] + c[2] + c[3], 0., 1e-15); // translation invariant
  p[3][2] = 1.;                                      // fold: D becomes non-zero, along z
  ASSERT_TRUE(D::edge_operator(p, e, c));
  value = {0., 0., 0.};
  for(int k = 0; k < 4; ++k)
    value = value + c[k] * p[k];
  EXPECT_GT(std::abs(value[2]), 0.1);
}

TEST(L0Denoising, BadParameterThrowsAndLeavesTheMeshUnchanged)
{
  Mesh m = denoising_support::cube<Mesh>(3);
  const auto before = positions(m);
  EXPECT_THROW(PMP::l0_denoising(m, CGAL::parameters::l0_weight(0.)), std::invalid_argument);
  EXPECT_EQ(max_distance(before, positions(m)), 0.);
  Mesh empty;
  PMP::l0_denoising(empty);
  EXPECT_TRUE(empty.is_empty());
}

// A solver that counts its factorisations, and one whose factorisation fails.
struct Counting_solver : CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>>
{
  typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>> Base;
  std::shared_ptr<int> factorisations = std::make_shared<int>(0);
  bool fail = false;
  bool factor(const Matrix& A, NT& D)
  {
    ++*factorisations;
    return !fail && Base::factor(A, D);
  }
};

// The sparse_linear_solver parameter is the solver used: one factorisation
// per value of beta (1e-3 to 1e3 by factors sqrt(2): 40), the same result as
// the default solver, and its failure reported.
TEST(L0Denoising, SparseLinearSolverIsTheOneUsed)
{
  Mesh reference = denoising_support::cube<Mesh>(6);
  PMP::add_gaussian_noise(reference, 0.2, CGAL::parameters::random_seed(3));
  Mesh by_default = reference, given = reference;
  PMP::l0_denoising(by_default);
  Counting_solver solver;
  PMP::l0_denoising(given, CGAL::parameters::sparse_linear_solver(solver));
  EXPECT_EQ(*solver.factorisations, 40);
  EXPECT_EQ(max_distance(positions(by_default), positions(given)), 0.);

  Counting_solver failing;
  failing.fail = true;
  Mesh m = reference;
  EXPECT_THROW(PMP::l0_denoising(m, CGAL::parameters::sparse_linear_solver(failing)), std::runtime_error);
  EXPECT_EQ(max_distance(positions(reference), positions(m)), 0.); // left unchanged
  EXPECT_EQ(*failing.factorisations, 1);
}
