// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Seeded, reproducible noise for evaluating denoisers: as in section 5.2 of
// the intrinsic filter paper, vertices moved along their normals by Gaussian
// noise of standard deviation sigma_E times the mean edge length (on every
// vertex or on a random fraction of them); Gaussian noise in random
// directions; and a simulation of a range scanner's noise, along the rays
// from a virtual camera.

#ifndef CGAL_POLYGON_MESH_PROCESSING_ADD_NOISE_H
#define CGAL_POLYGON_MESH_PROCESSING_ADD_NOISE_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/mesh_access.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
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

// Moves each vertex of `tmesh` by a seeded random displacement: calls
// `make_draw(m)` once with the flattened mesh, then `draw(v, sigma, gaussian,
// d)` for every vertex in order, fixed or not, so that the noise of a vertex
// does not depend on which others are fixed; the vertex moves by d if `draw`
// returns true and it is not constrained. sigma is relative_sigma times the
// mean edge length. The caller has checked the arguments; `tmesh` has faces.
template <typename TriangleMesh, typename NamedParameters, typename MakeDraw>
void add_vertex_noise(TriangleMesh& tmesh, double relative_sigma, const NamedParameters& np, const char* fname,
                      const MakeDraw& make_draw)
{
  const Mesh_maps<TriangleMesh, NamedParameters> maps(tmesh, np);
  const std::uint64_t seed = parameters::choose_parameter(parameters::get_parameter(np, internal_np::random_seed), 0u);
  Flat_mesh m = maps.flat(tmesh, fname);
  const std::vector<char> fixed = maps.constrained(tmesh);
  const double sigma = relative_sigma * mean_edge_length(m);
  const auto draw = make_draw(m);
  Seeded_gaussian gaussian(seed);
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
  {
    Vec3 d;
    if(draw(v, sigma, gaussian, d) && !fixed[v])
      m.points[v] = m.points[v] + d;
  }
  maps.write_points(tmesh, m.points);
}

template <typename TriangleMesh, typename NamedParameters>
void add_noise_along_normals(TriangleMesh& tmesh, double relative_sigma, double fraction, const NamedParameters& np,
                             const char* fname)
{
  if(faces(tmesh).empty())
    return;
  require_non_negative(relative_sigma, fname, "the noise level");
  if(!(fraction >= 0. && fraction <= 1.))
    throw std::invalid_argument(std::string(fname) + ": the fraction of vertices must lie in [0, 1].");
  add_vertex_noise(tmesh, relative_sigma, np, fname, [fraction](const Flat_mesh& m) {
    return [fraction, normals = area_weighted_vertex_normals(m)](std::size_t v, double sigma, Seeded_gaussian& gaussian,
                                                                 Vec3& d) {
      const bool selected = fraction >= 1. || gaussian.uniform() <= fraction;
      d = (sigma * gaussian()) * normals[v];
      return selected;
    };
  });
}

// Isotropic Gaussian noise (see add_isotropic_gaussian_noise()): each vertex
// moves by a vector of three independent Gaussian coordinates of standard
// deviation relative_sigma / sqrt(3) mean edge lengths, so that the RMS
// length of the moves is relative_sigma mean edge lengths, as along normals.
template <typename TriangleMesh, typename NamedParameters>
void add_isotropic_noise(TriangleMesh& tmesh, double relative_sigma, const NamedParameters& np, const char* fname)
{
  if(faces(tmesh).empty())
    return;
  require_non_negative(relative_sigma, fname, "the noise level");
  add_vertex_noise(tmesh, relative_sigma, np, fname, [](const Flat_mesh&) {
    return [](std::size_t, double sigma, Seeded_gaussian& gaussian, Vec3& d) {
      const double x = gaussian(), y = gaussian(), z = gaussian();
      d = (sigma / std::sqrt(3.)) * Vec3{x, y, z};
      return true;
    };
  });
}

