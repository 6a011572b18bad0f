// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reading a user's mesh (through its property maps) into the flat arrays the
// algorithms work on, and writing results back. Shared by every public
// function of the package.

#ifndef CGAL_PMP_INTERNAL_DENOISING_MESH_ACCESS_H
#define CGAL_PMP_INTERNAL_DENOISING_MESH_ACCESS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/input_checks.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/named_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>

#include <CGAL/property_map.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// The property maps a public function reads from its named parameters.
template <typename TriangleMesh, typename NamedParameters>
struct Mesh_maps
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::type Vertex_point_map;
  typedef typename GetInitializedVertexIndexMap<TriangleMesh, NamedParameters>::const_type Vertex_index_map;
  typedef typename GetInitializedFaceIndexMap<TriangleMesh, NamedParameters>::const_type Face_index_map;
  typedef typename internal_np::Lookup_named_param_def<internal_np::vertex_is_constrained_t, NamedParameters,
                                                       Static_boolean_property_map<vertex_descriptor, false>>::type
      Vertex_constrained_map;

  Geom_traits gt;
  Vertex_point_map vpm;
  Vertex_index_map vim;
  Face_index_map fim;
  Vertex_constrained_map vcm;

  Mesh_maps(const TriangleMesh& tmesh, const NamedParameters& np)
      : gt(parameters::choose_parameter<Geom_traits>(parameters::get_parameter(np, internal_np::geom_traits))),
        vpm(parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                         get_property_map(CGAL::vertex_point, const_cast<TriangleMesh&>(tmesh)))),
        vim(CGAL::get_initialized_vertex_index_map(tmesh, np)), fim(CGAL::get_initialized_face_index_map(tmesh, np)),
        vcm(parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_is_constrained),
                                         Static_boolean_property_map<vertex_descriptor, false>()))
  {
  }

  Flat_mesh flat(const TriangleMesh& tmesh, const char* function_name) const
  {
    return make_flat_mesh(tmesh, vpm, vim, fim, function_name);
  }

  // 1 for the vertices the user pinned (by vertex index)
  std::vector<char> constrained(const TriangleMesh& tmesh) const
  {
    std::vector<char> fixed(num_vertices(tmesh), 0);
    for(auto v : vertices(tmesh))
      fixed[get(vim, v)] = get(vcm, v) ? 1 : 0;
    return fixed;
  }

  // Writes positions (by vertex index) back through the vertex point map.
  void write_points(TriangleMesh& tmesh, const std::vector<Vec3>& points) const
  {
    typedef typename Geom_traits::Point_3 Point_3;
    for(auto v : vertices(tmesh))
    {
      const Vec3& p = points[get(vim, v)];
      put(vpm, v, Point_3(p[0], p[1], p[2]));
    }
  }

  // Writes per-face vectors (by face index) to a user's face normal map.
  template <typename FaceNormalMap>
  void write_face_vectors(const TriangleMesh& tmesh, const std::vector<Vec3>& normals, FaceNormalMap fnm) const
  {
    typedef typename boost::property_traits<FaceNormalMap>::value_type Vector_3;
    for(auto f : faces(tmesh))
    {
      const Vec3& n = normals[get(fim, f)];
      put(fnm, f, Vector_3(n[0], n[1], n[2]));
    }
  }
};

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
