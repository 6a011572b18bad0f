// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Flat, index-based copies of a triangle mesh and of its per-face data
// (centroids, areas, unit normals). Every stage of the denoisers works on
// these arrays; the user's mesh is read once and written once.

#ifndef CGAL_PMP_INTERNAL_DENOISING_FACE_DATA_H
#define CGAL_PMP_INTERNAL_DENOISING_FACE_DATA_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/input_checks.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/parallel.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
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

// The two directions of a renumbering, `index` giving the input index of
// each element (empty: the identity, and `values` is returned as it is):
// scattered() takes values by element to values by input index,
// gathered() values by input index to values by element.
template <typename T>
std::vector<T> scattered(const std::vector<T>& values, const std::vector<std::uint32_t>& index)
{
  if(index.empty())
    return values;
  std::vector<T> out(values.size());
  for(std::size_t k = 0; k < values.size(); ++k)
    out[index[k]] = values[k];
  return out;
}
template <typename T>
std::vector<T> gathered(const std::vector<T>& values, const std::vector<std::uint32_t>& index)
{
  if(index.empty() || values.empty())
    return values;
  std::vector<T> out(index.size());
  for(std::size_t k = 0; k < index.size(); ++k)
    out[k] = values[index[k]];
  return out;
}

// A triangle mesh as arrays: vertex positions and, per face, its three vertex
// indices in the face's orientation; plus vertex -> incident faces in CSR form.
// The faces may be renumbered for memory locality (reorder_faces_for_locality);
// then `input_face` gives the input index of each face, and the incident faces
// of a vertex stay listed in the order of their input indices.
struct Flat_mesh
{
  std::vector<Vec3> points;                   // by vertex index
  std::vector<std::array<std::uint32_t, 3>> triangles; // by face index
  std::vector<std::uint32_t> vertex_face_offsets;      // size nv + 1
  std::vector<std::uint32_t> vertex_faces;
  std::vector<std::uint32_t> input_face; // input index of each face; empty: the identity
  std::vector<std::uint32_t> input_vertex; // input index of each vertex; empty: the identity

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_faces() const { return triangles.size(); }
  std::uint32_t input_index(std::uint32_t f) const { return input_face.empty() ? f : input_face[f]; }
  // values by face index -> values by input face index
  template <typename T>
  std::vector<T> in_input_order(const std::vector<T>& values) const
  {
    return scattered(values, input_face);
  }
  // values by vertex index -> values by input vertex index, and back
  template <typename T>
  std::vector<T> vertex_values_in_input_order(const std::vector<T>& values) const
  {
    return scattered(values, input_vertex);
  }
  template <typename T>
  std::vector<T> vertex_values_from_input_order(const std::vector<T>& values) const
  {
    return gathered(values, input_vertex);
  }
};

// Throws std::invalid_argument with a message naming the problem if `tmesh`
// cannot be denoised: a face that is not a triangle (here), an index map that
// is not a bijection onto [0, n) or a non-finite coordinate (input_checks.h,
// called in `make_flat_mesh`).
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
      throw std::invalid_argument(std::string(function_name) + ": the mesh has a face with " +
                                  std::to_string(degree) +
                                  " vertices; only triangle meshes are supported "
                                  "(triangulate it first, e.g. with triangulate_faces()).");
  }
}

