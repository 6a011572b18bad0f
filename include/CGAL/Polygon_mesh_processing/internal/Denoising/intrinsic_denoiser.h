// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The driver of intrinsic_denoising() (Algorithm 1): reads the options once,
// then either runs the automatic selection (automatic_selection.h; on a
// sample of a big mesh, selection_sample.h) or one
// denoising with the parameters given and automatic defaults for the others,
// ended by the stopping rule if it is on; the result goes back to the mesh
// in one write.

#ifndef CGAL_PMP_INTERNAL_DENOISING_INTRINSIC_DENOISER_H
#define CGAL_PMP_INTERNAL_DENOISING_INTRINSIC_DENOISER_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic_selection.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter_iterations.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh_access.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/named_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/selection_sample.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertex_update.h>
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

  // Reads and checks the options; `tmesh` must have a face.
  Intrinsic_denoiser(const TriangleMesh& tmesh, const NamedParameters& np) : tmesh_(tmesh), np_(np), maps_(tmesh, np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    report_.automatic_parameters = choose_parameter(get_parameter(np, internal_np::automatic_parameters), true);
    stop_rule_ = choose_parameter(get_parameter(np, internal_np::stop_when_converged),
                                  report_.automatic_parameters && !given<internal_np::number_of_iterations_t>);
    given_noise_ = choose_parameter(get_parameter(np, internal_np::noise_level), -1.);
    if constexpr(given<internal_np::noise_level_t>)
      require_non_negative(given_noise_, fname, "noise_level");
    vertex_iterations_ =
        choose_parameter(get_parameter(np, internal_np::vertex_iterations), Intrinsic_defaults::vertex_iterations);
    vertex_update_ = choose_parameter(get_parameter(np, internal_np::vertex_update), Vertex_update::PAPER);
    prevent_folds_ = choose_parameter(get_parameter(np, internal_np::prevent_folds), true);
    relax_ = choose_parameter(get_parameter(np, internal_np::relax_along_surface), uses_automatic_selection());
  }

  // Whether the automatic selection runs: only when the kernel, the radius,
  // the number of iterations and the noise level are all left to the
  // automatic mode.
  bool uses_automatic_selection() const
  {
    constexpr bool kernel_or_radius_given = given<internal_np::sigma_spatial_t> || given<internal_np::sigma_range_t> ||
                                            given<internal_np::neighbor_radius_t> ||
                                            given<internal_np::relative_neighbor_radius_t>;
    return report_.automatic_parameters && stop_rule_ && !given<internal_np::number_of_iterations_t> &&
           !kernel_or_radius_given && given_noise_ < 0.;
  }

  // The automatic selection: runs the candidates of Selection_rules, sharing
  // the paths of each radius, keeps the one chosen and describes all of them
  // in the report. The kept run is then denoised again with only its
  // outliers moving if the noise is sparse, or else checked on a synthetic
  // copy of its result and shortened or lengthened if the check says so.
  // On a big mesh (Sample_rules) all of this runs on a sample of patches,
  // and the setting chosen once on the whole mesh.
  Candidate_run select_automatically()
  {
    const std::size_t sample_faces = parameters::choose_parameter(
        parameters::get_parameter(np_, internal_np::selection_sample_faces), Sample_rules::faces);
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
        tmesh_, np_, maps_, fname, [this](const Flat_mesh& mesh) { return defaults_for(mesh); });
    const unsigned int iterations = report_setup(s);
    const auto progress = progress_callback();

    // the vertex update reads the vertices of nearby faces: number them as the
    // (Morton-ordered) faces use them; the points go back in input order
    if(!s.mesh.input_face.empty())
      reorder_vertices_for_locality(s.mesh);
    const std::vector<char> fixed = s.mesh.vertex_values_from_input_order(maps_.constrained(tmesh_));
    Fold_safeguard guard;
    guard.enabled = prevent_folds_;
    Least_squares_recovery recovery = make_vertex_recovery(vertex_update_);
    const std::vector<Vec3> input_normals = guard.enabled ? s.input_faces.normals : std::vector<Vec3>();
    guard.reference = &input_normals;

    std::vector<Vec3>& points = s.mesh.points;
    const std::vector<Vec3> input_points = stop_rule_ || relax_ ? points : std::vector<Vec3>();
    std::vector<Vec3> previous, last_filtered;
    report_.stop_reason = Intrinsic_stop_reason::ITERATION_LIMIT;
    iterate_filter<ConcurrencyTag>(
        s, s.kernel, std::move(s.input_faces), points, fixed, vertex_iterations_, guard, iterations,
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

  auto progress_callback() const
  {
    return parameters::choose_parameter(parameters::get_parameter(np_, internal_np::progress_callback), No_progress());
  }

  // The selection on the mesh that `maps` gives (the input or a sample of
  // it); `finish`: the result is the one returned (relaxed along the surface
  // if asked), not only the choice of a setting.
  template <typename Maps>
  Candidate_run select_on(const Maps& maps, bool finish)
  {
    Automatic_selection<ConcurrencyTag> selection(vertex_iterations_, prevent_folds_, keep_normals, vertex_update_);
    const std::vector<char> constrained = maps.constrained(tmesh_);
    selection.run_candidates(
        Selection_rules::candidates, Selection_rules::number_of_candidates,
        [this, &maps](const Selection_rules::Candidate& candidate) { return candidate_setup(maps, candidate); },
        constrained, progress_callback());
    const std::size_t best = selection.choose();
    std::vector<Candidate_run>& runs = selection.runs();
    report_selection(selection, best);
    if(runs[best].iterations == 0)
      return std::move(runs[best]);

    const Selection_rules::Candidate& kept = Selection_rules::candidates[best];
    if(!selection.reuse_paths(kept.relative_radius, constrained)) // the paths of the kept candidate's radius
      selection.setup_paths(candidate_setup(maps, kept), constrained);
    // Sparse noise (sparse_noise.h): if the kept result's residual says that
    // only a few vertices were noisy, those alone are denoised, from the
    // input, with the kept kernel, radius and number of iterations.
    const Sparse_noise_test test = selection.test_sparse_noise(runs[best]);
    report_.inlier_residual_correlation = test.inlier_correlation;
    if(test.sparse)
    {
      Candidate_run outliers_only = selection.run_outliers_only(kept.sigma, report_.iterations, test.outlier);
      report_.outlier_vertices = test.outliers;
      report_.displacement = outliers_only.trajectory.back().rms;
      if(relax_ && finish)
        report_.relaxed_vertices = selection.relax(outliers_only, test.outlier);
      return outliers_only;
    }
    Candidate_run result = self_check(maps, selection, std::move(runs[best]), kept, constrained);
    // The second pass (Selection_rules::second_pass_share): if the kept
    // kernel changes its own short run's result by more than half as much
    // as that run changed the input, what the run removed was mostly shape,
    // and the input is kept.
    if(result.iterations > 0 && result.iterations <= Selection_rules::second_pass_max_iterations)
    {
      const std::pair<double, double> angles = selection.second_pass_angles(result, kept.sigma);
      report_.change_angle = angles.first;
      report_.second_pass_angle = angles.second;
      if(angles.second > Selection_rules::second_pass_share * angles.first)
      {
        report_.iterations = 0;
        report_.stop_reason = Intrinsic_stop_reason::SECOND_PASS;
        report_.displacement = 0.;
        return selection.run_from_input(kept.sigma, 0);
      }
    }
    if(relax_ && finish)
      report_.relaxed_vertices = selection.relax(result);
    return result;
  }

  // The setting the report holds (kernel, radius, iterations: chosen on a
  // sample) run from the input on the whole mesh, and relaxed along the
  // surface if asked; with no iteration, the input.
  Candidate_run run_chosen_setting()
  {
    const double sigma = report_.sigma_range, radius = report_.relative_neighbor_radius;
    const unsigned int k = report_.iterations;
    if(k == 0)
    {
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
    Automatic_selection<ConcurrencyTag> selection(vertex_iterations_, prevent_folds_, keep_normals, vertex_update_);
    const std::vector<char> constrained = maps_.constrained(tmesh_);
    selection.setup_paths(candidate_setup(maps_, {sigma, radius}), constrained);
    Candidate_run result = selection.run_from_input(sigma, k);
    report_.mean_edge_length = selection.mean_edge_length_of_input();
    report_.neighbor_radius = radius * selection.centroid_distance();
    report_.displacement = result.trajectory[k - 1].rms;
    if(relax_)
      report_.relaxed_vertices = selection.relax(result);
    return result;
  }

  // The paths of a candidate of the automatic selection on the mesh that
  // `maps` gives.
  template <typename Maps>
  Intrinsic_setup candidate_setup(const Maps& maps, const Selection_rules::Candidate& candidate) const
  {
    Setup_defaults defaults;
    defaults.sigma_spatial = defaults.sigma_range = candidate.sigma;
    defaults.relative_radius = candidate.relative_radius;
    return make_intrinsic_setup<ConcurrencyTag>(tmesh_, np_, maps, fname,
                                                [&defaults](const Flat_mesh&) { return defaults; });
  }

  // The self-check of the kept run `run` (candidate `kept`, on the current
  // paths of `selection`): the kept kernel runs on a synthetic copy of its
  // result on the paths of the candidate's radius, then on those of the
  // other radii still held, walking from the candidate's radius towards
  // larger radii and towards smaller ones; a walk stops at the first radius
  // that does not bring the copy closer than the best so far, as the copy's
  // error is taken to have one minimum over the radius (too small a support
  // leaves noise, too large a one removes shape). The candidate's radius and
  // the nearest on either side, always checked, run together. A radius other
  // than the candidate's is taken if the copy came more than
  // Selection_rules::self_check_tolerance closer to the result with it;
  // then, or if another number of iterations recovered the copy better, the
  // run is redone from the input (or, with the candidate's radius and more
  // iterations, goes on from its result).
  template <typename Maps>
  Candidate_run self_check(const Maps& maps, Automatic_selection<ConcurrencyTag>& selection, Candidate_run&& run,
                           const Selection_rules::Candidate& kept, const std::vector<char>& constrained)
  {
    const std::vector<Vec3> copy = selection.synthetic_copy(run);
    std::vector<double> radii = selection.held_radii(); // the candidate's among them: its paths are current
    std::sort(radii.begin(), radii.end());
    const auto own = std::find_if(radii.begin(), radii.end(),
                                  [&run](double r) { return same_relative_radius(r, run.relative_radius); });
    CGAL_assertion(own != radii.end());
    const std::ptrdiff_t start = own - radii.begin(), count = std::ptrdiff_t(radii.size());
    std::vector<double> first(1, run.relative_radius);
    if(start + 1 < count)
      first.push_back(radii[std::size_t(start + 1)]);
    if(start >= 1)
      first.push_back(radii[std::size_t(start - 1)]);
    std::vector<std::vector<double>> first_errors = selection.self_check_errors(run, kept.sigma, copy, first, true);
    std::vector<double> errors = std::move(first_errors[0]);
    const auto smallest = [](const std::vector<double>& e) { return *std::min_element(e.begin(), e.end()); };
    report_.maximum_iterations = Selection_rules::self_check_max_iterations;
    report_.self_check_radii.assign(1, run.relative_radius);
    report_.self_check_smallest_errors.assign(1, smallest(errors));
    double radius = run.relative_radius;
    double limit = smallest(errors) * (1. - Selection_rules::self_check_tolerance);
    std::size_t next = 1; // of first_errors
    for(std::ptrdiff_t step : {std::ptrdiff_t(1), std::ptrdiff_t(-1)})
      for(std::ptrdiff_t i = start + step; i >= 0 && i < count; i += step)
      {
        const double r = radii[std::size_t(i)];
        std::vector<double> e =
            i == start + step
                ? std::move(first_errors[next++])
                : std::move(selection.self_check_errors(run, kept.sigma, copy, std::vector<double>(1, r), false)[0]);
        const double e_min = smallest(e);
        report_.self_check_radii.push_back(r);
        report_.self_check_smallest_errors.push_back(e_min);
        if(!(e_min < limit))
          break; // the error rises from here on in this direction
        limit = e_min;
        radius = r;
        errors = std::move(e);
      }
    if(!selection.reuse_paths(radius, constrained))
      selection.setup_paths(candidate_setup(maps, {kept.sigma, radius}), constrained);
    const unsigned int k = self_check_iterations(errors, run.iterations);
    report_.self_check_errors = std::move(errors);
    const bool same_radius = radius == run.relative_radius;
    if(same_radius && k == run.iterations)
      return std::move(run);
    Candidate_run changed = !same_radius         ? selection.run_from_input(kept.sigma, k)
                            : k > run.iterations ? selection.run_on(std::move(run), kept.sigma, k - run.iterations)
                                                 : selection.run_again(kept.sigma, k);
    report_.iterations = k;
    report_.stop_reason = Intrinsic_stop_reason::SELF_CHECK;
    report_.displacement = k > 0 ? changed.trajectory[k - 1].rms : 0.;
    report_.relative_neighbor_radius = radius;
    report_.neighbor_radius = radius * selection.centroid_distance();
    return changed;
  }

  // Describes the candidates and the one kept (`best`) in the report.
  void report_selection(const Automatic_selection<ConcurrencyTag>& selection, std::size_t best)
  {
    report_.candidates.clear();
    for(const Candidate_run& r : selection.runs())
    {
      Intrinsic_candidate_report c;
      c.sigma = r.sigma;
      c.relative_neighbor_radius = r.relative_radius;
      c.iterations = r.iterations;
      c.stopped_by_correlation = r.stopped_by_correlation;
      c.residual_rms = r.iterations > 0 ? r.trajectory[r.iterations - 1].rms : 0.;
      c.residual_correlation = r.iterations > 0 ? r.trajectory[r.iterations - 1].correlation : 0.;
      c.flat_share = r.flat_share;
      c.score = r.score;
      report_.candidates.push_back(c);
    }
    report_.chosen_candidate = best;
    const Intrinsic_candidate_report& w = report_.candidates[best];
    report_.mean_edge_length = selection.mean_edge_length_of_input();
    report_.noise_level = w.residual_rms;
    report_.noise_level_estimated = true;
    report_.displacement = w.residual_rms;
    report_.sigma_spatial = report_.sigma_range = w.sigma;
    report_.relative_neighbor_radius = w.relative_neighbor_radius;
    report_.neighbor_radius = w.relative_neighbor_radius * selection.centroid_distance();
    report_.vertex_iterations = vertex_iterations_;
    report_.vertex_update = vertex_update_;
    report_.maximum_iterations = Selection_rules::max_iterations;
    report_.iterations = w.iterations;
    report_.stop_reason =
        w.stopped_by_correlation ? Intrinsic_stop_reason::RESIDUAL_CORRELATED : Intrinsic_stop_reason::ITERATION_LIMIT;
  }

  // The defaults of the parameters not given, from the noise level of `mesh`
  // (the input), which is estimated unless given; the noise level is needed
  // by the automatic parameters and by the stopping rule.
  Setup_defaults defaults_for(const Flat_mesh& mesh)
  {
    const bool need_noise = report_.automatic_parameters || stop_rule_;
    if(need_noise && given_noise_ < 0.)
    {
      // the estimate measures the mean edge length too
      const Noise_estimate estimate = estimate_noise<ConcurrencyTag>(mesh);
      report_.mean_edge_length = estimate.mean_edge_length;
      report_.noise_level = estimate.relative_noise;
    }
    else
    {
      report_.mean_edge_length = mean_edge_length<ConcurrencyTag>(mesh);
      report_.noise_level = need_noise ? given_noise_ : 0.;
    }
    if(need_noise)
    {
      report_.noise_level_estimated = given_noise_ < 0.;
      choice_ = automatic_choice(report_.noise_level);
    }
    return report_.automatic_parameters ? choice_.kernel : Setup_defaults();
  }

  // Writes the parameters of setup `s` to the report; returns the iteration
  // limit.
  unsigned int report_setup(const Intrinsic_setup& s)
  {
    const unsigned int iterations = parameters::choose_parameter(
        parameters::get_parameter(np_, internal_np::number_of_iterations),
        report_.automatic_parameters ? choice_.max_iterations : Intrinsic_defaults::iterations);
    report_.sigma_spatial = s.kernel.sigma_spatial;
    report_.sigma_range = s.kernel.sigma_range;
    report_.neighbor_radius = s.radius;
    report_.relative_neighbor_radius = s.centroid_distance > 0. ? s.radius / s.centroid_distance : 0.;
    report_.vertex_iterations = vertex_iterations_;
    report_.maximum_iterations = iterations;
    report_.displacement = 0.;
    report_.vertex_update = vertex_update_;
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
  Intrinsic_denoising_report report_;
  bool stop_rule_ = false;
  double given_noise_ = -1.;
  unsigned int vertex_iterations_ = 0;
  Vertex_update vertex_update_ = Vertex_update::PAPER;
  bool prevent_folds_ = true;
  bool relax_ = false;
  Automatic_choice choice_;
};

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
