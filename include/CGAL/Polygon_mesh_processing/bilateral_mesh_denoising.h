// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// [FDC03] Fleishman, Drori, Cohen-Or: "Bilateral mesh denoising", ACM TOG
// 22(3) (SIGGRAPH 2003). A classic method of the paper's Table 1: vertices
// moved along their normals by a bilateral average of their neighbours'
// offsets, iterated.

#ifndef CGAL_POLYGON_MESH_PROCESSING_BILATERAL_MESH_DENOISING_H
#define CGAL_POLYGON_MESH_PROCESSING_BILATERAL_MESH_DENOISING_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic/classic_methods.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

namespace internal {
namespace Denoising {

// One step of Fleishman et al.'s vertex filter: each free vertex v moves
// along its area-weighted normal n_v by the average of the heights
// h = n_v . (q - v) of the vertices q within 2 sigma_c (reached through
// edges), weighted by exp(-|q - v|^2 / 2 sigma_c^2 - h^2 / 2 sigma_s^2); with
// `adaptive`, sigma_s is the standard deviation of those heights.
struct Vertex_bilateral_filter
{
  double sigma_c, sigma_s;
  bool adaptive;

  // From mesh.points to `next` (one entry per vertex).
  template <typename ConcurrencyTag>
  void step(const Flat_mesh& mesh, const Csr& adjacency, const std::vector<char>& fixed, std::vector<Vec3>& next) const
  {
    const std::vector<Vec3> normals = area_weighted_vertex_normals(mesh);
    const Csr neighbors =
        geometric_neighborhoods<ConcurrencyTag>(mesh.points, Vertex_edge_adjacency{adjacency}, 2. * sigma_c);
    const std::vector<Vec3>& p = mesh.points;
    for_each_chunk<ConcurrencyTag>(p.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t v = b; v < e; ++v)
      {
        next[v] = p[v];
        const std::uint32_t kb = neighbors.begin(v), ke = neighbors.end(v);
        if((!fixed.empty() && fixed[v]) || kb == ke || squared_norm(normals[v]) == 0.)
          continue;
        const double s = adaptive ? height_deviation(p, neighbors, v, normals[v]) : sigma_s;
        double num = 0., den = 0.;
        for(std::uint32_t k = kb; k < ke; ++k)
        {
          const Vec3 d = p[neighbors.items[k]] - p[v];
          const double t2 = squared_norm(d);
          const double h = dot(normals[v], d);
          // with a zero sigma_s (all offsets equal) the range weight is 1
          const double w = std::exp(-t2 / (2. * sigma_c * sigma_c) - (s > 0. ? h * h / (2. * s * s) : 0.));
          num += w * h;
          den += w;
        }
        if(den > 0.)
          next[v] = p[v] + (num / den) * normals[v];
      }
    });
  }

  // The standard deviation of the heights n . (q - p_v) of v's neighbours q.
  static double height_deviation(const std::vector<Vec3>& p, const Csr& neighbors, std::size_t v, const Vec3& n)
  {
    const std::uint32_t kb = neighbors.begin(v), ke = neighbors.end(v);
    double sum = 0., sum2 = 0.;
    for(std::uint32_t k = kb; k < ke; ++k)
    {
      const double h = dot(n, p[neighbors.items[k]] - p[v]);
      sum += h;
      sum2 += h * h;
    }
    const double mean = sum / double(ke - kb);
    return std::sqrt((std::max)(0., sum2 / double(ke - kb) - mean * mean));
  }
};

} // namespace Denoising
} // namespace internal

/*!
  \ingroup PMP_denoising_grp

  \brief denoises `tmesh` by bilateral mesh denoising, Fleishman, Drori and
  Cohen-Or (2003) [FDC03].

  `number_of_iterations` times, every vertex \f$v\f$ with unit normal \f$n\f$
  (area-weighted mean of its faces' normals) moves to
  \f[ v' = v + n\,\frac{\sum_{q} W_c(t_q)\, W_s(h_q)\, h_q}{\sum_q W_c(t_q)\, W_s(h_q)}, \qquad
      t_q = \|v - q\|,\ h_q = n\cdot(q - v),\ W(x) = e^{-x^2/2\sigma^2}, \f]
  the sums running over the vertices \f$q \ne v\f$ connected to \f$v\f$ by
  edges within distance \f$\rho = 2\sigma_c\f$ of \f$v\f$. The positions,
  normals and neighbourhoods are those of the previous iteration (all vertices
  move at once). Without a given \f$\sigma_s\f$, each vertex uses the standard
  deviation of its neighbours' offsets \f$h_q\f$, as the paper proposes.

  The mesh is read once and written once, at the end: if an exception is
  thrown, `tmesh` is left unchanged.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Parallel_if_available_tag`; the result does not depend on it.
  \tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to denoise; its vertex points are overwritten with the result
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{sigma_spatial}
      \cgalParamDescription{\f$\sigma_c\f$, as a multiple of the mean edge length \f$l\f$ of the input}
      \cgalParamType{double}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{sigma_range}
      \cgalParamDescription{\f$\sigma_s\f$, as a multiple of \f$l\f$}
      \cgalParamType{double}
      \cgalParamDefault{per vertex, the standard deviation of the offsets \f$h_q\f$ of its neighbourhood}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{the number of iterations}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`5`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_constrained_map, vertex_point_map, vertex_index_map, face_index_map, geom_traits}
      \cgalParamDescription{as for `intrinsic_denoising()`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `tmesh` is a triangle mesh with finite coordinates; the sigmas are
       positive and finite. Otherwise `std::invalid_argument` is thrown. An
       empty mesh is left as it is.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
void bilateral_mesh_denoising(TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  static const char* fname = "bilateral_mesh_denoising()";
  if(faces(tmesh).empty())
    return;
  const D::Classic_sigmas sigmas = D::read_classic_sigmas(np, fname, 1., 1.);
  const double relative_sigma_c = sigmas.spatial, relative_sigma_s = sigmas.range;
  const bool adaptive = is_default_parameter<NamedParameters, internal_np::sigma_range_t>::value;
  const unsigned int iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 5u);

  D::Classic_setup<TriangleMesh, NamedParameters> setup(tmesh, np, fname);
  const double l = D::mean_edge_length(setup.mesh);
  D::Vertex_bilateral_filter filter{relative_sigma_c * l, relative_sigma_s * l, adaptive};
  if(!(filter.sigma_c > 0.))
    return; // every edge has length 0: nothing to filter
  const D::Csr adjacency = D::vertex_adjacency(setup.mesh);
  std::vector<D::Vec3> next(setup.mesh.number_of_vertices());
  for(unsigned int it = 0; it < iterations; ++it)
  {
    filter.step<ConcurrencyTag>(setup.mesh, adjacency, setup.fixed, next);
    setup.mesh.points.swap(next);
  }
  setup.write_points(tmesh);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
