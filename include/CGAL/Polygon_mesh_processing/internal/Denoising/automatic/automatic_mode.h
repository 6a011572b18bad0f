// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The automatic mode of intrinsic_denoising() from start to end: the
// selection among the candidates (automatic_selection.h), the sparse-noise
// test, the self-check and its walk over the radii, the second pass, the
// report of all of it, and the run of a setting chosen on a sample of a big
// mesh. The driver (intrinsic_denoiser.h) gives it the candidates' setups
// and the constrained vertices, and writes its result back.

#ifndef CGAL_PMP_INTERNAL_DENOISING_AUTOMATIC_MODE_H
#define CGAL_PMP_INTERNAL_DENOISING_AUTOMATIC_MODE_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_rules.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_selection.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/candidates.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/self_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/sparse_noise.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising_report.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Whether the automatic selection of `r` ran and every candidate stopped by
// its residual correlation within Selection_rules::short_run_iterations
// iterations: what the stopping rule gives both on meshes with little noise
// and on noise correlated from vertex to vertex (depth scans).
inline bool short_selection(const Intrinsic_denoising_report& r)
{
  for(const Intrinsic_candidate_report& c : r.candidates)
    if(!c.stopped_by_correlation || c.iterations > Selection_rules::short_run_iterations)
      return false;
  return !r.candidates.empty();
}

// The options of intrinsic_denoising() that the automatic mode reads.
struct Automatic_mode_options
{
  unsigned int vertex_iterations = 0;
  bool prevent_folds = true;
  bool keep_normals = false; // the last filtered normals are returned too
  Vertex_update vertex_update = Vertex_update::PAPER;
  bool relax = false;         // the result relaxed along the surface
  bool long_run_test = false; // Selection_rules' long-run test when every candidate stops at once
};

// The automatic mode, writing what it does to `report`. A candidate setup
// is made by `make_setup(candidate)` (a Selection_rules::Candidate: kernel
// width and relative radius), on the mesh the caller chose.
template <typename ConcurrencyTag>
class Automatic_mode
{
public:
  Automatic_mode(const Automatic_mode_options& options, Intrinsic_denoising_report& report)
      : options_(options), report_(report)
  {
  }

  // The selection on the mesh whose candidate setups `make_setup` builds
  // (the input or a sample of it), with the vertices flagged in
  // `constrained` (input order) held: runs the candidates of
  // Selection_rules, sharing the paths of each radius, keeps the one chosen
  // and describes all of them in the report. The kept run is then denoised
  // again with only its outliers moving if the noise is sparse, or else
  // checked on a synthetic copy of its result (self_check()) and shortened,
  // lengthened or given another radius if the check says so, and dropped
  // for the input if the second pass says it removed shape. `progress(c, n)`
  // is called after each candidate. `finish`: the result is the one
  // returned (relaxed along the surface if asked), not only the choice of a
  // setting.
  template <typename MakeSetup, typename Progress>
  Candidate_run select(const MakeSetup& make_setup, const std::vector<char>& constrained, const Progress& progress,
                       bool finish)
  {
    Automatic_selection<ConcurrencyTag> selection(options_.vertex_iterations, options_.prevent_folds,
                                                  options_.keep_normals, options_.vertex_update);
    selection.run_candidates(Selection_rules::candidates, Selection_rules::number_of_candidates, make_setup,
                             constrained, progress);
    const std::size_t best = selection.choose();
    std::vector<Candidate_run>& runs = selection.runs();
    report_selection(selection, best);
    report_residual(runs[best].stop_residual);
    if(options_.long_run_test && short_selection(report_))
    {
      Candidate_run long_run = long_run_test(make_setup, selection, constrained);
      if(long_run.iterations > 0)
      {
        if(options_.relax && finish)
          report_.relaxed_vertices = selection.relax(long_run);
        return long_run;
      }
    }
    if(runs[best].iterations == 0)
      return std::move(runs[best]);

    const Selection_rules::Candidate& kept = Selection_rules::candidates[best];
    if(!selection.reuse_paths(kept.relative_radius, constrained)) // the paths of the kept candidate's radius
      selection.setup_paths(make_setup(kept), constrained);
    const Intrinsic_kernel kernel = selection.kernel_of_width(kept.sigma);
    // Sparse noise (sparse_noise.h): if the kept result's residual says that
    // only a few vertices were noisy, those alone are denoised, from the
    // input, with the kept kernel, radius and number of iterations.
    const Sparse_noise_test test = selection.test_sparse_noise(runs[best]);
    report_.inlier_residual_correlation = test.inlier_correlation;
    if(test.sparse)
    {
      Candidate_run outliers_only = selection.run_outliers_only(kernel, report_.iterations, test.outlier);
      report_.outlier_vertices = test.outliers;
      report_.displacement = outliers_only.trajectory.back().rms;
      if(options_.relax && finish)
        report_.relaxed_vertices = selection.relax(outliers_only, test.outlier);
      return outliers_only;
    }
    Candidate_run result = self_check(make_setup, selection, std::move(runs[best]), kept, kernel, constrained);
    // The second pass (Selection_rules::second_pass_share): if the kept
    // kernel changes its own short run's result by more than half as much
    // as that run changed the input, what the run removed was mostly shape,
    // and the input is kept.
    if(result.iterations > 0 && result.iterations <= Selection_rules::second_pass_max_iterations)
    {
      const std::pair<double, double> angles = selection.second_pass_angles(result, kernel);
      report_.change_angle = angles.first;
      report_.second_pass_angle = angles.second;
      if(angles.second > Selection_rules::second_pass_share * angles.first)
      {
        report_.iterations = 0;
        report_.stop_reason = Intrinsic_stop_reason::SECOND_PASS;
        report_.displacement = 0.;
        return selection.run_from_input(kernel, 0);
      }
    }
    if(options_.relax && finish)
      report_.relaxed_vertices = selection.relax(result);
    return result;
  }

