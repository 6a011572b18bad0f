// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Eq. 10 (the vertex update of Sun et al. 2007) on flat arrays.

#ifndef CGAL_PMP_INTERNAL_DENOISING_VERTEX_UPDATE_H
#define CGAL_PMP_INTERNAL_DENOISING_VERTEX_UPDATE_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/least_squares_vertex_update.h>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// ---- Fold safeguard -------------------------------------------------------
//
// The update of eq. 10 "easily generates folded triangles" (the paper, sec. 6).
// With the safeguard on, a step never lets a face
//   (a) point against its orientation before the step,
//   (b) point against its target (filtered) normal if it did not before, nor
//   (c) point against its reference orientation (the input mesh's, for
//       intrinsic_denoising(); the orientation at the start of the call
//       otherwise) if it did not before.
// Rule (c) makes "no face points against its input orientation" an invariant
// of the whole denoising: a face cannot turn over gradually either. A face
// that the input already has folded is not unfolded by it.
// Per step: all vertices compute their move (eq. 10); faces are checked at the
// new positions; the vertices of a face that folds have their move halved,
// `max_halvings` times at most; vertices still on a folding face after that
// stay where they are (repeated until no face folds, which terminates since a
// face whose three vertices stay cannot fold). Faces the package treats as
// degenerate (zero normal, see face_geometry) are not checked. Every decision
// depends only on the positions of the previous step, so the result is the
// same for any number of threads.
struct Fold_safeguard
{
  bool enabled = true;
  unsigned int max_halvings = 4;
  // unit normals of the reference orientation by face index (zero: not
  // checked); if null, update_vertices uses the orientation at its start
  const std::vector<Vec3>* reference = nullptr;
  // counters of the last call of update_vertices (for tests and benchmarks)
  std::size_t halved_moves = 0; // vertex moves halved at least once
  std::size_t frozen_moves = 0; // vertex moves cancelled
  // scratch space of apply_fold_safeguard, kept between steps so that the
  // iterations allocate nothing once the first has run
  std::vector<double> scale;
  std::vector<char> bad;
  std::vector<std::uint32_t> stamp, bad_faces, moved, recheck;
};

// Whether moving the corners of triangle t from `before` to `after` folds it
// (rules (a) to (c) above). Every test is evaluated and combined without
// branches (they mispredict often on noisy meshes); the degeneracy test
// compares squares, so no root is taken.
inline bool folds(const std::array<std::uint32_t, 3>& t, const std::vector<Vec3>& before,
                  const std::vector<Vec3>& after, const Vec3& target, const Vec3& reference)
{
  const Vec3 &a0 = before[t[0]], &b0 = before[t[1]], &c0 = before[t[2]];
  const Vec3 e0 = b0 - a0, f0 = c0 - a0;
  const Vec3 n0 = cross(e0, f0);
  const Vec3 &a1 = after[t[0]], &b1 = after[t[1]], &c1 = after[t[2]];
  const Vec3 n1 = cross(b1 - a1, c1 - a1);
  const bool turned_from_reference = (dot(n0, reference) > 0.) & !(dot(n1, reference) > 0.); // (c)
  const double scale = degenerate_face_tolerance * (squared_norm(e0) + squared_norm(f0) + squared_norm(c0 - b0));
  const bool oriented = squared_norm(n0) > scale * scale;                           // not degenerate before the step
  const bool turned = !(dot(n1, n0) > 0.);                                          // (a)
  const bool turned_from_target = (dot(n0, target) > 0.) & !(dot(n1, target) > 0.); // (b)
  return turned_from_reference | (oriented & (turned | turned_from_target));
}

