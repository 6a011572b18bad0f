// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The 3D vector of doubles every stage of the denoisers computes with, and
// the mean angle between two sets of unit normals (E_n, eq. 12).

#ifndef CGAL_PMP_INTERNAL_DENOISING_VEC3_H
#define CGAL_PMP_INTERNAL_DENOISING_VEC3_H

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// A 3D vector of doubles; an aggregate of the package's namespace, so that
// its operators are found by argument-dependent lookup from anywhere.
struct Vec3
{
  double c[3];
  double& operator[](std::size_t i) { return c[i]; }
  const double& operator[](std::size_t i) const { return c[i]; }
  friend bool operator==(const Vec3& a, const Vec3& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }
  friend bool operator!=(const Vec3& a, const Vec3& b) { return !(a == b); }
};

inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double squared_norm(const Vec3& a) { return dot(a, a); }

inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

// Mean angle (degrees) between two equally long sets of unit normals, pair by
// pair; atan2 of |a x b| and a . b stays accurate for nearly equal normals.
// A pair with a zero normal counts as 0. E_n (eq. 12) is this between the
// face normals of two meshes.
inline double mean_angle_degrees(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  if(a.empty())
    return 0.;
  double sum = 0.;
  for(std::size_t f = 0; f < a.size(); ++f)
    sum += std::atan2(norm(cross(a[f], b[f])), dot(a[f], b[f]));
  return sum / double(a.size()) * (180. / 3.14159265358979323846);
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
