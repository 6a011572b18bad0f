// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// [HS13] He, Schaefer: "Mesh denoising via L0 minimization", ACM TOG 32(4)
// (SIGGRAPH 2013). A classic method of the paper's Table 1: the vertex
// positions minimise their distance to the input plus the L0 norm of an
// edge-based Laplacian, by alternating optimisation; the linear systems are
// solved with Eigen through CGAL's solver traits.

#ifndef CGAL_POLYGON_MESH_PROCESSING_L0_DENOISING_H
#define CGAL_POLYGON_MESH_PROCESSING_L0_DENOISING_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic_methods.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/tags.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// An interior edge (p1, p3) of two triangles (p1, p2, p3) and (p1, p3, p4).
struct Interior_edge
{
  std::uint32_t p1, p2, p3, p4;
};

// The edges shared by exactly two faces, each once.
inline std::vector<Interior_edge> interior_edges(const Flat_mesh& m)
{
  std::vector<Interior_edge> edges;
  for(std::uint32_t f = 0; f < m.number_of_faces(); ++f)
  {
    const auto& t = m.triangles[f];
    for(int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      std::uint32_t other = std::uint32_t(-1), count = 0, opposite = 0;
      for_each_face_on_edge(m, a, b, [&](std::uint32_t g) {
        if(g == f)
          return;
        other = g;
        ++count;
        for(std::uint32_t w : m.triangles[g])
          if(w != a && w != b)
            opposite = w;
      });
      if(count == 1 && other > f)
        edges.push_back({a, c, b, opposite});
    }
  }
  return edges;
}

// The coefficients of the edge operator D(e) on p1, p2, p3, p4, from the
// current positions: D(e) = (S_134 h_2 + S_123 h_4) / (S_123 + S_134), with
// h_k the component of p_k - p1 orthogonal to the edge direction p3 - p1 and
// S the triangle areas. D(e) = 0 iff the two triangles are coplanar (and on
// either side of the edge). Returns false for a degenerate edge.
inline bool edge_operator(const std::vector<Vec3>& p, const Interior_edge& e, std::array<double, 4>& c)
{
  const Vec3 d = p[e.p3] - p[e.p1];
  const double len2 = squared_norm(d);
  const double s123 = 0.5 * norm(cross(p[e.p2] - p[e.p1], d));
  const double s134 = 0.5 * norm(cross(d, p[e.p4] - p[e.p1]));
  const double s = s123 + s134;
  if(!(len2 > 0.) || !(s > 0.))
    return false;
  const double t2 = dot(p[e.p2] - p[e.p1], d) / len2, t4 = dot(p[e.p4] - p[e.p1], d) / len2;
  // h_k = p_k - (1 - t_k) p1 - t_k p3
  c[0] = -(s134 * (1. - t2) + s123 * (1. - t4)) / s; // p1
  c[1] = s134 / s;                                   // p2
  c[2] = -(s134 * t2 + s123 * t4) / s;               // p3
  c[3] = s123 / s;                                   // p4
  return true;
}

// He and Schaefer's alternating optimisation on a flat mesh, as named steps:
// measure_input() (the mean dihedral angle and edge length that scale the
// weights), set_regularizer() (R and the constant parts of the system), then
// per value of beta edge_system() (D from the current positions and delta)
// and solve() (the positions from the sparse system, with `Solver`, a model
// of CGAL's SparseLinearAlgebraWithFactorTraits_d). run() does all of them.
template <typename Solver>
class L0_minimization
{
  typedef Eigen::SparseMatrix<double> Sparse;

public:
  L0_minimization(Flat_mesh& mesh, const std::vector<char>& fixed, const Solver& solver, const char* fname)
      : mesh_(mesh), fixed_(fixed), solver_(solver), fname_(fname), edges_(interior_edges(mesh)), input_(mesh.points),
        nv_(mesh.number_of_vertices()), any_fixed_(std::find(fixed.begin(), fixed.end(), char(1)) != fixed.end())
  {
  }

