// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The patch copy on which the geodesic path strategy (geodesic_paths.h)
// runs CGAL's Surface_mesh_shortest_path: a CGAL::Surface_mesh that flags
// the vertices a geodesic may pass through, and the two customisation
// points that hand those flags to CGAL.

#ifndef CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATCH_MESH_H
#define CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATCH_MESH_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/vec3.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <boost/optional.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// The patch copy: a CGAL::Surface_mesh that also knows, for each of its
// vertices, whether a geodesic may pass through it (CGAL's pseudo-sources).
//
// CGAL's Surface_mesh_shortest_path makes a pseudo-source (a vertex from which
// new cones of geodesics are expanded) of every saddle vertex (angle sum at
// least 2 pi, up to CGAL's relative margin 100 eps) and of every border vertex.
// A shortest path through a border vertex makes, on its only side, an angle
// not larger than the interior angle of the surface there; a shortest path has
// no angle below pi at a vertex it passes through (it could be shortened), so
// it never passes through a border vertex of interior angle below pi. About
// 13 of the 22 border vertices of a patch are such convex corners; expanding
// cones from them only costs time (10 to 20% of the path time). The patch
// therefore flags a vertex as a pseudo-source if it is
// - interior: CGAL's own saddle test (the same angle formula, in degrees, and
//   the same bound), on angles computed once per mesh face corner;
// - on the border: interior angle at least (1 - 1e-9) pi (straight or
//   reflex; the margin keeps straight borders, where the angle is pi up to
//   rounding).
// The flags reach CGAL through its two customisation points: the traits'
// Is_saddle_vertex functor (Geodesic_patch_traits) and the BGL free function
// is_border(vertex, graph), overloaded below for this mesh type so that it
// reports a border vertex only where a geodesic may turn around it.
// is_border(v, g) for a vertex is used by Surface_mesh_shortest_path only to
// choose its pseudo-sources (CGAL 5.5); halfedge and edge border tests are
// untouched.
typedef CGAL::Simple_cartesian<double> Geodesic_patch_kernel;
class Geodesic_patch_mesh : public CGAL::Surface_mesh<Geodesic_patch_kernel::Point_3>
{
public:
  typedef CGAL::Surface_mesh<Geodesic_patch_kernel::Point_3> Base;
  std::vector<char> pseudo_source; // by vertex index
  std::vector<char> border;        // by vertex index
};

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#define CGAL_GRAPH_TRAITS_INHERITANCE_CLASS_NAME CGAL::Polygon_mesh_processing::internal::Denoising::Geodesic_patch_mesh
#define CGAL_GRAPH_TRAITS_INHERITANCE_BASE_CLASS_NAME                                                                  \
  CGAL::Surface_mesh<CGAL::Polygon_mesh_processing::internal::Denoising::Geodesic_patch_kernel::Point_3>
#include <CGAL/boost/graph/graph_traits_inheritance_macros.h>

namespace boost {
// as CGAL does for graph_traits<const Surface_mesh<P> >
template <>
struct graph_traits<const CGAL::Polygon_mesh_processing::internal::Denoising::Geodesic_patch_mesh>
    : public graph_traits<CGAL::Polygon_mesh_processing::internal::Denoising::Geodesic_patch_mesh>
{
};
} // namespace boost

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Found by argument-dependent lookup from Surface_mesh_shortest_path (see
// Geodesic_patch_mesh): a border vertex that is a pseudo-source.
inline boost::optional<Geodesic_patch_mesh::Halfedge_index> is_border(Geodesic_patch_mesh::Vertex_index v,
                                                                      const Geodesic_patch_mesh& g)
{
  if(g.border[std::size_t(v)] && g.pseudo_source[std::size_t(v)])
    return g.halfedge(v); // the incoming border halfedge (see build_patch())
  return boost::none;
}

struct Geodesic_patch_traits
    : public CGAL::Surface_mesh_shortest_path_traits<Geodesic_patch_kernel, Geodesic_patch_mesh>
{
  struct Is_saddle_vertex
  {
    typedef bool result_type;
    template <typename VertexPointMap>
    bool operator()(Geodesic_patch_mesh::Vertex_index v, const Geodesic_patch_mesh& g, const VertexPointMap&) const
    {
      return g.pseudo_source[std::size_t(v)] != 0;
    }
    bool operator()(Geodesic_patch_mesh::Vertex_index v, const Geodesic_patch_mesh& g) const
    {
      return g.pseudo_source[std::size_t(v)] != 0;
    }
  };
  Is_saddle_vertex is_saddle_vertex_object() const { return Is_saddle_vertex(); }
};

// The angle of a triangle at q, in degrees, as CGAL's Is_saddle_vertex
// computes it (Surface_mesh_shortest_path/function_objects.h).
inline double corner_angle_degrees(const Vec3& p, const Vec3& q, const Vec3& r)
{
  const Vec3 u = p - q, v = r - q;
  const double product =
      std::sqrt((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  if(product == 0)
    return 0.;
  double cosine = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / product;
  cosine = (std::min)(1., (std::max)(-1., cosine));
  return std::acos(cosine) * 180. / CGAL_PI;
}

// Squared distance from p to the triangle (a, b, c) (closest point by the
// Voronoi regions of the vertices, edges and interior).
inline double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if(d1 <= 0. && d2 <= 0.)
    return squared_norm(ap);
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if(d3 >= 0. && d4 <= d3)
    return squared_norm(bp);
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0. && d1 >= 0. && d3 <= 0.)
    return squared_norm(ap - (d1 / (d1 - d3)) * ab);
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if(d6 >= 0. && d5 <= d6)
    return squared_norm(cp);
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0. && d2 >= 0. && d6 <= 0.)
    return squared_norm(ap - (d2 / (d2 - d6)) * ac);
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0. && (d4 - d3) >= 0. && (d5 - d6) >= 0.)
    return squared_norm(bp - ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b));
  const double denom = va + vb + vc;
  if(!(denom > 0.)) // degenerate triangle: nearest of its vertices
    return (std::min)({squared_norm(ap), squared_norm(bp), squared_norm(cp)});
  const double v = vb / denom, w = vc / denom;
  return squared_norm(ap - v * ab - w * ac);
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
