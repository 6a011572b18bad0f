// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The driver of intrinsic_denoising() (Algorithm 1): reads the options once,
// then either hands the mesh to the automatic mode (automatic/
// automatic_mode.h; on a big mesh it chooses on a sample of patches,
// automatic/selection_sample.h, and runs the setting chosen on the whole
// mesh) or runs one denoising with the parameters given and automatic
// defaults for the others, ended by the stopping rule if it is on; the
// result goes back to the mesh in one write.

#ifndef CGAL_PMP_INTERNAL_DENOISING_INTRINSIC_DENOISER_H
#define CGAL_PMP_INTERNAL_DENOISING_INTRINSIC_DENOISER_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_mode.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/selection_sample.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/named_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_iterations.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/intrinsic_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/mesh_access.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising_report.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters>
class Intrinsic_denoiser
{
  typedef parameters::Default_named_parameters Defaults;
  template <typename Tag>
  static constexpr bool given = !parameters::is_default_parameter<NamedParameters, Tag>::value;

public:
  static constexpr bool keep_normals = given<internal_np::face_normal_t>;

  // Checks the options `o`; `tmesh` must have a face. `np` gives the maps
  // (points, constrained vertices, the face normals returned) and the
  // progress callback.
  Intrinsic_denoiser(const TriangleMesh& tmesh, const Intrinsic_options& o, const NamedParameters& np)
      : tmesh_(tmesh), np_(np), maps_(tmesh, np), o_(o)
  {
    report_.automatic_parameters = o.automatic_parameters;
    stop_rule_ = stops_when_converged(o);
    if(o.noise_level)
      require_non_negative(*o.noise_level, fname, "noise_level");
    relax_ = relaxes_along_surface(o);
  }

  // Whether the automatic selection runs (see Denoising::uses_automatic_selection()).
  bool uses_automatic_selection() const { return Denoising::uses_automatic_selection(o_); }

  // The automatic selection: runs the candidates of Selection_rules, sharing
  // the paths of each radius, keeps the one chosen and describes all of them
  // in the report. The kept run is then denoised again with only its
  // outliers moving if the noise is sparse, or else checked on a synthetic
  // copy of its result and shortened or lengthened if the check says so.
  // On a big mesh (Sample_rules) all of this runs on a sample of patches,
  // and the setting chosen once on the whole mesh.
  Candidate_run select_automatically()
  {
    const std::size_t sample_faces = o_.selection_sample_faces;
    // sampled if nf > min_ratio * sample_faces, written so as not to overflow (nf >= 1)
    const std::size_t nf = std::size_t(num_faces(tmesh_));
    if(sample_faces == 0 || sample_faces > (nf - 1) / Sample_rules::min_ratio)
      return select_on(maps_, true);
    Selection_sample sample;
    {
      const Flat_mesh whole = maps_.flat(tmesh_, fname);
      sample = sample_patches(whole, maps_.constrained(tmesh_), sample_faces,
                              std::max<std::size_t>(1, sample_faces / Sample_rules::patches));
    }
    select_on(Sample_maps{&sample}, false);
    if(report_.outlier_vertices == 0)
    {
      report_.selection_sample_faces = sample.mesh.number_of_faces();
      report_.selection_sample_patches = sample.patches;
      return run_chosen_setting();
    }
    const bool automatic = report_.automatic_parameters; // sparse noise: the outliers are found on the whole mesh
    report_ = Intrinsic_denoising_report();
    report_.automatic_parameters = automatic;
    return select_on(maps_, true);
  }

