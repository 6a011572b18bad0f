// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The enumerations that named parameters of the package take: which paths
// the intrinsic filter follows, which signal a weight term measures, and how
// the vertices follow the filtered normals.

#ifndef CGAL_PMP_DENOISING_TYPES_H
#define CGAL_PMP_DENOISING_TYPES_H

namespace CGAL {
namespace Polygon_mesh_processing {

/// \ingroup PMP_denoising_grp
/// How the path from face `i` to a neighbour `j` is chosen; the sums of eq. 9
/// run along that path.
enum class Intrinsic_path_strategy
{
  /// Section 4 of the paper: neighbours projected on the tangent plane of `i`,
  /// split into six regions by their areal coordinates, sorted by distance, and
  /// linked by the square pattern (node `k` hangs from node `(ceil(sqrt(k))-1)^2`).
  SQUARE_PATTERN,
  /// The path is `{i, j}` (no intermediate face): with it the intrinsic filter
  /// degenerates to a bilateral normal filter on the same neighbourhood.
  DIRECT,
  /// Shortest paths in the adjacency graph inside the neighbourhood (faces
  /// through shared vertices, from centroid to centroid; vertices through
  /// edges), by Dijkstra: a cheap approximation of geodesic paths, and the
  /// paths of the geodesic and propagation filter presets.
  SHORTEST_GRAPH_PATH,
  /// The paper's first formulation (section 3.2, figure 2): the path is the
  /// exact geodesic from centroid `c_i` to centroid `c_j` (CGAL's
  /// `Surface_mesh_shortest_path`, computed on a copy of the neighbourhood
  /// patch), its nodes the faces the geodesic crosses, in order.
  GEODESIC
};

/// \ingroup PMP_denoising_grp
/// Built-in signals for \f$\varphi\f$ (in \f$d^s\f$) and \f$\psi\f$ (in
/// \f$d^r\f$) of the general intrinsic filter; a property map can be given
/// instead.
enum class Intrinsic_signal
{
  /// the signal being filtered
  INPUT,
  /// the position: face centroid, or vertex point
  POSITION,
  /// the unit normal: of the face, or the area-weighted normal of the vertex
  NORMAL,
  /// a constant: its term of the weight is 1 (as \f$d^r = 1\f$ in eq. 6)
  CONSTANT
};

/// \ingroup PMP_denoising_grp
/// How the vertices follow the filtered face normals after each filter pass.
enum class Vertex_update
{
  /// eq. 10 of the paper: \f$v_{iter}\f$ local steps, each vertex moved along
  /// the normals of its faces toward the planes through their centroids
  PAPER,
  /// global steps: each moves to the positions that minimise the misfit
  /// eq. 10 descends, \f$\sum_f \sum_{(a,b) \in f} (n_f \cdot (x_a - x_b))^2\f$,
  /// over the whole mesh at once, plus a weak pull to the positions before
  /// the step (a sparse linear system solved by conjugate gradients)
  LEAST_SQUARES
};

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