// Depth-scan noise (see add_depth_scan_noise()): each vertex moves along the
// ray from a camera to it by the sum of
// - a Gaussian term whose standard deviation grows as the square of the depth
//   (structured-light and time-of-flight sensors: relative_sigma at the depth
//   of the bounding-box centre);
// - a low-frequency term, half of relative_sigma in amplitude: three plane
//   waves of random directions and phases, of wavelength 12 mean edge
//   lengths (the smooth ripples of a depth map's reconstruction);
// - outliers: 2% of the vertices get an extra Gaussian term of four times
//   relative_sigma.
struct Depth_scan_model
{
  static constexpr double camera_distance = 2.; // in bounding-box diagonals from its centre
  static constexpr double low_frequency_amplitude = 0.5;
  static constexpr double wavelength = 12.; // in mean edge lengths
  static constexpr int waves = 3;
  static constexpr double outlier_fraction = 0.02;
  static constexpr double outlier_scale = 4.;
};

template <typename TriangleMesh, typename NamedParameters>
void add_depth_scan_noise_impl(TriangleMesh& tmesh, double relative_sigma, const NamedParameters& np, const char* fname)
{
  using M = Depth_scan_model;
  if(faces(tmesh).empty())
    return;
  require_non_negative(relative_sigma, fname, "the noise level");
  const Mesh_maps<TriangleMesh, NamedParameters> maps(tmesh, np);
  const std::uint64_t seed = parameters::choose_parameter(parameters::get_parameter(np, internal_np::random_seed), 0u);
  Flat_mesh m = maps.flat(tmesh, fname);
  const std::vector<char> fixed = maps.constrained(tmesh);
  const double edge = mean_edge_length(m);
  const double sigma = relative_sigma * edge;
  if(m.points.empty() || !(sigma > 0.))
    return;
  Vec3 lo = m.points[0], hi = m.points[0];
  for(const Vec3& p : m.points)
    for(int c = 0; c < 3; ++c)
    {
      lo[c] = std::min(lo[c], p[c]);
      hi[c] = std::max(hi[c], p[c]);
    }
  const Vec3 centre = 0.5 * (lo + hi);
  const double diagonal = norm(hi - lo);
  Seeded_gaussian gaussian(seed);
  // the camera: a random direction from the centre (seeded), looking at it
  Vec3 axis{gaussian(), gaussian(), gaussian()};
  if(!(squared_norm(axis) > 0.))
    axis = Vec3{0., 0., 1.};
  axis = (1. / norm(axis)) * axis;
  const Vec3 camera = centre + (M::camera_distance * diagonal) * axis;
  const double centre_depth = M::camera_distance * diagonal;
  Vec3 wave_dir[M::waves];
  double phase[M::waves];
  for(int w = 0; w < M::waves; ++w)
  {
    Vec3 d{gaussian(), gaussian(), gaussian()};
    wave_dir[w] = squared_norm(d) > 0. ? (1. / norm(d)) * d : Vec3{1., 0., 0.};
    phase[w] = 6.283185307179586476925286766559 * gaussian.uniform();
  }
  const double k = 6.283185307179586476925286766559 / (M::wavelength * edge);
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
  {
    // draw for every vertex, as add_noise_along_normals() does
    const double g = gaussian(), outlier = gaussian();
    const bool is_outlier = gaussian.uniform() <= M::outlier_fraction;
    if(fixed[v])
      continue;
    const Vec3 ray = m.points[v] - camera;
    const double depth = norm(ray);
    if(!(depth > 0.))
      continue;
    const double scale = (depth / centre_depth) * (depth / centre_depth);
    double low = 0.;
    for(int w = 0; w < M::waves; ++w)
      low += std::sin(k * dot(m.points[v] - centre, wave_dir[w]) + phase[w]);
    low *= M::low_frequency_amplitude / std::sqrt(double(M::waves) / 2.); // unit RMS before the amplitude
    const double amount = sigma * (scale * g + low + (is_outlier ? M::outlier_scale * outlier : 0.));
    m.points[v] = m.points[v] + (amount / depth) * ray;
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

  \tparam TriangleMesh a model of `VertexListGraph` and `FaceListGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to make noisy; its vertex points are overwritten
  \param relative_sigma the standard deviation of the displacements, as a multiple of the mean edge length of
                        `tmesh` before the noise is added
  \param np an optional sequence of named parameters among the ones listed below

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

  \tparam TriangleMesh a model of `VertexListGraph` and `FaceListGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to make noisy; its vertex points are overwritten
  \param fraction the probability with which each vertex is chosen, in [0, 1] (1: every vertex)
  \param relative_sigma the standard deviation of the displacement of a chosen vertex, as a multiple of the mean
                        edge length of `tmesh` before the noise is added
  \param np an optional sequence of named parameters among the ones of `add_gaussian_noise()`

  \pre as for `add_gaussian_noise()`, and `fraction` lies in [0, 1].
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void add_impulsive_noise(TriangleMesh& tmesh, double fraction, double relative_sigma,
                         const NamedParameters& np = parameters::default_values())
{
  internal::Denoising::add_noise_along_normals(tmesh, relative_sigma, fraction, np, "add_impulsive_noise()");
}

/*!
  \ingroup PMP_denoising_grp

  \brief isotropic Gaussian noise: every vertex of `tmesh` moves by a random
  vector whose three coordinates are independent Gaussians of standard
  deviation `relative_sigma` / \f$\sqrt{3}\f$ times the mean edge length, in
  a direction that is uniformly distributed.

  The root mean square length of the moves is `relative_sigma` times the mean
  edge length, as with `add_gaussian_noise()`, but only a third of their
  energy is along the normal on average: the rest moves vertices along the
  surface, which scrambles small and thin triangles. Some publications add
  noise this way rather than along the normals. Seeded and reproducible like
  `add_gaussian_noise()`, with the same named parameters.

  \tparam TriangleMesh a model of `VertexListGraph` and `FaceListGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to make noisy; its vertex points are overwritten
  \param relative_sigma the root mean square length of the moves, as a multiple of the mean edge length of `tmesh`
                        before the noise is added
  \param np an optional sequence of named parameters among the ones of `add_gaussian_noise()`

  \pre as for `add_gaussian_noise()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void add_isotropic_gaussian_noise(TriangleMesh& tmesh, double relative_sigma,
                                  const NamedParameters& np = parameters::default_values())
{
  internal::Denoising::add_isotropic_noise(tmesh, relative_sigma, np, "add_isotropic_gaussian_noise()");
}

/*!
  \ingroup PMP_denoising_grp

  \brief simulated depth-scan noise: every vertex of `tmesh` moves along the
  ray from a virtual camera to it, as the depth measured by a range sensor
  errs, rather than along its normal.

  The camera sits at twice the bounding-box diagonal from the box's centre,
  in a direction drawn from the seed. A vertex's displacement is the sum of
  a Gaussian term whose standard deviation is `relative_sigma` times the mean
  edge length at the depth of the box's centre and grows as the square of
  the depth (nearer vertices are less noisy), a low-frequency term (three
  plane waves of random directions, wavelength 12 mean edge lengths,
  amplitude half of that standard deviation), and, on 2% of the vertices, an
  outlier term of four times that standard deviation. Seeded and reproducible
  like `add_gaussian_noise()`, with the same named parameters.

  \tparam TriangleMesh a model of `VertexListGraph` and `FaceListGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to make noisy; its vertex points are overwritten
  \param relative_sigma the standard deviation of the Gaussian term at the depth of the bounding-box centre, as a
                        multiple of the mean edge length of `tmesh` before the noise is added; the low-frequency
                        and outlier terms are proportional to it
  \param np an optional sequence of named parameters among the ones of `add_gaussian_noise()`

  \pre as for `add_gaussian_noise()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void add_depth_scan_noise(TriangleMesh& tmesh, double relative_sigma,
                          const NamedParameters& np = parameters::default_values())
{
  internal::Denoising::add_depth_scan_noise_impl(tmesh, relative_sigma, np, "add_depth_scan_noise()");
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
