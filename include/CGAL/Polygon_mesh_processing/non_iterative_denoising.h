// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// [JDD03] Jones, Durand, Desbrun: "Non-iterative, feature-preserving mesh
// smoothing", ACM TOG 22(3) (SIGGRAPH 2003). A classic method of the paper's
// Table 1: each vertex is moved to a robust average of its projections on the
// tangent planes of nearby triangles, with mollified normals.

#ifndef CGAL_POLYGON_MESH_PROCESSING_NON_ITERATIVE_DENOISING_H
#define CGAL_POLYGON_MESH_PROCESSING_NON_ITERATIVE_DENOISING_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic/classic_methods.h>

#include <CGAL/tags.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

namespace internal {
namespace Denoising {

// Jones et al.'s filter as two named steps: mollify() smooths the vertices by
// a spatial Gaussian of width sigma_f / 2 over the face centroids (the
// mollified normals only serve the predictions); project() moves each free
// vertex to the weighted mean of its projections onto the planes of the
// faces within 2 sigma_f (their centroids, mollified normals), weighted by
// area, a spatial Gaussian (sigma_f) and an influence Gaussian on the
// projection distance (sigma_g). step() runs both on mesh.points.
template <typename ConcurrencyTag>
struct Robust_projection_filter
{
  double sigma_f, sigma_g;
  std::vector<Vec3> mollified, next;
  Face_data fd, mollified_faces;

  Robust_projection_filter(double sigma_f, double sigma_g, std::size_t vertices)
      : sigma_f(sigma_f), sigma_g(sigma_g), mollified(vertices), next(vertices)
  {
  }

  void step(Flat_mesh& mesh, const std::vector<char>& fixed)
  {
    compute_face_data<ConcurrencyTag>(mesh, mesh.points, fd);
    mollify(mesh);
    compute_face_data<ConcurrencyTag>(mesh, mollified, mollified_faces);
    project(mesh, fixed);
    mesh.points.swap(next);
  }

  void mollify(const Flat_mesh& mesh)
  {
    const std::vector<Vec3>& p = mesh.points;
    const double sigma_m = 0.5 * sigma_f;
    const Csr near = vertex_face_neighborhoods<ConcurrencyTag>(mesh, p, fd.centroids, 2. * sigma_m);
    for_each_chunk<ConcurrencyTag>(p.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t v = b; v < e; ++v)
      {
        Vec3 sum = {0., 0., 0.};
        double den = 0.;
        for(std::uint32_t k = near.begin(v); k < near.end(v); ++k)
        {
          const std::uint32_t q = near.items[k];
          const double w = fd.areas[q] * std::exp(-squared_norm(fd.centroids[q] - p[v]) / (2. * sigma_m * sigma_m));
          sum = sum + w * fd.centroids[q];
          den += w;
        }
        mollified[v] = den > 0. ? (1. / den) * sum : p[v];
      }
    });
  }

  void project(const Flat_mesh& mesh, const std::vector<char>& fixed)
  {
    const std::vector<Vec3>& p = mesh.points;
    const std::vector<Vec3>& nq = mollified_faces.normals;
    const Csr near = vertex_face_neighborhoods<ConcurrencyTag>(mesh, p, fd.centroids, 2. * sigma_f);
    for_each_chunk<ConcurrencyTag>(p.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t v = b; v < e; ++v)
      {
        next[v] = p[v];
        if(!fixed.empty() && fixed[v])
          continue;
        Vec3 sum = {0., 0., 0.};
        double den = 0.;
        for(std::uint32_t k = near.begin(v); k < near.end(v); ++k)
        {
          const std::uint32_t q = near.items[k];
          const double offset = dot(fd.centroids[q] - p[v], nq[q]);
          const Vec3 prediction = p[v] + offset * nq[q];
          const double w = fd.areas[q] * std::exp(-squared_norm(fd.centroids[q] - p[v]) / (2. * sigma_f * sigma_f) -
                                                  offset * offset / (2. * sigma_g * sigma_g));
          sum = sum + w * prediction;
          den += w;
        }
        if(den > 0.)
          next[v] = (1. / den) * sum;
      }
    });
  }
};

} // namespace Denoising
} // namespace internal

/*!
  \ingroup PMP_denoising_grp

  \brief denoises `tmesh` by the non-iterative, feature-preserving smoothing of
  Jones, Durand and Desbrun (2003) [JDD03].

  Every vertex \f$p\f$ moves to
  \f[ p' = \frac{\sum_q \Pi_q(p)\, a_q\, f(\|c_q - p\|)\, g(\|\Pi_q(p) - p\|)}{\sum_q a_q\, f(\|c_q - p\|)\,
  g(\|\Pi_q(p) - p\|)}, \qquad \Pi_q(p) = p + ((c_q - p)\cdot \tilde n_q)\,\tilde n_q, \f] over the triangles \f$q\f$
  (area \f$a_q\f$, centroid \f$c_q\f$) connected to \f$p\f$ whose centroid lies within \f$2\sigma_f\f$ of \f$p\f$, with
  Gaussians \f$f\f$ (width \f$\sigma_f\f$, spatial) and \f$g\f$ (width
  \f$\sigma_g\f$, influence). \f$\Pi_q(p)\f$ is the prediction of \f$p\f$ by
  the tangent plane of \f$q\f$. The normals \f$\tilde n_q\f$ are mollified:
  taken from a copy of the mesh whose vertices are first smoothed by the
  spatial Gaussian alone, of width \f$\sigma_f / 2\f$ (the weighted mean of the
  nearby centroids). All vertices are computed from the input at once: one
  pass, no iteration (more passes can be asked for).

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
      \cgalParamDescription{\f$\sigma_f\f$, as a multiple of the mean edge length \f$l\f$ of the input}
      \cgalParamType{double}
      \cgalParamDefault{`2`}
    \cgalParamNEnd
    \cgalParamNBegin{sigma_range}
      \cgalParamDescription{\f$\sigma_g\f$, as a multiple of \f$l\f$}
      \cgalParamType{double}
      \cgalParamDefault{`0.5`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{the number of passes (the method is meant to be used with one)}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`1`}
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
void non_iterative_denoising(TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static const char* fname = "non_iterative_denoising()";
  if(faces(tmesh).empty())
    return;
  const D::Classic_sigmas sigmas = D::read_classic_sigmas(np, fname, 2., 0.5);
  const double relative_sigma_f = sigmas.spatial, relative_sigma_g = sigmas.range;
  const unsigned int iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1u);

  D::Classic_setup<TriangleMesh, NamedParameters> setup(tmesh, np, fname);
  const double l = D::mean_edge_length(setup.mesh);
  D::Robust_projection_filter<ConcurrencyTag> filter(relative_sigma_f * l, relative_sigma_g * l,
                                                     setup.mesh.number_of_vertices());
  if(!(filter.sigma_f > 0.))
    return; // every edge has length 0: nothing to filter
  for(unsigned int it = 0; it < iterations; ++it)
    filter.step(setup.mesh, setup.fixed);
  setup.write_points(tmesh);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
