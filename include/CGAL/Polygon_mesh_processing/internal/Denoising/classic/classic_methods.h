// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Parts shared by the classic denoisers of the paper's Table 1: the setup
// every one starts from, topological face neighbourhoods, the faces around a
// vertex within a radius, and the loop "filter the face normals, then move
// the vertices (eq. 10)" common to the normal-filtering methods (Sun et al.
// 2007, Zheng et al. 2011, Zhang et al. 2015), optionally followed by the
// same relaxation along the surface as the intrinsic filter's
// (relax_tangentially()).

#ifndef CGAL_PMP_INTERNAL_DENOISING_CLASSIC_METHODS_H
#define CGAL_PMP_INTERNAL_DENOISING_CLASSIC_METHODS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/mesh_access.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/path_forest.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/weights/path_weights.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// What every classic method starts from: the user's property maps, a flat
// copy of the mesh (checked: triangles, index maps, finite coordinates) and
// its constrained vertices, by vertex index. The result is written back once,
// at the end, so an exception leaves the user's mesh unchanged.
template <typename TriangleMesh, typename NamedParameters>
struct Classic_setup
{
  const Mesh_maps<TriangleMesh, NamedParameters> maps;
  Flat_mesh mesh;
  const std::vector<char> fixed;

  Classic_setup(const TriangleMesh& tmesh, const NamedParameters& np, const char* fname)
      : maps(tmesh, np), mesh(maps.flat(tmesh, fname)), fixed(maps.constrained(tmesh))
  {
  }

  // The face data of the input and the paper's d (mean distance between the
  // centroids of edge-adjacent faces; 0 if no two faces share an edge).
  template <typename ConcurrencyTag>
  double input_faces(Face_data& input) const
  {
    compute_face_data<ConcurrencyTag>(mesh, mesh.points, input);
    return mean_adjacent_centroid_distance(mesh, input);
  }

  void write_points(TriangleMesh& tmesh) const { maps.write_points(tmesh, mesh.points); }
};

// The faces sharing at least `shared` vertices with each face (2: an edge, 1:
// a vertex), face itself excluded, in increasing index order.
inline Csr topological_face_neighbors(const Flat_mesh& m, int shared)
{
  const std::size_t nf = m.number_of_faces();
  Csr csr;
  csr.offsets.assign(nf + 1, 0);
  std::vector<std::uint32_t> list;
  for(std::size_t f = 0; f < nf; ++f)
  {
    list.clear();
    for(std::uint32_t v : m.triangles[f])
      for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
        if(m.vertex_faces[k] != f)
          list.push_back(m.vertex_faces[k]);
    std::sort(list.begin(), list.end());
    // a face appears once per shared vertex
    for(std::size_t a = 0; a < list.size();)
    {
      std::size_t b = a;
      while(b < list.size() && list[b] == list[a])
        ++b;
      if(int(b - a) >= shared)
        csr.items.push_back(list[a]);
      a = b;
    }
    csr.offsets[f + 1] = std::uint32_t(csr.items.size());
  }
  return csr;
}

// For each vertex v, the faces whose centroid lies within `radius` of v and
// that are connected to v through faces of that kind (a breadth-first search
// from v's incident faces through shared vertices:
// Face_fan_search::run_from_vertex()). The lists do not depend on the tag.
template <typename ConcurrencyTag>
Csr vertex_face_neighborhoods(const Flat_mesh& m, const std::vector<Vec3>& points, const std::vector<Vec3>& centroids,
                              double radius)
{
  const double r2 = radius * radius;
  Csr csr;
  build_lists<ConcurrencyTag>(
      m.number_of_vertices(), csr.offsets, csr.items, [&m] { return Face_fan_search(m); },
      [&](std::size_t v, Face_fan_search& s, std::vector<std::uint32_t>& out) {
        s.run_from_vertex(std::uint32_t(v), m, centroids, points[v], r2);
        out.insert(out.end(), s.found_begin(), s.found_end());
      });
  return csr;
}

// The scheme of the normal-filtering denoisers: `iterations` times, the face
// normals of the current mesh are filtered by `filter(current_face_data,
// filtered_normals)` and the vertices follow them by `vertex_iterations` steps
// of eq. 10, or of the least-squares update (`update`). Works on
// `mesh.points`; writes nothing to the user's mesh. Returns the filtered
// normals of the last pass (empty if no pass).
template <typename ConcurrencyTag, typename Filter>
std::vector<Vec3> normal_filtering_scheme(Flat_mesh& mesh, const std::vector<char>& fixed, unsigned int iterations,
                                          unsigned int vertex_iterations, Filter& filter,
                                          Vertex_update update = Vertex_update::PAPER)
{
  Face_data current;
  std::vector<Vec3> filtered, centroids, next;
  Least_squares_recovery recovery = make_vertex_recovery(update);
  for(unsigned int it = 0; it < iterations; ++it)
  {
    compute_face_data<ConcurrencyTag>(mesh, mesh.points, current);
    filter(current, filtered);
    update_vertices<ConcurrencyTag>(mesh, mesh.points, filtered, fixed, vertex_iterations, centroids, next, nullptr,
                                    &recovery);
  }
  return filtered;
}

