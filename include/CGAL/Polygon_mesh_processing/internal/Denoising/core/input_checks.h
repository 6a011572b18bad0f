// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Checks of a user's mesh, property maps and parameters made before anything
// is computed, so that a bad input gives a clear std::invalid_argument (and
// leaves the mesh unchanged) instead of a crash, an out-of-bounds access or
// NaN coordinates. Every function of the package checks through these.

#ifndef CGAL_PMP_INTERNAL_DENOISING_INPUT_CHECKS_H
#define CGAL_PMP_INTERNAL_DENOISING_INPUT_CHECKS_H

#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Throws std::invalid_argument unless `index_map` maps the `n` elements of
// `range` one to one onto [0, n). A `Surface_mesh` with removed elements that
// were not garbage-collected fails this check (its built-in indices then range
// beyond n); so does a user map that is not initialised.
template <typename Range, typename IndexMap>
void check_index_map(const Range& range, const IndexMap& index_map, std::size_t n, const char* what,
                     const char* function_name)
{
  std::vector<char> seen(n, 0);
  for(auto x : range)
  {
    const std::size_t i = static_cast<std::size_t>(get(index_map, x));
    if(i >= n || seen[i])
      throw std::invalid_argument(std::string(function_name) + ": the " + what + " index map does not number the " +
                                  what + "s from 0 to n-1 (index " + std::to_string(i) + " of " + std::to_string(n) +
                                  "); for a Surface_mesh with removed elements, call collect_garbage() first.");
    seen[i] = 1;
  }
}

// Throws std::invalid_argument unless the three coordinates are finite.
inline void check_finite_point(double x, double y, double z, const char* function_name)
{
  if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    throw std::invalid_argument(std::string(function_name) +
                                ": the mesh has a vertex with a NaN or infinite coordinate.");
}

// Throws std::invalid_argument naming the face's degree if a face of `tmesh`
// is not a triangle (make_flat_mesh() calls it, and the two checks above).
template <typename TriangleMesh>
void check_triangle_faces(const TriangleMesh& tmesh, const char* function_name)
{
  for(auto f : faces(tmesh))
  {
    std::size_t degree = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tmesh), tmesh))
    {
      (void)h;
      ++degree;
    }
    if(degree != 3)
      throw std::invalid_argument(std::string(function_name) + ": the mesh has a face with " + std::to_string(degree) +
                                  " vertices; only triangle meshes are supported "
                                  "(triangulate it first, e.g. with triangulate_faces()).");
  }
}

// Throws std::invalid_argument unless x is positive and finite.
inline void require_positive(double x, const char* function_name, const char* what)
{
  if(!(x > 0.) || !std::isfinite(x))
    throw std::invalid_argument(std::string(function_name) + ": " + what + " must be a positive finite number (got " +
                                std::to_string(x) + ").");
}

// Throws std::invalid_argument unless x is zero or positive, and finite.
inline void require_non_negative(double x, const char* function_name, const char* what)
{
  if(!(x >= 0.) || !std::isfinite(x))
    throw std::invalid_argument(std::string(function_name) + ": " + what +
                                " must be a non-negative finite number (got " + std::to_string(x) + ").");
}

// Throws std::invalid_argument unless x is in [0, 1) and finite (thresholds).
inline void require_unit_interval(double x, const char* function_name, const char* what)
{
  if(!(x >= 0. && x < 1.))
    throw std::invalid_argument(std::string(function_name) + ": " + what + " must be in [0, 1) (got " +
                                std::to_string(x) + ").");
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