  // Minimises with lambda = lambda_factor l^2 gamma and alpha_0 = alpha_factor
  // gamma. Returns false, the mesh left as it is, if it has no interior edge,
  // is flat or is degenerate.
  bool run(double lambda_factor, double alpha_factor)
  {
    double gamma = 0., l = 0.;
    if(edges_.empty() || !measure_input(gamma, l))
      return false;
    const double lambda = lambda_factor * l * l * gamma;
    double alpha = alpha_factor * gamma;
    const double beta_max = 1e3, kappa = std::sqrt(2.);
    set_regularizer();
    Sparse Dm;
    Eigen::MatrixXd delta;
    for(double beta = 1e-3; beta <= beta_max; beta *= kappa, alpha *= 0.5)
    {
      edge_system(beta, lambda, Dm, delta);
      solve(beta, alpha, Dm, delta);
    }
    return true;
  }

  // The mean dihedral angle (radians) and edge length of the input; false if
  // either is not positive (nothing to denoise).
  bool measure_input(double& gamma, double& l) const
  {
    Face_data fd;
    compute_face_data<CGAL::Sequential_tag>(mesh_, mesh_.points, fd);
    gamma = 0.;
    const Csr edge_faces = topological_face_neighbors(mesh_, 2);
    std::size_t count = 0;
    for(std::size_t f = 0; f < edge_faces.size(); ++f)
      for(std::uint32_t k = edge_faces.begin(f); k < edge_faces.end(f); ++k)
        if(edge_faces.items[k] > f)
        {
          const Vec3 &a = fd.normals[f], &b = fd.normals[edge_faces.items[k]];
          gamma += std::atan2(norm(cross(a, b)), dot(a, b));
          ++count;
        }
    gamma = count > 0 ? gamma / double(count) : 0.;
    l = mean_edge_length(mesh_);
    return gamma > 0. && l > 0.;
  }

  // R (constant), R^T R, the identity and the identity on the pinned vertices.
  void set_regularizer()
  {
    const std::size_t ne = edges_.size();
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(4 * ne);
    for(std::size_t e = 0; e < ne; ++e)
    {
      triplets.emplace_back(int(e), int(edges_[e].p1), 1.);
      triplets.emplace_back(int(e), int(edges_[e].p2), -1.);
      triplets.emplace_back(int(e), int(edges_[e].p3), 1.);
      triplets.emplace_back(int(e), int(edges_[e].p4), -1.);
    }
    Sparse R(static_cast<Eigen::Index>(ne), static_cast<Eigen::Index>(nv_));
    R.setFromTriplets(triplets.begin(), triplets.end());
    RtR_ = Sparse(R.transpose()) * R;
    identity_.resize(static_cast<Eigen::Index>(nv_), static_cast<Eigen::Index>(nv_));
    identity_.setIdentity();
    pinned_identity_.resize(static_cast<Eigen::Index>(nv_), static_cast<Eigen::Index>(nv_));
    std::vector<Eigen::Triplet<double>> diagonal;
    for(std::size_t v = 0; v < nv_; ++v)
      if(fixed_[v])
        diagonal.emplace_back(int(v), int(v), 1.);
    pinned_identity_.setFromTriplets(diagonal.begin(), diagonal.end());
  }

  // D from the current positions (one row per interior edge, none for a
  // degenerate one) and delta: D_e(p) where |D_e(p)|^2 >= lambda / beta, else 0.
  void edge_system(double beta, double lambda, Sparse& Dm, Eigen::MatrixXd& delta) const
  {
    const std::size_t ne = edges_.size();
    const std::vector<Vec3>& p = mesh_.points;
    std::vector<Eigen::Triplet<double>> triplets;
    delta = Eigen::MatrixXd::Zero(Eigen::Index(ne), 3);
    std::array<double, 4> c;
    for(std::size_t e = 0; e < ne; ++e)
    {
      if(!edge_operator(p, edges_[e], c))
        continue;
      const std::uint32_t ids[4] = {edges_[e].p1, edges_[e].p2, edges_[e].p3, edges_[e].p4};
      Vec3 value = {0., 0., 0.};
      for(int k = 0; k < 4; ++k)
      {
        triplets.emplace_back(int(e), int(ids[k]), c[k]);
        value = value + c[k] * p[ids[k]];
      }
      if(squared_norm(value) >= lambda / beta)
        for(int x = 0; x < 3; ++x)
          delta(Eigen::Index(e), x) = value[x];
    }
    Dm.resize(static_cast<Eigen::Index>(ne), static_cast<Eigen::Index>(nv_));
    Dm.setFromTriplets(triplets.begin(), triplets.end());
  }