  // One denoising from the input with the parameters given and, for the
  // others, the defaults of defaults_for(); ended by the stopping rule if it
  // is on (not tested before Automatic_rules::min_iterations unless there is
  // no noise). The report describes it.
  Candidate_run run_with_rules()
  {
    Intrinsic_setup s = make_intrinsic_setup<ConcurrencyTag>(
        tmesh_, o_.filter, maps_, fname, [this](const Flat_mesh& mesh) { return defaults_for(mesh); });
    const unsigned int iterations = report_setup(s);
    const auto progress = progress_callback();

    // the vertex update reads the vertices of nearby faces: number them as the
    // (Morton-ordered) faces use them; the points go back in input order
    if(!s.mesh.input_face.empty())
      reorder_vertices_for_locality(s.mesh);
    const std::vector<char> fixed = s.mesh.vertex_values_from_input_order(maps_.constrained(tmesh_));
    Fold_safeguard guard;
    guard.enabled = o_.prevent_folds;
    Least_squares_recovery recovery = make_vertex_recovery(o_.vertex_update);
    const std::vector<Vec3> input_normals = guard.enabled ? s.input_faces.normals : std::vector<Vec3>();
    guard.reference = &input_normals;

    std::vector<Vec3>& points = s.mesh.points;
    const std::vector<Vec3> input_points = stop_rule_ || relax_ ? points : std::vector<Vec3>();
    std::vector<Vec3> previous, last_filtered;
    report_.stop_reason = Intrinsic_stop_reason::ITERATION_LIMIT;
    iterate_filter<ConcurrencyTag>(
        s, s.kernel, std::move(s.input_faces), points, fixed, o_.vertex_iterations, guard, iterations,
        [&](unsigned int k, const std::vector<Vec3>& p, std::vector<Vec3>& filtered) {
          report_.iterations = k;
          progress(std::size_t(k), std::size_t(iterations));
          const bool go_on = !(stop_rule_ && k < iterations && stops(s.mesh, p, input_points, filtered, previous, k));
          if(keep_normals && (!go_on || k == iterations))
            last_filtered = filtered;
          if(go_on && stop_rule_)
            previous.swap(filtered); // the next pass overwrites all of `filtered`
          return go_on;
        },
        &recovery);
    if(stop_rule_)
      report_.displacement = relative_rms_displacement(s.mesh, points, input_points, report_.mean_edge_length);
    if(relax_)
      report_.relaxed_vertices = relax_tangentially<ConcurrencyTag>(s.mesh, input_points, points, fixed, guard);
    Candidate_run r;
    r.points = s.mesh.vertex_values_in_input_order(points);
    if constexpr(keep_normals)
    {
      if(last_filtered.empty()) // no iteration ran: nothing filtered, the input's face normals
      {
        Face_data input_faces;
        compute_face_data<ConcurrencyTag>(s.mesh, points, input_faces);
        last_filtered = std::move(input_faces.normals);
      }
      r.normals = s.mesh.in_input_order(last_filtered);
    }
    return r;
  }

  // Writes the result's points (and its filtered normals, if asked) to `tmesh`.
  void write_result(TriangleMesh& tmesh, const Candidate_run& result) const
  {
    maps_.write_points(tmesh, result.points);
    if constexpr(keep_normals)
      maps_.write_face_vectors(tmesh, result.normals, parameters::get_parameter(np_, internal_np::face_normal));
  }

  const Intrinsic_denoising_report& report() const { return report_; }

private:
  static constexpr const char* fname = "intrinsic_denoising()";

  // The selection of the automatic mode on the mesh that `maps` gives (the
  // input or a sample of it); `finish`: see Automatic_mode::select().
  template <typename Maps>
  Candidate_run select_on(const Maps& maps, bool finish)
  {
    Automatic_mode<ConcurrencyTag> mode(automatic_mode_options(), report_);
    return mode.select([this, &maps](const Selection_rules::Candidate& c) { return candidate_setup(maps, c); },
                       maps.constrained(tmesh_), progress_callback(), finish);
  }

  // The setting the report holds (kernel, radius, iterations: chosen on a
  // sample) run from the input on the whole mesh, and relaxed along the
  // surface if asked; with no iteration, the input.
  Candidate_run run_chosen_setting()
  {
    if(report_.iterations > 0)
    {
      Automatic_mode<ConcurrencyTag> mode(automatic_mode_options(), report_);
      return mode.run_chosen_setting([this](const Selection_rules::Candidate& c) { return candidate_setup(maps_, c); },
                                     maps_.constrained(tmesh_));
    }
    Candidate_run input;
    const Flat_mesh m = maps_.flat(tmesh_, fname);
    report_.mean_edge_length = mean_edge_length<ConcurrencyTag>(m);
    input.points = m.points;
    if constexpr(keep_normals)
    {
      Face_data faces;
      compute_face_data<ConcurrencyTag>(m, m.points, faces);
      input.normals = std::move(faces.normals);
    }
    return input;
  }

  Automatic_mode_options automatic_mode_options() const
  {
    Automatic_mode_options o;
    o.vertex_iterations = o_.vertex_iterations;
    o.prevent_folds = o_.prevent_folds;
    o.keep_normals = keep_normals;
    o.vertex_update = o_.vertex_update;
    o.relax = relax_;
    o.long_run_test = o_.long_run_test;
    return o;
  }

  auto progress_callback() const
  {
    return parameters::choose_parameter(parameters::get_parameter(np_, internal_np::progress_callback), No_progress());
  }

