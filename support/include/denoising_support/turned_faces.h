// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// How many faces of a mesh point against their orientation in another
// version of it (same faces, same order): the fold safeguard's measure, for
// the tests.

#ifndef DENOISING_SUPPORT_TURNED_FACES_H
#define DENOISING_SUPPORT_TURNED_FACES_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <vector>

namespace denoising_support {

// Unnormalised normal (twice the area vector) of each face, by face index.
template <typename Mesh>
auto area_vectors(const Mesh& mesh)
{
  typedef
      typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type
          Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  std::vector<Vector> n;
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    const Point a = get(CGAL::vertex_point, mesh, source(h, mesh)), b = get(CGAL::vertex_point, mesh, target(h, mesh)),
                c = get(CGAL::vertex_point, mesh, target(next(h, mesh), mesh));
    n.push_back(CGAL::cross_product(b - a, c - a));
  }
  return n;
}

// Faces of `after` whose normal points against (or is orthogonal to) the
// normal of the same face in `before`; faces of zero area in `before` are not
// counted.
template <typename Mesh>
std::size_t turned_faces(const Mesh& before, const Mesh& after)
{
  const auto a = area_vectors(before), b = area_vectors(after);
  std::size_t count = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].squared_length() > 0. && !(a[i] * b[i] > 0.))
      ++count;
  return count;
}

} // namespace denoising_support

#endif