  // The positions solving (I + beta D^T D + alpha R^T R) p = p* + beta D^T
  // delta, pinned vertices held at their input positions (their columns
  // moved to the right-hand side).
  void solve(double beta, double alpha, const Sparse& Dm, const Eigen::MatrixXd& delta)
  {
    const Sparse Dt = Dm.transpose();
    Sparse M = identity_ + beta * (Dt * Dm) + alpha * RtR_;
    Eigen::MatrixXd pinned_part = Eigen::MatrixXd::Zero(Eigen::Index(nv_), 3);
    if(any_fixed_)
    {
      Eigen::MatrixXd pinned_positions = Eigen::MatrixXd::Zero(Eigen::Index(nv_), 3);
      for(std::size_t v = 0; v < nv_; ++v)
        if(fixed_[v])
          for(int x = 0; x < 3; ++x)
            pinned_positions(Eigen::Index(v), x) = input_[v][x];
      pinned_part = M * pinned_positions;
      M.prune([this](const Eigen::Index& r, const Eigen::Index& c, const double&) {
        return !fixed_[std::size_t(r)] && !fixed_[std::size_t(c)];
      });
      M += pinned_identity_;
    }
    typename Solver::Matrix A(static_cast<int>(nv_));
    for(int col = 0; col < M.outerSize(); ++col)
      for(Sparse::InnerIterator it(M, col); it; ++it)
        A.set_coef(int(it.row()), int(it.col()), it.value(), true);
    double denominator = 1.;
    if(!solver_.factor(A, denominator))
      throw std::runtime_error(std::string(fname_) + ": the sparse factorisation failed.");
    const Eigen::MatrixXd rhs_delta = Dt * delta;
    std::vector<Vec3>& p = mesh_.points;
    for(int x = 0; x < 3; ++x)
    {
      typename Solver::Vector b(static_cast<int>(nv_)), sol(static_cast<int>(nv_));
      for(std::size_t v = 0; v < nv_; ++v)
        b[int(v)] = fixed_[v] ? input_[v][x]
                              : input_[v][x] + beta * rhs_delta(Eigen::Index(v), x) - pinned_part(Eigen::Index(v), x);
      if(!solver_.linear_solver(b, sol))
        throw std::runtime_error(std::string(fname_) + ": the sparse solve failed.");
      for(std::size_t v = 0; v < nv_; ++v)
        p[v][x] = fixed_[v] ? input_[v][x] : sol[int(v)];
    }
  }

private:
  Flat_mesh& mesh_;
  const std::vector<char>& fixed_;
  Solver solver_;
  const char* fname_;
  const std::vector<Interior_edge> edges_;
  const std::vector<Vec3> input_;
  const std::size_t nv_;
  const bool any_fixed_;
  Sparse RtR_, identity_, pinned_identity_;
};

} // namespace Denoising
} // namespace internal

