// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The kernel, radius and paths of the intrinsic filters from their options
// (filter_options.h), and the construction of their paths: shared by the
// face-normal denoiser and the general filter of section 3.1.

#ifndef CGAL_PMP_INTERNAL_DENOISING_INTRINSIC_SETUP_H
#define CGAL_PMP_INTERNAL_DENOISING_INTRINSIC_SETUP_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/mesh_access.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/geodesic_paths.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/graph_paths.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/path_forest.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/square_pattern_paths.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/weights/normal_filter_pass.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Default parameter values of the intrinsic filters (see the documentation of
// intrinsic_denoising() for how they were chosen).
struct Intrinsic_defaults
{
  static constexpr unsigned int iterations = 30;
  static constexpr unsigned int vertex_iterations = 2;
  static constexpr double relative_radius = 4.;
  static constexpr double sigma_spatial = 0.4;
  static constexpr double sigma_range = 0.4;
};

// The values used for the parameters the caller did not give: the fixed
// defaults, or those the automatic mode of intrinsic_denoising() derived from
// the mesh.
struct Setup_defaults
{
  double sigma_spatial = Intrinsic_defaults::sigma_spatial;
  double sigma_range = Intrinsic_defaults::sigma_range;
  double relative_radius = Intrinsic_defaults::relative_radius;
};

// The kernel of `o`: sigma_s, sigma_r (defaults from `defaults`), n, m and
// the self term (default `default_self`), checked.
inline Intrinsic_kernel filter_kernel(const Filter_options& o, const char* fname, bool default_self = false,
                                      const Setup_defaults& defaults = Setup_defaults())
{
  Intrinsic_kernel k;
  k.sigma_spatial = o.sigma_spatial.value_or(defaults.sigma_spatial);
  k.sigma_range = o.sigma_range.value_or(defaults.sigma_range);
  k.spatial_exponent = o.spatial_exponent;
  k.range_exponent = o.range_exponent;
  k.include_self = o.include_self_weight.value_or(default_self);
  require_positive(k.sigma_spatial, fname, "sigma_spatial");
  require_positive(k.sigma_range, fname, "sigma_range");
  require_positive(k.spatial_exponent, fname, "spatial_exponent");
  require_positive(k.range_exponent, fname, "range_exponent");
  return k;
}

// Mean distance between the positions of adjacent items (each pair once).
template <typename Adjacency>
double mean_adjacent_distance(const std::vector<Vec3>& positions, const Adjacency& adjacent)
{
  double sum = 0.;
  std::size_t count = 0;
  for(std::uint32_t a = 0; a < positions.size(); ++a)
    adjacent(a, [&](std::uint32_t b) {
      if(b > a)
      {
        sum += norm(positions[b] - positions[a]);
        ++count;
      }
    });
  return count == 0 ? 0. : sum / double(count);
}

// The forest size from which square-pattern paths keep their parents as
// region sizes, for the filter pass on this processor: where the AVX2 kernel
// runs, always (it takes each shell's parent once,
// intrinsic_filter_faces_l1_avx2_shells, and is faster on region sizes than
// on a parent per node: one pass, 2 threads, 1.2M faces 0.198-0.211 s against
// 0.229 s, fandisk 1.50 against 1.70 ms); elsewhere from
// square_pattern_compact_min_nodes on, for the memory.
inline std::size_t square_pattern_compact_min_nodes_for_filter()
{
  return filter_pass_prefers_square_regions() ? 0 : square_pattern_compact_min_nodes;
}