// Runs a normal-filtering denoiser on `setup.mesh` with its filter
// `filter(current_face_data, filtered_normals)` (normal_filtering_scheme()):
// number_of_iterations, vertex_iterations, vertex_update and
// relax_along_surface are read from `np` (defaults 20, 10, eq. 10 and no
// relaxation); then writes the points to the user's mesh (once) and, if
// asked for, the filtered normals of the last pass.
template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters, typename Filter>
void run_normal_filtering(TriangleMesh& tmesh, const NamedParameters& np,
                          Classic_setup<TriangleMesh, NamedParameters>& setup, Filter& filter)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const bool relax = choose_parameter(get_parameter(np, internal_np::relax_along_surface), false);
  const std::vector<Vec3> input = relax ? setup.mesh.points : std::vector<Vec3>();
  const std::vector<Vec3> filtered = normal_filtering_scheme<ConcurrencyTag>(
      setup.mesh, setup.fixed, choose_parameter(get_parameter(np, internal_np::number_of_iterations), 20u),
      choose_parameter(get_parameter(np, internal_np::vertex_iterations), 10u), filter,
      choose_parameter(get_parameter(np, internal_np::vertex_update), Vertex_update::PAPER));
  if(relax)
  {
    // these methods have no fold safeguard of their own: the relaxation's
    // steps go through it with the result's orientation as the reference, so
    // no face turns over against the result
    Fold_safeguard guard;
    relax_tangentially<ConcurrencyTag>(setup.mesh, input, setup.mesh.points, setup.fixed, guard);
  }
  setup.write_points(tmesh);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::face_normal_t>::value)
    if(!filtered.empty())
      setup.maps.write_face_vectors(tmesh, filtered, get_parameter(np, internal_np::face_normal));
}

// One pass of a (joint) bilateral normal filter, as the intrinsic filter's
// engine with direct paths, phi = the face centroid, psi = `guidance`, and
// n = m = 2 (Zheng et al. 2011 with guidance = the normals; Zhang et al. 2015
// with guidance = the guidance normals):
//   out[i] = normalised sum over j in {i} + N_i of
//            A_j exp(-|c_i - c_j|^2 / 2 sigma_s^2) exp(-|g_i - g_j|^2 / 2 sigma_r^2) n_j.
// Face i takes part with weight A_i (both kernels are 1 at distance 0). A
// face whose sum vanishes keeps its normal.
template <typename ConcurrencyTag>
void bilateral_normal_pass(const Path_forest& direct, const Face_data& fd, const std::vector<Vec3>& guidance,
                           double sigma_spatial, double sigma_range, std::vector<Vec3>& out)
{
  Intrinsic_kernel kernel;
  kernel.sigma_spatial = sigma_spatial;
  kernel.sigma_range = sigma_range;
  kernel.spatial_exponent = kernel.range_exponent = 2.;
  kernel.include_self = true;
  out.resize(fd.normals.size());
  const auto centroid_sq = [&fd](std::uint32_t a, std::uint32_t b) {
    return squared_norm(fd.centroids[a] - fd.centroids[b]);
  };
  const auto guidance_sq = [&guidance](std::uint32_t a, std::uint32_t b) {
    return squared_norm(guidance[a] - guidance[b]);
  };
  intrinsic_weights_pass<ConcurrencyTag>(direct, kernel, centroid_sq, guidance_sq,
                                         [&](std::size_t i, std::uint32_t b, std::uint32_t e, const double* w) {
                                           Vec3 sum = fd.areas[i] * fd.normals[i];
                                           for(std::uint32_t k = b; k < e; ++k)
                                           {
                                             const std::uint32_t j = direct.face[k];
                                             sum = sum + (fd.areas[j] * w[k - b]) * fd.normals[j];
                                           }
                                           const double len = norm(sum);
                                           out[i] = (len > 0. && std::isfinite(len)) ? (1. / len) * sum : fd.normals[i];
                                         });
}

// sigma_spatial and sigma_range of a classic method (defaults `spatial` and
// `range`), checked positive.
struct Classic_sigmas
{
  double spatial, range;
};

template <typename NamedParameters>
Classic_sigmas read_classic_sigmas(const NamedParameters& np, const char* fname, double spatial, double range)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const Classic_sigmas s{choose_parameter(get_parameter(np, internal_np::sigma_spatial), spatial),
                         choose_parameter(get_parameter(np, internal_np::sigma_range), range)};
  require_positive(s.spatial, fname, "sigma_spatial");
  require_positive(s.range, fname, "sigma_range");
  return s;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
