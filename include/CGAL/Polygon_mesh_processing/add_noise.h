// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Seeded, reproducible noise for evaluating denoisers, as in section 5.2 of
// the intrinsic filter paper: vertices moved along their normals by Gaussian
// noise of standard deviation sigma_E times the mean edge length.

#ifndef CGAL_POLYGON_MESH_PROCESSING_ADD_NOISE_H
#define CGAL_POLYGON_MESH_PROCESSING_ADD_NOISE_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh_access.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Standard normal samples from std::mt19937_64 by the Box-Muller transform.
// Both are fully specified, so a seed gives the same noise on every platform
// (std::normal_distribution is implementation-defined).
class Seeded_gaussian
{
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.;

public:
  explicit Seeded_gaussian(std::uint64_t seed) : engine_(seed) {}
  // uniform in (0, 1]
  double uniform() { return (double((engine_() >> 11) + 1)) * (1.0 / 9007199254740992.0); }
  double operator()()
  {
    if(has_spare_)
    {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = uniform(), u2 = uniform();
    const double radius = std::sqrt(-2. * std::log(u1));
    const double angle = 6.283185307179586476925286766559 * u2;
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }
};

template <typename TriangleMesh, typename NamedParameters>
void add_noise_along_normals(TriangleMesh& tmesh, double relative_sigma, double fraction,
                             const NamedParameters& np, const char* fname)
{
  if(faces(tmesh).empty())
    return;
  if(!(relative_sigma >= 0.) || !std::isfinite(relative_sigma))
    throw std::invalid_argument(std::string(fname) + ": the noise level must be a non-negative finite number.");
  if(!(fraction >= 0. && fraction <= 1.))
    throw std::invalid_argument(std::string(fname) + ": the fraction of vertices must lie in [0, 1].");
  const Mesh_maps<TriangleMesh, NamedParameters> maps(tmesh, np);
  const std::uint64_t seed = parameters::choose_parameter(parameters::get_parameter(np, internal_np::random_seed), 0u);
  Flat_mesh m = maps.flat(tmesh, fname);
  const std::vector<Vec3> normals = area_weighted_vertex_normals(m);
  const std::vector<char> fixed = maps.constrained(tmesh);
  const double sigma = relative_sigma * mean_edge_length(m);
  Seeded_gaussian gaussian(seed);
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
  {
    // draw for every vertex, so that the noise of a vertex does not depend on
    // which others are fixed or selected
    const bool selected = fraction >= 1. || gaussian.uniform() <= fraction;
    const double amount = sigma * gaussian();
    if(selected && !fixed[v])
      m.points[v] = m.points[v] + amount * normals[v];
  }
  maps.write_points(tmesh, m.points);
}

} // namespace Denoising
} // namespace internal

/*!
  \ingroup PMP_denoising_grp

  \brief moves every vertex of `tmesh` along its area-weighted normal by a
  Gaussian amount of standard deviation `relative_sigma` times the mean edge
  length of `tmesh` (the paper's \f$\sigma_E\f$, section 5.2).

  The noise is reproducible: the same seed gives the same displacements on
  every platform (a Mersenne twister `std::mt19937_64` and the Box-Muller
  transform, both fully specified).

  \cgalNamedParamsBegin
    \cgalParamNBegin{random_seed}
      \cgalParamDescription{the seed of the random generator}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_constrained_map}
      \cgalParamDescription{vertices that receive no noise}
      \cgalParamType{a model of `ReadablePropertyMap` with vertex descriptors as keys and `bool` as values}
      \cgalParamDefault{no vertex is constrained}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map, geom_traits}
      \cgalParamDescription{as for `intrinsic_denoising()`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `tmesh` is a triangle mesh with finite coordinates and `relative_sigma`
       is non-negative; otherwise `std::invalid_argument` is thrown and `tmesh`
       is unchanged.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void add_gaussian_noise(TriangleMesh& tmesh, double relative_sigma,
                        const NamedParameters& np = parameters::default_values())
{
  internal::Denoising::add_noise_along_normals(tmesh, relative_sigma, 1., np, "add_gaussian_noise()");
}

/*!
  \ingroup PMP_denoising_grp

  \brief impulsive noise: each vertex of `tmesh` is chosen with probability
  `fraction`, and each chosen vertex moves along its area-weighted normal by a
  Gaussian amount of standard deviation `relative_sigma` times the mean edge
  length. Seeded and reproducible like `add_gaussian_noise()`, with the same
  named parameters.

  \pre as for `add_gaussian_noise()`, and `fraction` lies in [0, 1].
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void add_impulsive_noise(TriangleMesh& tmesh, double fraction, double relative_sigma,
                         const NamedParameters& np = parameters::default_values())
{
  internal::Denoising::add_noise_along_normals(tmesh, relative_sigma, fraction, np, "add_impulsive_noise()");
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