/*!
  \ingroup PMP_denoising_grp

  \brief denoises `tmesh` by L0 minimisation of an edge-based Laplacian, He and
  Schaefer (2013) [HS13].

  The positions \f$p\f$ minimise
  \f[ \|p - p^*\|^2 + \alpha\, \|R(p)\|^2 + \lambda\, \|D(p)\|_0 \f]
  with \f$p^*\f$ the input, \f$D(e)\f$ for every interior edge \f$e = (p_1,
  p_3)\f$ with opposite vertices \f$p_2, p_4\f$ the edge operator
  \f$(S_{134} h_2 + S_{123} h_4) / (S_{123} + S_{134})\f$ (\f$h_k\f$: the part
  of \f$p_k - p_1\f$ orthogonal to the edge; \f$S\f$: triangle areas; zero
  iff the two triangles are coplanar), and \f$R(e) = p_1 - p_2 + p_3 - p_4\f$
  a regulariser against flipped triangles. As in the paper, an auxiliary
  \f$\delta \approx D(p)\f$ is introduced with a penalty \f$\beta\|D(p) -
  \delta\|^2\f$ and the two are optimised in turn: \f$\delta_e = D_e(p)\f$ if
  \f$\|D_e(p)\|^2 \ge \lambda/\beta\f$, else 0; then \f$p\f$ solves the
  sparse linear system \f$(I + \beta D^\top D + \alpha R^\top R)\, p = p^* +
  \beta D^\top\delta\f$ (by default Eigen's `SimplicialLDLT` through
  `CGAL::Eigen_solver_traits`; see `sparse_linear_solver`). \f$\beta\f$ grows from \f$10^{-3}\f$ by a
  factor \f$\sqrt 2\f$ up to \f$10^3\f$ and \f$\alpha\f$ is halved at every
  step. The coefficients of \f$D\f$ are recomputed from the current positions
  at every step. The paper's defaults are \f$\lambda = 0.02\,\bar l^2
  \bar\gamma\f$ and \f$\alpha_0 = 0.1\,\bar\gamma\f$, with \f$\bar l\f$ the mean
  edge length and \f$\bar\gamma\f$ the mean dihedral angle of the input;
  here \f$\bar\gamma\f$ is in radians and the default factor of
  \f$\lambda\f$ is \f$0.02 \cdot 180/\pi\f$, i.e. the paper's value with
  \f$\bar\gamma\f$ in degrees (with radians, 0.02 barely smooths: measured
  E_n 28.0 -> 24.7 degrees on fandisk at \f$\sigma_E = 0.3\f$).

  Boundary and non-manifold edges have no operator. The mesh is read once and
  written once, at the end: if an exception is thrown, `tmesh` is left
  unchanged.

  \tparam ConcurrencyTag unused (the solver is sequential); for the family's
          signature
  \tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to denoise; its vertex points are overwritten with the result
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{l0_weight}
      \cgalParamDescription{the factor \f$c\f$ of \f$\lambda = c\,\bar l^2\bar\gamma\f$, \f$\bar\gamma\f$ in radians
                            (larger: fewer, sharper features, flatter result)}
      \cgalParamType{double}
      \cgalParamDefault{`0.02 * 180 / pi` (about 1.15)}
    \cgalParamNEnd
    \cgalParamNBegin{regularization_weight}
      \cgalParamDescription{the factor \f$a\f$ of \f$\alpha_0 = a\,\bar\gamma\f$}
      \cgalParamType{double}
      \cgalParamDefault{`0.1`}
    \cgalParamNEnd
    \cgalParamNBegin{sparse_linear_solver}
      \cgalParamDescription{the solver of the sparse symmetric system of each step, factorised once per step and
                            solved for the three coordinates}
      \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d`}
      \cgalParamDefault{`CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::%EigenType>>`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_constrained_map, vertex_point_map, vertex_index_map, face_index_map, geom_traits}
      \cgalParamDescription{as for `intrinsic_denoising()` (a constrained vertex keeps its input position in every
                            solve)}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `tmesh` is a triangle mesh with finite coordinates; the weights are
       positive and finite. Otherwise `std::invalid_argument` is thrown; if the
       sparse factorisation fails, `std::runtime_error`. An empty mesh is left
       as it is.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
void l0_denoising(TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>> Default_solver;
  typedef typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t, NamedParameters,
                                                       Default_solver>::type Solver;
  static const char* fname = "l0_denoising()";
  if(faces(tmesh).empty())
    return;
  const double lambda_factor =
      choose_parameter(get_parameter(np, internal_np::l0_weight), 0.02 * 180. / 3.14159265358979323846);
  const double alpha_factor = choose_parameter(get_parameter(np, internal_np::regularization_weight), 0.1);
  D::require_positive(lambda_factor, fname, "l0_weight");
  D::require_positive(alpha_factor, fname, "regularization_weight");

  D::Classic_setup<TriangleMesh, NamedParameters> setup(tmesh, np, fname);
  D::L0_minimization<Solver> minimization(
      setup.mesh, setup.fixed, choose_parameter<Default_solver>(get_parameter(np, internal_np::sparse_linear_solver)),
      fname);
  if(minimization.run(lambda_factor, alpha_factor))
    setup.write_points(tmesh);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