// The paths of `strategy` in the neighbourhoods `neighbors` of items at
// `positions`. The square pattern and geodesic paths need the items to be the
// faces of `faces` (with their data `fd`); they are refused for other items.
// With `use_step_length`, the step lengths of eq. 4 are set, in units of
// `unit` (the mean distance between adjacent items).
template <typename ConcurrencyTag, typename Adjacency>
Path_forest make_paths(const Filter_options& o, Intrinsic_path_strategy strategy, bool use_step_length, double unit,
                       const std::vector<Vec3>& positions, const Adjacency& adjacent, const Csr& neighbors,
                       const Flat_mesh* faces, const Face_data* fd, const char* fname)
{
  Path_forest paths;
  if((strategy == Intrinsic_path_strategy::SQUARE_PATTERN || strategy == Intrinsic_path_strategy::GEODESIC) &&
     (faces == nullptr || fd == nullptr))
    throw std::invalid_argument(std::string(fname) +
                                ": square-pattern and geodesic paths are defined for face signals only; use DIRECT "
                                "or SHORTEST_GRAPH_PATH for vertex signals.");
  switch(strategy)
  {
  case Intrinsic_path_strategy::DIRECT:
    paths = direct_paths(neighbors);
    break;
  case Intrinsic_path_strategy::SHORTEST_GRAPH_PATH:
    paths = shortest_graph_paths<ConcurrencyTag>(positions, adjacent, neighbors);
    break;
  case Intrinsic_path_strategy::SQUARE_PATTERN:
    paths = square_pattern_paths<ConcurrencyTag>(*faces, *fd, neighbors, square_pattern_compact_min_nodes_for_filter());
    break;
  case Intrinsic_path_strategy::GEODESIC:
  {
    Geodesic_path_options go;
    go.patch_rings = o.geodesic_patch_rings.value_or(go.patch_rings);
    go.step_length = use_step_length;
    go.length_unit = unit > 0. ? unit : 1.;
    return geodesic_paths<ConcurrencyTag>(*faces, *fd, neighbors, go); // with its own step lengths
  }
  default:
    throw std::invalid_argument(std::string(fname) + ": unknown path strategy.");
  }
  if(use_step_length)
    set_step_lengths(paths, positions, unit > 0. ? unit : 1.);
  return paths;
}

// What stays fixed across the iterations of Algorithm 1: the flat mesh and
// paths (built on the mesh as given), and the kernel. The neighbourhoods are
// released once the paths are built (the path trees list the neighbours).
struct Intrinsic_setup
{
  Flat_mesh mesh;
  Face_data input_faces;
  double radius = 0.;
  double centroid_distance = 0.; // d, the unit of relative radii and step lengths
  Path_forest paths;
  Intrinsic_kernel kernel;
};

struct Fixed_setup_defaults
{
  Setup_defaults operator()(const Flat_mesh&) const { return Setup_defaults(); }
};

// `choose_defaults(mesh)` gives the values of the options not set in `o`.
template <typename ConcurrencyTag, typename TriangleMesh, typename Maps, typename ChooseDefaults = Fixed_setup_defaults>
Intrinsic_setup make_intrinsic_setup(const TriangleMesh& tmesh, const Filter_options& o, const Maps& maps,
                                     const char* fname, const ChooseDefaults& choose_defaults = ChooseDefaults())
{
  Intrinsic_setup s;
  const Intrinsic_path_strategy strategy = o.path_strategy.value_or(Intrinsic_path_strategy::SQUARE_PATTERN);
  const bool step_length = o.use_step_length;
  s.mesh = maps.flat(tmesh, fname);
  const Setup_defaults defaults = choose_defaults(static_cast<const Flat_mesh&>(s.mesh));
  s.kernel = filter_kernel(o, fname, false, defaults);
  compute_face_data<ConcurrencyTag>(s.mesh, s.mesh.points, s.input_faces);
  const double d = mean_adjacent_centroid_distance<ConcurrencyTag>(s.mesh, s.input_faces);
  s.centroid_distance = d;
  s.radius = filter_radius(o, fname, d, defaults.relative_radius);
  if(strategy == Intrinsic_path_strategy::SQUARE_PATTERN || strategy == Intrinsic_path_strategy::DIRECT)
    reorder_faces_for_locality<ConcurrencyTag>(s.mesh, s.input_faces); // same paths; results in s.mesh.input_face order
  if(strategy == Intrinsic_path_strategy::SQUARE_PATTERN)              // each neighbourhood searched and used at once
  {
    s.paths = square_pattern_paths_within<ConcurrencyTag>(s.mesh, s.input_faces, s.radius,
                                                          square_pattern_compact_min_nodes_for_filter());
    if(step_length)
      set_step_lengths(s.paths, s.input_faces.centroids, d > 0. ? d : 1.);
    return s;
  }
  {
    // released once the paths are built: they hold everything the iterations need
    const Csr neighbors = geometric_neighborhoods<ConcurrencyTag>(s.mesh, s.input_faces.centroids, s.radius,
                                                                  max_neighbors_within(s.radius, s.input_faces));
    s.paths = make_paths<ConcurrencyTag>(o, strategy, step_length, d, s.input_faces.centroids,
                                         Face_vertex_adjacency{s.mesh}, neighbors, &s.mesh, &s.input_faces, fname);
  }
  return s;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
