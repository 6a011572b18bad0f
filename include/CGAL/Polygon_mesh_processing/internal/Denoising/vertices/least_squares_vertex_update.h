// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A global alternative to eq. 10: the vertex positions that fit the filtered
// face normals over the whole mesh, solved as one sparse linear system.

#ifndef CGAL_PMP_INTERNAL_DENOISING_LEAST_SQUARES_VERTEX_UPDATE_H
#define CGAL_PMP_INTERNAL_DENOISING_LEAST_SQUARES_VERTEX_UPDATE_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/named_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Eq. 10 is a Jacobi-like descent step of
//   E_n(x) = sum_f sum_{edges (a, b) of f} (n_f . (x_a - x_b))^2,
// moving every vertex by the mean of its faces' corrections, so that two
// steps (the default v_iter) remove only part of the misfit. The
// least-squares update minimises
//   E(x) = E_n(x) + alpha sum_v w_v |x_v - p_v|^2
// over all free vertices at once, with p the positions before the step and
// w_v the number of faces around v (the weight E_n gives v). The second term
// keeps the step local: E_n alone is blind to translations and scalings of
// the whole mesh, and to tangential motion on flat parts.
//
// E is quadratic; its 3n x 3n system is solved by conjugate gradients with
// the 3x3 diagonal blocks as preconditioner, started from p. The matrix is
// never stored: a product is one gather over the faces around each vertex,
// so memory is a few vectors of the vertex count. Fixed vertices, and
// vertices with no face, stay at p. Every product and every dot product adds
// in an order that does not depend on the number of threads. It fits the
// target normals far better than eq. 10 when they are right, and their
// errors as faithfully when they are not (the manual gives figures).
struct Least_squares_recovery
{
  bool enabled = false;
  double fidelity = 0.05;  // alpha
  double tolerance = 1e-6; // on the preconditioned residual, relative to the start
  unsigned int max_solver_iterations = 200;
  // iterations of the last solve (for tests and benchmarks)
  unsigned int last_solver_iterations = 0;
  // scratch space, kept between steps
  std::vector<std::array<double, 6>> inverse_blocks;
  std::vector<double> weights;
  std::vector<Vec3> rhs, residual, preconditioned, direction, product;
  std::vector<double> partial;
};

namespace least_squares_detail {

// symmetric 3x3 matrices as (xx, yy, zz, xy, xz, yz)
using Sym3 = std::array<double, 6>;

inline Vec3 multiply(const Sym3& s, const Vec3& v)
{
  return {s[0] * v[0] + s[3] * v[1] + s[4] * v[2], s[3] * v[0] + s[1] * v[1] + s[5] * v[2],
          s[4] * v[0] + s[5] * v[1] + s[2] * v[2]};
}

// Inverse of a symmetric positive definite matrix (zero if singular).
inline Sym3 inverse(const Sym3& s)
{
  const double c00 = s[1] * s[2] - s[5] * s[5], c01 = s[4] * s[5] - s[3] * s[2], c02 = s[3] * s[5] - s[4] * s[1];
  const double det = s[0] * c00 + s[3] * c01 + s[4] * c02;
  if(!(std::abs(det) > 0.) || !std::isfinite(det))
    return {0., 0., 0., 0., 0., 0.};
  const double k = 1. / det;
  return {k * c00, k * (s[0] * s[2] - s[4] * s[4]), k * (s[0] * s[1] - s[3] * s[3]), k * c01,
          k * c02, k * (s[3] * s[4] - s[0] * s[5])};
}

// sum_v dot(a_v, b_v) added in blocks of fixed size, then in block order: the
// same for any number of threads.
template <typename ConcurrencyTag>
double blocked_dot(const std::vector<Vec3>& a, const std::vector<Vec3>& b, std::vector<double>& partial)
{
  constexpr std::size_t block = 2048;
  const std::size_t n = a.size(), nb = (n + block - 1) / block;
  partial.assign(nb, 0.);
  for_each_chunk<ConcurrencyTag>(
      nb,
      [&](std::size_t bb, std::size_t be) {
        for(std::size_t k = bb; k < be; ++k)
        {
          double s = 0.;
          const std::size_t end = (std::min)(n, (k + 1) * block);
          for(std::size_t v = k * block; v < end; ++v)
            s += dot(a[v], b[v]);
          partial[k] = s;
        }
      },
      1);
  double s = 0.;
  for(double x : partial)
    s += x;
  return s;
}

// The weights w_v, the right-hand side alpha w p and the inverse of the
// diagonal blocks of the system for `normals` and `points`; w_v = 0 marks a
// vertex that stays.
template <typename ConcurrencyTag>
void assemble_system(const Flat_mesh& m, const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                     const std::vector<char>& fixed, Least_squares_recovery& ls)
{
  const std::size_t nv = m.number_of_vertices();
  ls.inverse_blocks.resize(nv);
  ls.weights.resize(nv);
  ls.rhs.resize(nv);
  const double alpha = ls.fidelity;
  for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t vb, std::size_t ve) {
    for(std::size_t v = vb; v < ve; ++v)
    {
      const std::uint32_t fb = m.vertex_face_offsets[v], fe = m.vertex_face_offsets[v + 1];
      if(fe == fb || (!fixed.empty() && fixed[v]))
      {
        ls.weights[v] = 0.;
        continue;
      }
      const double wv = double(fe - fb);
      Sym3 block = {alpha * wv, alpha * wv, alpha * wv, 0., 0., 0.};
      for(std::uint32_t k = fb; k < fe; ++k)
      {
        const Vec3& n = normals[m.vertex_faces[k]];
        block[0] += 2. * n[0] * n[0];
        block[1] += 2. * n[1] * n[1];
        block[2] += 2. * n[2] * n[2];
        block[3] += 2. * n[0] * n[1];
        block[4] += 2. * n[0] * n[2];
        block[5] += 2. * n[1] * n[2];
      }
      ls.weights[v] = wv;
      ls.rhs[v] = (alpha * wv) * points[v];
      ls.inverse_blocks[v] = inverse(block);
    }
  });
}

