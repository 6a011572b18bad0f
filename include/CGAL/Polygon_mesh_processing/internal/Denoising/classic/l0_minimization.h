// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The internals of l0_denoising() (HS13): the interior edges and their
// edge-based Laplacian operator, and the alternating minimisation of the
// distance to the input plus the L0 norm of that operator.

#ifndef CGAL_PMP_INTERNAL_DENOISING_L0_MINIMIZATION_H
#define CGAL_PMP_INTERNAL_DENOISING_L0_MINIMIZATION_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic/classic_methods.h>

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
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
