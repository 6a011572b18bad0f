// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The options of the intrinsic filters as run-time values: kernel, radius
// and paths. The named parameters are read into them once
// (read_filter_options()), and a caller that sets them at run time (the
// command-line tool, the Python module) fills them directly; an option left
// empty takes the default of whoever reads it.

#ifndef CGAL_PMP_INTERNAL_DENOISING_FILTER_OPTIONS_H
#define CGAL_PMP_INTERNAL_DENOISING_FILTER_OPTIONS_H

#include <CGAL/Polygon_mesh_processing/denoising_types.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/input_checks.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/named_parameters.h>

#include <optional>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

struct Filter_options
{
  std::optional<double> sigma_spatial, sigma_range; // default: the caller's (Setup_defaults)
  double spatial_exponent = 1., range_exponent = 1.;
  std::optional<bool> include_self_weight;              // default: the caller's
  std::optional<double> neighbor_radius;                // absolute; replaces the relative radius
  std::optional<double> relative_neighbor_radius;       // in d; default: the caller's
  std::optional<Intrinsic_path_strategy> path_strategy; // default: the caller's
  bool use_step_length = false;
  std::optional<unsigned int> geodesic_patch_rings; // default: Geodesic_path_options'
};

// The options of `np`: only those it holds are set.
template <typename NamedParameters>
Filter_options read_filter_options(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Filter_options o;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::sigma_spatial_t>::value)
    o.sigma_spatial = get_parameter(np, internal_np::sigma_spatial);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::sigma_range_t>::value)
    o.sigma_range = get_parameter(np, internal_np::sigma_range);
  o.spatial_exponent = choose_parameter(get_parameter(np, internal_np::spatial_exponent), 1.);
  o.range_exponent = choose_parameter(get_parameter(np, internal_np::range_exponent), 1.);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::include_self_weight_t>::value)
    o.include_self_weight = get_parameter(np, internal_np::include_self_weight);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::neighbor_radius_t>::value)
    o.neighbor_radius = get_parameter(np, internal_np::neighbor_radius);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::relative_neighbor_radius_t>::value)
    o.relative_neighbor_radius = get_parameter(np, internal_np::relative_neighbor_radius);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::path_strategy_t>::value)
    o.path_strategy = get_parameter(np, internal_np::path_strategy);
  o.use_step_length = choose_parameter(get_parameter(np, internal_np::use_step_length), false);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::geodesic_patch_rings_t>::value)
    o.geodesic_patch_rings = get_parameter(np, internal_np::geodesic_patch_rings);
  return o;
}

// Whether a kernel width or a radius is set: the automatic selection of
// intrinsic_denoising() runs only without them.
inline bool sets_kernel_or_radius(const Filter_options& o)
{
  return o.sigma_spatial || o.sigma_range || o.neighbor_radius || o.relative_neighbor_radius;
}

// The neighbourhood radius: neighbor_radius if set, else
// relative_neighbor_radius (default `default_relative`) times `unit` (the
// mean distance between adjacent items' positions).
inline double filter_radius(const Filter_options& o, const char* fname, double unit, double default_relative)
{
  if(o.neighbor_radius)
  {
    require_positive(*o.neighbor_radius, fname, "neighbor_radius");
    return *o.neighbor_radius;
  }
  const double relative = o.relative_neighbor_radius.value_or(default_relative);
  require_positive(relative, fname, "relative_neighbor_radius");
  return relative * unit;
}

// The same radius read from named parameters (the classic methods').
template <typename NamedParameters>
double read_radius(const NamedParameters& np, const char* fname, double unit, double default_relative)
{
  return filter_radius(read_filter_options(np), fname, unit, default_relative);
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