// y = A x on the free vertices (zero on the others), A the system of
// assemble_system().
template <typename ConcurrencyTag>
void apply_system(const Flat_mesh& m, const std::vector<Vec3>& normals, const Least_squares_recovery& ls,
                  const std::vector<Vec3>& x, std::vector<Vec3>& y)
{
  const std::size_t nv = m.number_of_vertices();
  const std::vector<double>& w = ls.weights;
  const double alpha = ls.fidelity;
  y.resize(nv);
  for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t vb, std::size_t ve) {
    for(std::size_t v = vb; v < ve; ++v)
    {
      if(w[v] == 0.)
      {
        y[v] = {0., 0., 0.};
        continue;
      }
      Vec3 s = (alpha * w[v]) * x[v];
      for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
      {
        const std::uint32_t f = m.vertex_faces[k];
        const auto& t = m.triangles[f];
        const Vec3& n = normals[f];
        s = s + dot(n, 3. * x[v] - x[t[0]] - x[t[1]] - x[t[2]]) * n;
      }
      y[v] = s;
    }
  });
}

} // namespace least_squares_detail

// One least-squares step: `next` receives the minimiser of E (see above) for
// the face normals `normals` from the positions `points`.
template <typename ConcurrencyTag>
void least_squares_vertex_step(const Flat_mesh& m, const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                               const std::vector<char>& fixed, Least_squares_recovery& ls, std::vector<Vec3>& next)
{
  namespace L = least_squares_detail;
  const std::size_t nv = m.number_of_vertices();
  auto& inv = ls.inverse_blocks;
  auto& w = ls.weights;
  auto &b = ls.rhs, &r = ls.residual, &z = ls.preconditioned, &d = ls.direction, &q = ls.product;
  L::assemble_system<ConcurrencyTag>(m, points, normals, fixed, ls);
  const auto apply = [&](const std::vector<Vec3>& x, std::vector<Vec3>& y) {
    L::apply_system<ConcurrencyTag>(m, normals, ls, x, y);
  };

  next = points;
  apply(next, q);
  r.resize(nv);
  z.resize(nv);
  for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t vb, std::size_t ve) {
    for(std::size_t v = vb; v < ve; ++v)
    {
      r[v] = w[v] == 0. ? Vec3{0., 0., 0.} : b[v] - q[v];
      z[v] = L::multiply(inv[v], r[v]);
    }
  });
  d = z;
  double rz = L::blocked_dot<ConcurrencyTag>(r, z, ls.partial);
  const double stop = rz * ls.tolerance * ls.tolerance;
  ls.last_solver_iterations = 0;
  for(unsigned int it = 0; it < ls.max_solver_iterations && rz > stop && rz > 0.; ++it)
  {
    apply(d, q);
    const double dq = L::blocked_dot<ConcurrencyTag>(d, q, ls.partial);
    if(!(dq > 0.))
      break;
    const double step = rz / dq;
    for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t vb, std::size_t ve) {
      for(std::size_t v = vb; v < ve; ++v)
      {
        next[v] = next[v] + step * d[v];
        r[v] = r[v] - step * q[v];
        z[v] = L::multiply(inv[v], r[v]);
      }
    });
    const double rz_next = L::blocked_dot<ConcurrencyTag>(r, z, ls.partial);
    const double gamma = rz_next / rz;
    rz = rz_next;
    for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t vb, std::size_t ve) {
      for(std::size_t v = vb; v < ve; ++v)
        d[v] = z[v] + gamma * d[v];
    });
    ls.last_solver_iterations = it + 1;
  }
  // a non-finite solve (it needs non-finite input) leaves the step undone
  for(std::size_t v = 0; v < nv; ++v)
    if(!(std::isfinite(next[v][0]) && std::isfinite(next[v][1]) && std::isfinite(next[v][2])))
    {
      next = points;
      break;
    }
}

// The recovery `mode` asks for.
inline Least_squares_recovery make_vertex_recovery(Vertex_update mode)
{
  Least_squares_recovery ls;
  ls.enabled = mode == Vertex_update::LEAST_SQUARES;
  return ls;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