  // The paths of a candidate of the automatic selection on the mesh that
  // `maps` gives.
  template <typename Maps>
  Intrinsic_setup candidate_setup(const Maps& maps, const Selection_rules::Candidate& candidate) const
  {
    Setup_defaults defaults;
    defaults.sigma_spatial = defaults.sigma_range = candidate.sigma;
    defaults.relative_radius = candidate.relative_radius;
    return make_intrinsic_setup<ConcurrencyTag>(tmesh_, o_.filter, maps, fname,
                                                [&defaults](const Flat_mesh&) { return defaults; });
  }

  // The defaults of the parameters not given, from the noise level of `mesh`
  // (the input), which is estimated unless given; the noise level is needed
  // by the automatic parameters and by the stopping rule.
  Setup_defaults defaults_for(const Flat_mesh& mesh)
  {
    const bool need_noise = report_.automatic_parameters || stop_rule_;
    if(need_noise && !o_.noise_level)
    {
      // the estimate measures the mean edge length too
      const Noise_estimate estimate = estimate_noise<ConcurrencyTag>(mesh);
      report_.mean_edge_length = estimate.mean_edge_length;
      report_.noise_level = estimate.relative_noise;
    }
    else
    {
      report_.mean_edge_length = mean_edge_length<ConcurrencyTag>(mesh);
      report_.noise_level = need_noise ? *o_.noise_level : 0.;
    }
    if(need_noise)
    {
      report_.noise_level_estimated = !o_.noise_level;
      choice_ = automatic_choice(report_.noise_level);
    }
    return report_.automatic_parameters ? choice_.kernel : Setup_defaults();
  }

  // Writes the parameters of setup `s` to the report; returns the iteration
  // limit.
  unsigned int report_setup(const Intrinsic_setup& s)
  {
    const unsigned int iterations = o_.number_of_iterations.value_or(
        report_.automatic_parameters ? choice_.max_iterations : Intrinsic_defaults::iterations);
    report_.sigma_spatial = s.kernel.sigma_spatial;
    report_.sigma_range = s.kernel.sigma_range;
    report_.neighbor_radius = s.radius;
    report_.relative_neighbor_radius = s.centroid_distance > 0. ? s.radius / s.centroid_distance : 0.;
    report_.vertex_iterations = o_.vertex_iterations;
    report_.maximum_iterations = iterations;
    report_.displacement = 0.;
    report_.vertex_update = o_.vertex_update;
    return iterations;
  }

  // The stopping rule after iteration k (points `p`, filtered normals
  // `filtered`, those of the iteration before `previous`): stop when the
  // vertices have moved by the noise level or the normals no longer change;
  // not before min_iterations unless there is no noise. Sets the stop reason.
  bool stops(const Flat_mesh& mesh, const std::vector<Vec3>& p, const std::vector<Vec3>& input_points,
             const std::vector<Vec3>& filtered, const std::vector<Vec3>& previous, unsigned int k)
  {
    if(k < Automatic_rules::min_iterations && report_.noise_level >= Automatic_rules::min_noise)
      return false;
    report_.displacement = relative_rms_displacement(mesh, p, input_points, report_.mean_edge_length);
    if(report_.displacement >= Automatic_rules::displacement_fraction * report_.noise_level)
    {
      report_.stop_reason = Intrinsic_stop_reason::NOISE_LEVEL_REACHED;
      return true;
    }
    if(!previous.empty() && mean_angle_degrees(filtered, previous) < Automatic_rules::change_tolerance)
    {
      report_.stop_reason = Intrinsic_stop_reason::CONVERGED;
      return true;
    }
    return false;
  }

  const TriangleMesh& tmesh_;
  const NamedParameters& np_;
  const Mesh_maps<TriangleMesh, NamedParameters> maps_;
  const Intrinsic_options o_;
  Intrinsic_denoising_report report_;
  bool stop_rule_ = false;
  bool relax_ = false;
  Automatic_choice choice_;
};

// intrinsic_denoising() with the options `o` (read from its named parameters,
// or set at run time) and the maps and progress callback of `np`.
template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters>
Intrinsic_denoising_report intrinsic_denoising_with_options(TriangleMesh& tmesh, const Intrinsic_options& o,
                                                            const NamedParameters& np)
{
  if(faces(tmesh).empty())
    return Intrinsic_denoising_report();
  Intrinsic_denoiser<ConcurrencyTag, TriangleMesh, NamedParameters> denoiser(tmesh, o, np);
  const Candidate_run result =
      denoiser.uses_automatic_selection() ? denoiser.select_automatically() : denoiser.run_with_rules();
  denoiser.write_result(tmesh, result);
  return denoiser.report();
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