template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap, typename FaceIndexMap>
Flat_mesh make_flat_mesh(const TriangleMesh& tmesh, VertexPointMap vpm, VertexIndexMap vim,
                         FaceIndexMap fim, const char* function_name)
{
  check_triangle_faces(tmesh, function_name);
  Flat_mesh m;
  const std::size_t nv = num_vertices(tmesh);
  const std::size_t nf = num_faces(tmesh);
  if(nv >= std::size_t((std::numeric_limits<std::uint32_t>::max)()) ||
     3 * nf >= std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    throw std::invalid_argument(std::string(function_name) + ": the mesh is too large (more than 2^32 entries).");
  check_index_map(vertices(tmesh), vim, nv, "vertex", function_name);
  check_index_map(faces(tmesh), fim, nf, "face", function_name);
  m.points.resize(nv);
  for(auto v : vertices(tmesh))
  {
    const auto& p = get(vpm, v);
    const Vec3 q = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    check_finite_point(q[0], q[1], q[2], function_name);
    m.points[get(vim, v)] = q;
  }
  m.triangles.resize(nf);
  for(auto f : faces(tmesh))
  {
    auto& t = m.triangles[get(fim, f)];
    int k = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, tmesh), tmesh))
      t[k++] = static_cast<std::uint32_t>(get(vim, v));
  }
  // vertex -> faces, faces listed in increasing index order
  m.vertex_face_offsets.assign(nv + 1, 0);
  for(const auto& t : m.triangles)
    for(std::uint32_t v : t)
      ++m.vertex_face_offsets[v + 1];
  for(std::size_t v = 0; v < nv; ++v)
    m.vertex_face_offsets[v + 1] += m.vertex_face_offsets[v];
  m.vertex_faces.resize(m.vertex_face_offsets[nv]);
  std::vector<std::uint32_t> fill(m.vertex_face_offsets.begin(), m.vertex_face_offsets.end() - 1);
  for(std::size_t f = 0; f < nf; ++f)
    for(std::uint32_t v : m.triangles[f])
      m.vertex_faces[fill[v]++] = static_cast<std::uint32_t>(f);
  return m;
}

// Relative threshold under which a face counts as degenerate (zero area): its
// normal is then the zero vector, so that it never produces a NaN.
constexpr double degenerate_face_tolerance = 1e-12;

// Unit normal (or zero for a degenerate face), area and centroid of face f.
inline void face_geometry(const std::vector<Vec3>& points, const std::array<std::uint32_t, 3>& t,
                          Vec3& normal, double& area, Vec3& centroid)
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
    const double t = (p[a] - lo[a]) * inv_extent[a]; // in [0, 1]
    const double c = t > 0. ? (t < 1. ? t : 1.) : 0.;  // also maps NaN to 0
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

// Renumbers the vertices in the order in which the faces (renumbered along
// the Morton curve first) use them, so that the vertices of nearby faces
// have nearby indices: the vertex update then reads memory mostly in
// sequence. Vertices no face uses come last, in input order. Each face keeps
// its corners in order and each vertex its incident faces in order, so every
// per-vertex result is the same as without the renumbering; `input_vertex`
// records the input index of every vertex.
inline void reorder_vertices_for_locality(Flat_mesh& m)
{
  const std::size_t nv = m.number_of_vertices();
  if(nv < 2 || !m.input_vertex.empty())
    return;
  const std::uint32_t unset = std::uint32_t(-1);
  std::vector<std::uint32_t> new_index(nv, unset);
  std::uint32_t next = 0;
  for(const auto& t : m.triangles)
    for(std::uint32_t v : t)
      if(new_index[v] == unset)
        new_index[v] = next++;
  for(std::size_t v = 0; v < nv; ++v)
    if(new_index[v] == unset)
      new_index[v] = next++;
  m.input_vertex.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
    m.input_vertex[new_index[v]] = std::uint32_t(v);
  m.points = m.vertex_values_from_input_order(m.points);
  for(auto& t : m.triangles)
    for(std::uint32_t& v : t)
      v = new_index[v];
  std::vector<std::uint32_t> offsets(nv + 1, 0), faces;
  faces.reserve(m.vertex_faces.size());
  for(std::size_t w = 0; w < nv; ++w)
  {
    const std::uint32_t v = m.input_vertex[w];
    faces.insert(faces.end(), m.vertex_faces.begin() + m.vertex_face_offsets[v],
                 m.vertex_faces.begin() + m.vertex_face_offsets[v + 1]);
    offsets[w + 1] = std::uint32_t(faces.size());
  }
  m.vertex_face_offsets.swap(offsets);
  m.vertex_faces.swap(faces);
}