// Restricts the moves `points` -> `next` of one step as described above;
// the scratch space is the guard's. Only the first check looks at
// every face: a later round re-checks just the faces around the vertices the
// round moved back, since whether a face folds depends on its own three
// vertices only. So every round finds the same folding faces as a check of all
// faces would, and the result does not depend on the number of threads.
template <typename ConcurrencyTag>
void apply_fold_safeguard(const Flat_mesh& m, const std::vector<Vec3>& points, std::vector<Vec3>& next,
                          const std::vector<Vec3>& normals, Fold_safeguard& guard)
{
  std::vector<double>& scale = guard.scale;
  std::vector<char>& bad = guard.bad;
  std::vector<std::uint32_t>&stamp = guard.stamp, &bad_faces = guard.bad_faces, &moved = guard.moved,
  &recheck = guard.recheck;
  const std::size_t nf = m.number_of_faces(), nv = m.number_of_vertices();
  bad.resize(nf);
  for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t f = b; f < e; ++f)
      bad[f] = folds(m.triangles[f], points, next, normals[f], (*guard.reference)[f]) ? 1 : 0;
  });
  bad_faces.clear();
  for(std::size_t f = 0; f < nf; ++f)
    if(bad[f])
      bad_faces.push_back(std::uint32_t(f));
  if(bad_faces.empty())
    return;
  scale.assign(nv, 1.);
  // stamp[v] / stamp[nv + f]: the last round (from 1) that listed vertex v /
  // face f, so that each is listed once per round
  stamp.assign(nv + nf, 0u);
  for(std::uint32_t round = 0; !bad_faces.empty(); ++round)
  {
    const bool halve = round < guard.max_halvings;
    const std::uint32_t mark = round + 1;
    moved.clear();
    for(std::uint32_t f : bad_faces)
      for(std::uint32_t v : m.triangles[f])
        if(scale[v] != 0. && stamp[v] != mark)
        {
          stamp[v] = mark;
          moved.push_back(v);
        }
    recheck.clear();
    for(std::uint32_t v : moved)
    {
      if(halve)
      {
        next[v] = points[v] + 0.5 * (next[v] - points[v]);
        scale[v] *= 0.5;
      }
      else
      {
        next[v] = points[v];
        scale[v] = 0.;
      }
      for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
      {
        const std::uint32_t f = m.vertex_faces[k];
        if(stamp[nv + f] != mark)
        {
          stamp[nv + f] = mark;
          recheck.push_back(f);
        }
      }
    }
    // a face that folds has a vertex that moved this round (one whose three
    // vertices stay cannot fold), so it is among the re-checked faces
    bad_faces.clear();
    for(std::uint32_t f : recheck)
      if(folds(m.triangles[f], points, next, normals[f], (*guard.reference)[f]))
        bad_faces.push_back(f);
  }
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(scale[v] == 0.)
      ++guard.frozen_moves;
    else if(scale[v] < 1.)
      ++guard.halved_moves;
  }
}

// `iterations` steps of
//   v <- v + 1/|F_v| sum_{j in F_v} n_j (n_j . (c_j - v)),
// all vertices moved at once from the positions of the previous step (c_j are
// the centroids of that step). Vertices with `fixed[v] != 0` and vertices with
// no incident face do not move. `centroids` is scratch space. With a `guard`
// that is enabled, every step is restricted so that no face folds (see
// Fold_safeguard). With a `least_squares` recovery that is enabled, each step
// is a least-squares step (see Least_squares_recovery) instead of eq. 10,
// restricted by the guard in the same way.
template <typename ConcurrencyTag>
void update_vertices(const Flat_mesh& m, std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                     const std::vector<char>& fixed, unsigned int iterations, std::vector<Vec3>& centroids,
                     std::vector<Vec3>& next, Fold_safeguard* guard = nullptr,
                     Least_squares_recovery* least_squares = nullptr)
{
  const std::size_t nf = m.number_of_faces(), nv = m.number_of_vertices();
  std::vector<Vec3> start_orientation;
  if(guard)
  {
    guard->halved_moves = guard->frozen_moves = 0;
    if(guard->enabled && !guard->reference)
    {
      Face_data fd;
      compute_face_data<ConcurrencyTag>(m, points, fd);
      start_orientation = std::move(fd.normals);
    }
  }
  Fold_safeguard* const active_guard = guard && guard->enabled ? guard : nullptr;
  const std::vector<Vec3>* const saved_reference = guard ? guard->reference : nullptr;
  if(active_guard && !active_guard->reference)
    active_guard->reference = &start_orientation;
  centroids.resize(nf);
  next.resize(nv);
  const bool global = least_squares && least_squares->enabled;
  for(unsigned int it = 0; it < iterations; ++it)
  {
    if(global)
    {
      least_squares_vertex_step<ConcurrencyTag>(m, points, normals, fixed, *least_squares, next);
      if(active_guard)
        apply_fold_safeguard<ConcurrencyTag>(m, points, next, normals, *active_guard);
      points.swap(next);
      continue;
    }
    for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
      for(std::size_t f = b; f < e; ++f)
      {
        const auto& t = m.triangles[f];
        centroids[f] = (1. / 3.) * (points[t[0]] + points[t[1]] + points[t[2]]);
      }
    });
    for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t b, std::size_t e) {
      for(std::size_t v = b; v < e; ++v)
      {
        const std::uint32_t fb = m.vertex_face_offsets[v], fe = m.vertex_face_offsets[v + 1];
        if(fe == fb || (!fixed.empty() && fixed[v]))
        {
          next[v] = points[v];
          continue;
        }
        Vec3 move = {0., 0., 0.};
        for(std::uint32_t k = fb; k < fe; ++k)
        {
          const std::uint32_t f = m.vertex_faces[k];
          const Vec3& n = normals[f];
          move = move + dot(n, centroids[f] - points[v]) * n;
        }
        next[v] = points[v] + (1. / double(fe - fb)) * move;
      }
    });
    if(active_guard)
      apply_fold_safeguard<ConcurrencyTag>(m, points, next, normals, *active_guard);
    points.swap(next);
  }
  if(guard)
    guard->reference = saved_reference;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
