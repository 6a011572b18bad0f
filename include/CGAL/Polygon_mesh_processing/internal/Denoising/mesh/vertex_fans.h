// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The faces around a vertex of a Flat_mesh grouped into fans: faces
// connected through the edges at the vertex (Vertex_fans).

#ifndef CGAL_PMP_INTERNAL_DENOISING_VERTEX_FANS_H
#define CGAL_PMP_INTERNAL_DENOISING_VERTEX_FANS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/flat_mesh.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Groups a subset of the faces around a vertex into fans (a union-find over
// the faces that share an edge at the vertex). Knows, for every vertex,
// whether all its faces form one fan, so that the common case (every face
// around such a vertex in the subset) needs no grouping. Holds scratch
// memory: one per thread.
class Vertex_fans
{
public:
  explicit Vertex_fans(const Flat_mesh& m) : m_(m), one_fan_(m.number_of_vertices(), 0)
  {
    for(std::uint32_t v = 0; v < m.number_of_vertices(); ++v)
    {
      faces_.assign(m.vertex_faces.begin() + m.vertex_face_offsets[v],
                    m.vertex_faces.begin() + m.vertex_face_offsets[v + 1]);
      one_fan_[v] = group(v) == 1;
    }
  }

  // Groups the faces g around v with selected(g) into fans; returns the
  // number of fans. Then face(a), a < size(), are those faces and find(a)
  // the representative of face a's fan.
  template <typename Selected>
  std::size_t group_selected(std::uint32_t v, const Selected& selected)
  {
    faces_.clear();
    for(std::uint32_t q = m_.vertex_face_offsets[v]; q < m_.vertex_face_offsets[v + 1]; ++q)
    {
      const std::uint32_t g = m_.vertex_faces[q];
      if(selected(g))
        faces_.push_back(g);
    }
    const std::size_t n = faces_.size();
    root_.resize(n);
    if(one_fan_[v] && n == m_.vertex_face_offsets[v + 1] - m_.vertex_face_offsets[v])
    {
      std::fill(root_.begin(), root_.end(), std::size_t(0));
      return n == 0 ? 0 : 1;
    }
    return group(v);
  }

  std::size_t size() const { return faces_.size(); }
  std::uint32_t face(std::size_t a) const { return faces_[a]; }

  std::size_t find(std::size_t a)
  {
    while(root_[a] != a)
      a = root_[a] = root_[root_[a]];
    return a;
  }

private:
  // Union-find of faces_ (around v) by shared edges; returns the number of fans.
  std::size_t group(std::uint32_t v)
  {
    const std::size_t n = faces_.size();
    root_.resize(n);
    for(std::size_t a = 0; a < n; ++a)
      root_[a] = a;
    std::size_t fans = n;
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = a + 1; b < n; ++b)
        if(share_edge_at(faces_[a], faces_[b], v))
        {
          const std::size_t ra = find(a), rb = find(b);
          if(ra != rb)
          {
            root_[ra] = rb;
            --fans;
          }
        }
    return fans;
  }

  bool share_edge_at(std::uint32_t f, std::uint32_t g, std::uint32_t v) const
  {
    const auto& a = m_.triangles[f];
    const auto& b = m_.triangles[g];
    for(std::uint32_t x : a)
      if(x != v && (b[0] == x || b[1] == x || b[2] == x))
        return true;
    return false;
  }

  const Flat_mesh& m_;
  std::vector<char> one_fan_; // by vertex: its faces are connected through edges around it
  std::vector<std::uint32_t> faces_;
  std::vector<std::size_t> root_;
};

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
