// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Synthetic test models built from triangle soups: a plane grid, a cube, an
// octahedron with non-uniform sampling and the 18-edge (hexagonal) prism of
// the paper's section 5.2; and a mesh joined with a scaled copy of itself.
// Shared by the tests and the benchmarks.

#ifndef DENOISING_SUPPORT_SYNTHETIC_MESHES_H
#define DENOISING_SUPPORT_SYNTHETIC_MESHES_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <tuple>
#include <type_traits>
#include <vector>

namespace denoising_support {

using P3 = std::array<double, 3>;

// Triangle soup whose equal points (to 1e-9) are merged as they are added.
class Soup_builder
{
  std::map<std::tuple<long long, long long, long long>, std::size_t> index_;

public:
  std::vector<P3> points;
  std::vector<std::vector<std::size_t>> triangles;

  std::size_t add_point(const P3& p)
  {
    const auto key = std::make_tuple(std::llround(p[0] * 1e9), std::llround(p[1] * 1e9), std::llround(p[2] * 1e9));
    auto it = index_.find(key);
    if(it != index_.end())
      return it->second;
    index_.emplace(key, points.size());
    points.push_back(p);
    return points.size() - 1;
  }

  // Adds triangle (a, b, c), oriented so that its normal has a non-negative
  // component along `direction`.
  void add_triangle(const P3& a, const P3& b, const P3& c, const P3& direction)
  {
    const P3 u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const P3 n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double s = n[0] * direction[0] + n[1] * direction[1] + n[2] * direction[2];
    const std::size_t ia = add_point(a), ib = add_point(b), ic = add_point(c);
    if(s >= 0)
      triangles.push_back({ia, ib, ic});
    else
      triangles.push_back({ia, ic, ib});
  }

  // Outward orientation for a shape that is convex around the origin.
  void add_outward_triangle(const P3& a, const P3& b, const P3& c)
  {
    add_triangle(a, b, c, {a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]});
  }

  // Triangle (a, b, c) split into n^2 triangles. With `grading` != 1, the
  // sample at barycentric (l0, l1, l2) moves to (l0^g, l1^g, l2^g) normalised:
  // denser near the corners. The map is symmetric, so shared edges match.
  void add_subdivided_triangle(const P3& a, const P3& b, const P3& c, int n, double grading = 1.)
  {
    auto sample = [&](int i, int j) {
      double l[3] = {double(n - i - j) / n, double(i) / n, double(j) / n};
      double s = 0.;
      for(double& x : l)
        s += (x = std::pow(x, grading));
      P3 p;
      for(int k = 0; k < 3; ++k)
        p[k] = (l[0] * a[k] + l[1] * b[k] + l[2] * c[k]) / s;
      return p;
    };
    for(int i = 0; i < n; ++i)
      for(int j = 0; i + j < n; ++j)
      {
        add_outward_triangle(sample(i, j), sample(i + 1, j), sample(i, j + 1));
        if(i + j + 1 < n)
          add_outward_triangle(sample(i + 1, j), sample(i + 1, j + 1), sample(i, j + 1));
      }
  }

  // Parallelogram o + s u + t v (s, t in [0, 1]) split into nu x nv x 2 triangles.
  void add_subdivided_quad(const P3& o, const P3& u, const P3& v, int nu, int nv, bool outward = true,
                           const P3& up = {0., 0., 1.})
  {
    auto at = [&](int i, int j) {
      P3 p;
      for(int k = 0; k < 3; ++k)
        p[k] = o[k] + u[k] * double(i) / nu + v[k] * double(j) / nv;
      return p;
    };
    for(int i = 0; i < nu; ++i)
      for(int j = 0; j < nv; ++j)
      {
        const P3 p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
        if(outward)
        {
          add_outward_triangle(p00, p10, p11);
          add_outward_triangle(p00, p11, p01);
        }
        else
        {
          add_triangle(p00, p10, p11, up);
          add_triangle(p00, p11, p01, up);
        }
      }
  }

  template <typename Mesh>
  Mesh to_mesh() const
  {
    typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type
        Point;
    std::vector<Point> pts;
    for(const P3& p : points)
      pts.emplace_back(p[0], p[1], p[2]);
    Mesh mesh;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, triangles, mesh);
    return mesh;
  }
};

// Square [0, size]^2 in the plane z = 0, n x n cells, normals along +z (open).
template <typename Mesh>
Mesh plane_grid(int n, double size = 1.)
{
  Soup_builder s;
  s.add_subdivided_quad({0., 0., 0.}, {size, 0., 0.}, {0., size, 0.}, n, n, false);
  return s.to_mesh<Mesh>();
}

// A plane of `columns` x `rows` cells of width 1 and height `height`, each
// cell split along a diagonal: with a small height, two slivers per cell
// (aspect ratio about 1 / height), as in strip tessellations of CAD exports.
template <typename Mesh>
Mesh sliver_plane_grid(int columns, int rows, double height)
{
  Soup_builder s;
  s.add_subdivided_quad({0., 0., 0.}, {double(columns), 0., 0.}, {0., rows * height, 0.}, columns, rows, false);
  return s.to_mesh<Mesh>();
}

