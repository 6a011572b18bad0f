// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A flat, index-based copy of a triangle mesh (positions, triangles, the
// faces around each vertex), built once from the user's mesh, with the
// renumberings and the edge walks every stage uses.

#ifndef CGAL_PMP_INTERNAL_DENOISING_FLAT_MESH_H
#define CGAL_PMP_INTERNAL_DENOISING_FLAT_MESH_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/input_checks.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/vec3.h>

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
  std::vector<Vec3> points;                            // by vertex index
  std::vector<std::array<std::uint32_t, 3>> triangles; // by face index
  std::vector<std::uint32_t> vertex_face_offsets;      // size nv + 1
  std::vector<std::uint32_t> vertex_faces;
  std::vector<std::uint32_t> input_face;   // input index of each face; empty: the identity
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

// Fills m.vertex_face_offsets and m.vertex_faces from m.points and
// m.triangles: the faces around each vertex, in increasing face index order.
inline void list_faces_around_vertices(Flat_mesh& m)
{
  const std::size_t nv = m.points.size();
  m.vertex_face_offsets.assign(nv + 1, 0);
  for(const auto& t : m.triangles)
    for(std::uint32_t v : t)
      ++m.vertex_face_offsets[v + 1];
  for(std::size_t v = 0; v < nv; ++v)
    m.vertex_face_offsets[v + 1] += m.vertex_face_offsets[v];
  m.vertex_faces.resize(m.vertex_face_offsets[nv]);
  std::vector<std::uint32_t> fill(m.vertex_face_offsets.begin(), m.vertex_face_offsets.end() - 1);
  for(std::size_t f = 0; f < m.triangles.size(); ++f)
    for(std::uint32_t v : m.triangles[f])
      m.vertex_faces[fill[v]++] = static_cast<std::uint32_t>(f);
}

template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap, typename FaceIndexMap>
Flat_mesh make_flat_mesh(const TriangleMesh& tmesh, VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim,
                         const char* function_name)
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
  list_faces_around_vertices(m);
  return m;
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
// products) of the mesh `m` with its vertices at `points`; zero for a vertex
// with no incident face of non-zero area.
inline std::vector<Vec3> area_weighted_vertex_normals(const Flat_mesh& m, const std::vector<Vec3>& points)
{
  std::vector<Vec3> n(m.number_of_vertices(), Vec3{0., 0., 0.});
  for(const auto& t : m.triangles)
  {
    const Vec3 c = cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
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

// The same at the mesh's own positions.
inline std::vector<Vec3> area_weighted_vertex_normals(const Flat_mesh& m)
{
  return area_weighted_vertex_normals(m, m.points);
}

// Calls fn(g) for every face g on the edge (a, b): the faces around vertex a
// that also have vertex b, in the order in which a lists its faces.
template <typename Fn>
void for_each_face_on_edge(const Flat_mesh& m, std::uint32_t a, std::uint32_t b, const Fn& fn)
{
  for(std::uint32_t i = m.vertex_face_offsets[a]; i < m.vertex_face_offsets[a + 1]; ++i)
  {
    const std::uint32_t g = m.vertex_faces[i];
    const auto& u = m.triangles[g];
    if(u[0] == b || u[1] == b || u[2] == b)
      fn(g);
  }
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
    for_each_face_on_edge(m, t[k], t[(k + 1) % 3], [&](std::uint32_t g) {
      if(g > f)
        fn(g);
    });
}

// Mean edge length (each edge once), used to scale noise. The same value
// with every concurrency tag.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
double mean_edge_length(const Flat_mesh& m)
{
  return mean_of_face_terms<ConcurrencyTag>(m.number_of_faces(), [&](std::size_t f, const auto& add) {
    const auto& t = m.triangles[f];
    for(int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      // count edge (a, b) once: from the face of smallest index on it
      std::size_t first = f;
      for_each_face_on_edge(m, a, b, [&first](std::uint32_t g) { first = (std::min)(first, std::size_t(g)); });
      if(first == f)
        add(norm(m.points[b] - m.points[a]));
    }
  });
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
