// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Per-face data of a flat mesh as arrays by face index (unit normals, areas,
// centroids), the renumbering of faces for memory locality, and the paper's d.

#ifndef CGAL_PMP_INTERNAL_DENOISING_FACE_DATA_H
#define CGAL_PMP_INTERNAL_DENOISING_FACE_DATA_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/vec3.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/flat_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Relative threshold under which a face counts as degenerate (zero area): its
// normal is then the zero vector, so that it never produces a NaN.
constexpr double degenerate_face_tolerance = 1e-12;

// Unit normal (or zero for a degenerate face), area and centroid of face f.
inline void face_geometry(const std::vector<Vec3>& points, const std::array<std::uint32_t, 3>& t, Vec3& normal,
                          double& area, Vec3& centroid)
{
  const Vec3& a = points[t[0]];
  const Vec3& b = points[t[1]];
  const Vec3& c = points[t[2]];
  const Vec3 ab = b - a, ac = c - a, bc = c - b;
  const Vec3 n = cross(ab, ac);
  const double len = norm(n);
  const double scale = squared_norm(ab) + squared_norm(ac) + squared_norm(bc);
  if(len > degenerate_face_tolerance * scale && std::isfinite(len))
    normal = (1. / len) * n;
  else
    normal = {0., 0., 0.};
  area = 0.5 * len;
  centroid = (1. / 3.) * (a + b + c);
}

// Per-face data by face index.
struct Face_data
{
  std::vector<Vec3> normals;
  std::vector<double> areas;
  std::vector<Vec3> centroids;
};

template <typename ConcurrencyTag>
void compute_face_data(const Flat_mesh& m, const std::vector<Vec3>& points, Face_data& fd)
{
  const std::size_t nf = m.number_of_faces();
  fd.normals.resize(nf);
  fd.areas.resize(nf);
  fd.centroids.resize(nf);
  for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t f = b; f < e; ++f)
      face_geometry(points, m.triangles[f], fd.normals[f], fd.areas[f], fd.centroids[f]);
  });
}

// Key of a point on the Morton (Z-order) curve of the box [lo, lo + extent]:
// the interleaved bits of its coordinates quantised to 21 bits each.
inline std::uint64_t morton_key(const Vec3& p, const Vec3& lo, const Vec3& inv_extent)
{
  std::uint64_t key = 0;
  std::uint64_t q[3];
  for(int a = 0; a < 3; ++a)
  {
    const double t = (p[a] - lo[a]) * inv_extent[a];  // in [0, 1]
    const double c = t > 0. ? (t < 1. ? t : 1.) : 0.; // also maps NaN to 0
    q[a] = std::uint64_t(c * double((1u << 21) - 1));
  }
  for(int bit = 20; bit >= 0; --bit)
    for(int a = 0; a < 3; ++a)
      key = (key << 1) | ((q[a] >> bit) & 1u);
  return key;
}

// Renumbers the faces of `m` (and their data `fd`) along the Morton curve of
// their centroids, so that the faces of a neighbourhood get nearby indices and
// the filter passes read normals mostly in sequence. Nothing but the numbering
// changes: each face keeps its vertices in order, each vertex lists its faces
// in the same order as before (the order of their input indices), and
// `m.input_face` records the input index of every face. Equal keys keep their
// input order, so the result does not depend on the concurrency tag.
template <typename ConcurrencyTag>
void reorder_faces_for_locality(Flat_mesh& m, Face_data& fd)
{
  const std::size_t nf = m.number_of_faces();
  if(nf < 2 || !m.input_face.empty())
    return;
  Vec3 lo = fd.centroids[0], hi = fd.centroids[0];
  for(const Vec3& c : fd.centroids)
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = (std::min)(lo[a], c[a]);
      hi[a] = (std::max)(hi[a], c[a]);
    }
  Vec3 inv;
  for(int a = 0; a < 3; ++a)
    inv[a] = hi[a] > lo[a] ? 1. / (hi[a] - lo[a]) : 0.;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(nf);
  for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t f = b; f < e; ++f)
      keys[f] = {morton_key(fd.centroids[f], lo, inv), std::uint32_t(f)};
  });
  std::sort(keys.begin(), keys.end()); // keys are distinct: the input index breaks ties
  std::vector<std::uint32_t> new_index(nf);
  m.input_face.resize(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    m.input_face[f] = keys[f].second;
    new_index[keys[f].second] = std::uint32_t(f);
  }
  std::vector<std::pair<std::uint64_t, std::uint32_t>>().swap(keys);
  m.triangles = gathered(m.triangles, m.input_face);
  fd.normals = gathered(fd.normals, m.input_face);
  fd.areas = gathered(fd.areas, m.input_face);
  fd.centroids = gathered(fd.centroids, m.input_face);
  for(std::uint32_t& f : m.vertex_faces)
    f = new_index[f];
}

// One third of the area of the faces around each vertex (its share of the
// surface: the measure of a vertex signal).
inline std::vector<double> vertex_areas(const Flat_mesh& m, const std::vector<double>& face_areas)
{
  std::vector<double> a(m.number_of_vertices(), 0.);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    for(std::uint32_t v : m.triangles[f])
      a[v] += face_areas[f] / 3.;
  return a;
}

// Mean distance between the centroids of edge-adjacent faces: the paper's d.
// Returns 0 if no two faces share an edge. The same value with every
// concurrency tag.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
double mean_adjacent_centroid_distance(const Flat_mesh& m, const Face_data& fd)
{
  return mean_of_face_terms<ConcurrencyTag>(m.number_of_faces(), [&](std::size_t f, const auto& add) {
    for_each_edge_adjacent_face_after(m, f, [&](std::uint32_t g) { add(norm(fd.centroids[g] - fd.centroids[f])); });
  });
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