// Cube [-1, 1]^3, each side n x n cells.
template <typename Mesh>
Mesh cube(int n)
{
  Soup_builder s;
  for(int axis = 0; axis < 3; ++axis)
    for(double side : {-1., 1.})
    {
      P3 o = {-1., -1., -1.}, u = {0., 0., 0.}, v = {0., 0., 0.};
      o[axis] = side;
      u[(axis + 1) % 3] = 2.;
      v[(axis + 2) % 3] = 2.;
      s.add_subdivided_quad(o, u, v, n, n);
    }
  return s.to_mesh<Mesh>();
}

// Regular octahedron (vertices at distance 1 on the axes), each face split
// into n^2 triangles graded towards the corners (non-uniform sampling).
template <typename Mesh>
Mesh graded_octahedron(int n, double grading = 2.)
{
  Soup_builder s;
  for(double sx : {-1., 1.})
    for(double sy : {-1., 1.})
      for(double sz : {-1., 1.})
        s.add_subdivided_triangle({sx, 0., 0.}, {0., sy, 0.}, {0., 0., sz}, n, grading);
  return s.to_mesh<Mesh>();
}

// Prism on a regular hexagon (18 edges): circumradius 1, height `height`;
// sides split into n_around x n_up cells, caps into 6 triangles of n_cap^2.
template <typename Mesh>
Mesh hexagonal_prism(int n_around, int n_up, int n_cap, double height = 2.)
{
  Soup_builder s;
  const double pi = 3.14159265358979323846;
  for(int k = 0; k < 6; ++k)
  {
    const double a0 = 2. * pi * k / 6., a1 = 2. * pi * (k + 1) / 6.;
    const P3 p0 = {std::cos(a0), std::sin(a0), -height / 2}, p1 = {std::cos(a1), std::sin(a1), -height / 2};
    s.add_subdivided_quad(p0, {p1[0] - p0[0], p1[1] - p0[1], 0.}, {0., 0., height}, n_around, n_up);
    for(double z : {-height / 2, height / 2})
      s.add_subdivided_triangle({0., 0., z}, {p0[0], p0[1], z}, {p1[0], p1[1], z}, n_cap);
  }
  return s.to_mesh<Mesh>();
}

// The 18-edge prism of the benchmarks: each rim side split into 12 on the
// caps and on the sides, so that caps and sides share every rim vertex (a
// closed, edge-connected surface; with different splits the rims have
// T-junctions). 7776 faces and 3890 vertices, close to the paper's prism
// (7824 faces, 3914 vertices, its table 2).
template <typename Mesh>
Mesh benchmark_prism()
{
  return hexagonal_prism<Mesh>(12, 42, 12);
}

// Cylinder of radius 1 and height `height` around the z axis, tessellated
// as CAD exports often are: each cap a fan of n triangles around its centre
// (a vertex of valence n), the side one band of n quads split in two;
// 4n faces, closed, outward. The caps' slivers and their centres of high
// valence are the irregular tessellation a geometric neighbourhood search
// must not scan once per face reached.
template <typename Mesh>
Mesh fan_cylinder(int n, double height = 0.5)
{
  Soup_builder s;
  const double pi = 3.14159265358979323846;
  const P3 bottom = {0., 0., 0.}, top = {0., 0., height};
  for(int k = 0; k < n; ++k)
  {
    const double a0 = 2. * pi * k / n, a1 = 2. * pi * ((k + 1) % n) / n;
    const P3 p0 = {std::cos(a0), std::sin(a0), 0.}, p1 = {std::cos(a1), std::sin(a1), 0.};
    const P3 q0 = {p0[0], p0[1], height}, q1 = {p1[0], p1[1], height};
    s.add_triangle(bottom, p0, p1, {0., 0., -1.});
    s.add_triangle(top, q0, q1, {0., 0., 1.});
    const P3 out = {p0[0] + p1[0], p0[1] + p1[1], 0.};
    s.add_triangle(p0, p1, q1, out);
    s.add_triangle(p0, q1, q0, out);
  }
  return s.to_mesh<Mesh>();
}

// `mesh` and a copy of it scaled by `scale` and moved by `shift` along x,
// as one mesh of twice the connected components (the copy's vertices and
// faces after those of `mesh`, in the same order).
template <typename Mesh>
Mesh with_scaled_copy(const Mesh& mesh, double scale, double shift)
{
  Mesh copy = mesh;
  const auto points = get(CGAL::vertex_point, copy);
  typedef typename boost::property_traits<std::remove_const_t<decltype(points)>>::value_type Point;
  for(auto v : vertices(copy))
  {
    const Point p = get(points, v);
    put(points, v, Point(shift + scale * p.x(), scale * p.y(), scale * p.z()));
  }
  Mesh both = mesh;
  CGAL::copy_face_graph(copy, both);
  return both;
}

} // namespace denoising_support

#endif
