// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The options of intrinsic_denoising() as run-time values. The named
// parameters are read into them once (read_intrinsic_options()); the
// command-line tool and the Python module fill them directly and call
// intrinsic_denoising_with_options() (intrinsic_denoiser.h), so that one
// instantiation serves every combination of options. An option left empty is
// left to the automatic mode, as a named parameter not given is.

#ifndef CGAL_PMP_INTERNAL_DENOISING_INTRINSIC_OPTIONS_H
#define CGAL_PMP_INTERNAL_DENOISING_INTRINSIC_OPTIONS_H

#include <CGAL/Polygon_mesh_processing/denoising_types.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_rules.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/named_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/intrinsic_setup.h>

#include <cstddef>
#include <optional>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

struct Intrinsic_options
{
  Filter_options filter; // kernel, radius, paths
  bool automatic_parameters = true;
  std::optional<unsigned int> number_of_iterations;
  std::optional<double> noise_level;
  std::optional<bool> stop_when_converged; // default: on in the automatic mode without number_of_iterations
  std::optional<bool> relax_along_surface; // default: on when the automatic selection runs
  unsigned int vertex_iterations = Intrinsic_defaults::vertex_iterations;
  Vertex_update vertex_update = Vertex_update::PAPER;
  bool prevent_folds = true;
  std::size_t selection_sample_faces = Sample_rules::faces;
  bool long_run_test = false; // Selection_rules' long-run test in the automatic selection
};

// The options of `np`: only those it holds are set.
template <typename NamedParameters>
Intrinsic_options read_intrinsic_options(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Intrinsic_options o;
  o.filter = read_filter_options(np);
  o.automatic_parameters = choose_parameter(get_parameter(np, internal_np::automatic_parameters), true);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::number_of_iterations_t>::value)
    o.number_of_iterations = get_parameter(np, internal_np::number_of_iterations);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::noise_level_t>::value)
    o.noise_level = get_parameter(np, internal_np::noise_level);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::stop_when_converged_t>::value)
    o.stop_when_converged = get_parameter(np, internal_np::stop_when_converged);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::relax_along_surface_t>::value)
    o.relax_along_surface = get_parameter(np, internal_np::relax_along_surface);
  o.vertex_iterations =
      choose_parameter(get_parameter(np, internal_np::vertex_iterations), Intrinsic_defaults::vertex_iterations);
  o.vertex_update = choose_parameter(get_parameter(np, internal_np::vertex_update), Vertex_update::PAPER);
  o.prevent_folds = choose_parameter(get_parameter(np, internal_np::prevent_folds), true);
  o.selection_sample_faces =
      choose_parameter(get_parameter(np, internal_np::selection_sample_faces), Sample_rules::faces);
  o.long_run_test = choose_parameter(get_parameter(np, internal_np::long_run_test), false);
  return o;
}

// Whether stop_when_converged is on: as set, or else in the automatic mode
// unless the number of iterations is set.
inline bool stops_when_converged(const Intrinsic_options& o)
{
  return o.stop_when_converged.value_or(o.automatic_parameters && !o.number_of_iterations);
}

// Whether the automatic selection runs: only when the kernel, the radius,
// the number of iterations and the noise level are all left to the
// automatic mode, with its stopping rule on.
inline bool uses_automatic_selection(const Intrinsic_options& o)
{
  return o.automatic_parameters && stops_when_converged(o) && !o.number_of_iterations &&
         !sets_kernel_or_radius(o.filter) && !o.noise_level;
}

// Whether the result is relaxed along the surface: as set, or else when the
// automatic selection runs.
inline bool relaxes_along_surface(const Intrinsic_options& o)
{
  return o.relax_along_surface.value_or(uses_automatic_selection(o));
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