// Area-weighted unit vertex normals (sum of the incident faces' cross
// products); zero for a vertex with no incident face of non-zero area.
inline std::vector<Vec3> area_weighted_vertex_normals(const Flat_mesh& m)
{
  std::vector<Vec3> n(m.number_of_vertices(), Vec3{0., 0., 0.});
  for(const auto& t : m.triangles)
  {
    const Vec3 c = cross(m.points[t[1]] - m.points[t[0]], m.points[t[2]] - m.points[t[0]]);
    for(std::uint32_t v : t)
      n[v] = n[v] + c;
  }
  for(Vec3& v : n)
  {
    const double len = norm(v);
    v = len > 0. ? (1. / len) * v : Vec3{0., 0., 0.};
  }
  return n;
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

// The mean of the values that terms(f, add) gives for every face f (one
// call add(x) per value), added in the order of the faces and of the calls,
// as one sequential loop would. With Parallel_tag the values are computed in
// parallel (at most 3 per face kept) and only added in order, so the result
// is bitwise the same; a face with more than 3 values (a non-manifold edge)
// makes the whole computation sequential. Returns 0 if there is no value.
template <typename ConcurrencyTag, typename Terms>
double mean_of_face_terms(std::size_t n, const Terms& terms)
{
  double sum = 0.;
  std::size_t count = 0;
  const auto add = [&sum, &count](double x) {
    sum += x;
    ++count;
  };
  bool in_order = !std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value || n < 4096;
  if(!in_order)
  {
    std::vector<std::array<double, 3>> values(n);
    std::vector<unsigned char> counts(n);
    for_each_chunk<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
      for(std::size_t f = b; f < e; ++f)
      {
        unsigned int c = 0;
        terms(f, [&](double x) {
          if(c < 3)
            values[f][c] = x;
          ++c;
        });
        counts[f] = static_cast<unsigned char>((std::min)(c, 4u));
      }
    });
    in_order = std::find(counts.begin(), counts.end(), static_cast<unsigned char>(4)) != counts.end();
    if(!in_order)
      for(std::size_t f = 0; f < n; ++f)
        for(unsigned int c = 0; c < counts[f]; ++c)
          add(values[f][c]);
  }
  if(in_order)
    for(std::size_t f = 0; f < n; ++f)
      terms(f, add);
  return count == 0 ? 0. : sum / double(count);
}

// Calls fn(g) for every face g of larger index than f that shares an edge
// with f (so that each pair of edge-adjacent faces is seen once, from its
// lower face), edge after edge of f, in the order of the faces around the
// edge's first vertex.
template <typename Fn>
void for_each_edge_adjacent_face_after(const Flat_mesh& m, std::size_t f, const Fn& fn)
{
  const auto& t = m.triangles[f];
  for(int k = 0; k < 3; ++k)
  {
    const std::uint32_t a = t[k], b = t[(k + 1) % 3];
    // faces around a that also contain b
    for(std::uint32_t i = m.vertex_face_offsets[a]; i < m.vertex_face_offsets[a + 1]; ++i)
    {
      const std::uint32_t g = m.vertex_faces[i];
      if(g <= f)
        continue;
      const auto& u = m.triangles[g];
      if(u[0] == b || u[1] == b || u[2] == b)
        fn(g);
    }
  }
}

// Mean distance between the centroids of edge-adjacent faces: the paper's d.
// Returns 0 if no two faces share an edge. The same value with every
// concurrency tag.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
double mean_adjacent_centroid_distance(const Flat_mesh& m, const Face_data& fd)
{
  return mean_of_face_terms<ConcurrencyTag>(m.number_of_faces(), [&](std::size_t f, const auto& add) {
    for_each_edge_adjacent_face_after(m, f,
                                      [&](std::uint32_t g) { add(norm(fd.centroids[g] - fd.centroids[f])); });
  });
}

// Mean edge length (each edge once), used to scale noise. The faces of each
// vertex must be listed by increasing index (a mesh not renumbered). The
// same value with every concurrency tag.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
double mean_edge_length(const Flat_mesh& m)
{
  return mean_of_face_terms<ConcurrencyTag>(m.number_of_faces(), [&](std::size_t f, const auto& add) {
    const auto& t = m.triangles[f];
    for(int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      // count edge (a,b) once: from the face of smallest index containing it
      bool first = true;
      for(std::uint32_t i = m.vertex_face_offsets[a]; i < m.vertex_face_offsets[a + 1] && first; ++i)
      {
        const std::uint32_t g = m.vertex_faces[i];
        if(g >= f)
          break;
        const auto& u = m.triangles[g];
        if(u[0] == b || u[1] == b || u[2] == b)
          first = false;
      }
      if(first)
        add(norm(m.points[b] - m.points[a]));
    }
  });
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