  // The setting the report holds (kernel, radius, at least one iteration:
  // chosen on a sample) run from the input on the mesh whose setups
  // `make_setup` builds (the whole mesh), and relaxed along the surface if
  // asked.
  template <typename MakeSetup>
  Candidate_run run_chosen_setting(const MakeSetup& make_setup, const std::vector<char>& constrained)
  {
    const double sigma = report_.sigma_range, radius = report_.relative_neighbor_radius;
    const unsigned int k = report_.iterations;
    CGAL_precondition(k > 0);
    Automatic_selection<ConcurrencyTag> selection(options_.vertex_iterations, options_.prevent_folds,
                                                  options_.keep_normals, options_.vertex_update);
    selection.setup_paths(make_setup(Selection_rules::Candidate{sigma, radius}), constrained);
    Candidate_run result = selection.run_from_input(selection.kernel_of_width(sigma), k);
    report_.mean_edge_length = selection.mean_edge_length_of_input();
    report_.neighbor_radius = radius * selection.centroid_distance();
    report_.displacement = result.trajectory[k - 1].rms;
    if(options_.relax)
      report_.relaxed_vertices = selection.relax(result);
    return result;
  }

private:
  // The self-check of the kept run `run` (candidate `kept`, of kernel
  // `kernel`, on the current paths of `selection`): the kept kernel runs on a synthetic copy of its
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
  template <typename MakeSetup>
  Candidate_run self_check(const MakeSetup& make_setup, Automatic_selection<ConcurrencyTag>& selection,
                           Candidate_run&& run, const Selection_rules::Candidate& kept, const Intrinsic_kernel& kernel,
                           const std::vector<char>& constrained)
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
    std::vector<std::vector<double>> first_errors = selection.self_check_errors(run, kernel, copy, first, true);
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
                : std::move(selection.self_check_errors(run, kernel, copy, std::vector<double>(1, r), false)[0]);
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
      selection.setup_paths(make_setup(Selection_rules::Candidate{kept.sigma, radius}), constrained);
    const unsigned int k = self_check_iterations(errors, run.iterations);
    report_.self_check_errors = std::move(errors);
    const bool same_radius = radius == run.relative_radius;
    if(same_radius && k == run.iterations)
      return std::move(run);
    Candidate_run changed = !same_radius         ? selection.run_from_input(kernel, k)
                            : k > run.iterations ? selection.run_on(std::move(run), kernel, k - run.iterations)
                                                 : selection.run_again(kernel, k);
    report_.iterations = k;
    report_.stop_reason = Intrinsic_stop_reason::SELF_CHECK;
    report_.displacement = k > 0 ? changed.trajectory[k - 1].rms : 0.;
    report_.relative_neighbor_radius = radius;
    report_.neighbor_radius = radius * selection.centroid_distance();
    return changed;
  }

  // The long-run test of Selection_rules: the long-run candidate from the
  // input for Selection_rules::long_run_iterations iterations on the paths
  // of its radius; returned (and reported) if its first iteration made at
  // least Selection_rules::long_run_first_share of the whole run's turn of
  // the face normals, else a run of no iteration (the share is reported
  // either way).
  template <typename MakeSetup>
  Candidate_run long_run_test(const MakeSetup& make_setup, Automatic_selection<ConcurrencyTag>& selection,
                              const std::vector<char>& constrained)
  {
    const Selection_rules::Candidate& c = Selection_rules::long_run_candidate;
    if(!selection.reuse_paths(c.relative_radius, constrained))
      selection.setup_paths(make_setup(c), constrained);
    const Intrinsic_kernel kernel = selection.kernel_of_width(c.sigma);
    Candidate_run first = selection.run_from_input(kernel, 1);
    const double first_turn = selection.turn_from_input(first);
    Candidate_run run = selection.run_on(std::move(first), kernel, Selection_rules::long_run_iterations - 1);
    const double turn = selection.turn_from_input(run);
    report_.long_run_first_share = turn > 0. ? first_turn / turn : 0.;
    if(!(report_.long_run_first_share >= Selection_rules::long_run_first_share))
      return Candidate_run();
    report_.sigma_spatial = report_.sigma_range = c.sigma;
    report_.relative_neighbor_radius = c.relative_radius;
    report_.neighbor_radius = c.relative_radius * selection.centroid_distance();
    report_.iterations = report_.maximum_iterations = run.iterations;
    report_.stop_reason = Intrinsic_stop_reason::LONG_RUN;
    report_.displacement = run.trajectory.back().rms;
    return run;
  }

  // The residual's description (residual_description.h) in the report.
  void report_residual(const Residual_description& d)
  {
    report_.residual_hop_correlations = d.hop_correlations;
    report_.residual_correlation_length = d.correlation_length;
    report_.residual_axis_share = d.axis_share;
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
    report_.vertex_iterations = options_.vertex_iterations;
    report_.vertex_update = options_.vertex_update;
    report_.maximum_iterations = Selection_rules::max_iterations;
    report_.iterations = w.iterations;
    report_.stop_reason =
        w.stopped_by_correlation ? Intrinsic_stop_reason::RESIDUAL_CORRELATED : Intrinsic_stop_reason::ITERATION_LIMIT;
  }

  Automatic_mode_options options_;
  Intrinsic_denoising_report& report_;
};

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
