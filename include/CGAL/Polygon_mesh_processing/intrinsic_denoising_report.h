// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What intrinsic_denoising() reports: the parameters it used, the noise
// level, the candidates of its automatic selection, why it stopped.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTRINSIC_DENOISING_REPORT_H
#define CGAL_POLYGON_MESH_PROCESSING_INTRINSIC_DENOISING_REPORT_H

#include <CGAL/Polygon_mesh_processing/denoising_types.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_rules.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/// \ingroup PMP_denoising_grp
/// Why `intrinsic_denoising()` stopped iterating.
enum class Intrinsic_stop_reason
{
  /// it ran `maximum_iterations` iterations
  ITERATION_LIMIT,
  /// stopping rule: the RMS vertex displacement from the input reached the
  /// noise level (times `Intrinsic_denoising_report::displacement_fraction`)
  NOISE_LEVEL_REACHED,
  /// stopping rule: the filtered normals changed by less than
  /// `Intrinsic_denoising_report::change_tolerance` degrees on average
  CONVERGED,
  /// the automatic selection: the residual between the input and the result
  /// became correlated across edges (shape, not noise, was being removed)
  RESIDUAL_CORRELATED,
  /// the automatic selection's self-check: on a synthetic noisy copy of the
  /// kept result, fewer or more iterations of the kept kernel, or another
  /// radius, came closer to the result (see
  /// `Intrinsic_denoising_report::self_check_errors` and
  /// `Intrinsic_denoising_report::self_check_radii`)
  SELF_CHECK,
  /// the automatic selection's second pass: the kept kernel, run again from
  /// the result of a short run, changed it by more than half as much as the
  /// run had changed the input, so the run removed mostly shape, not noise;
  /// the input is returned unchanged (see
  /// `Intrinsic_denoising_report::second_pass_angle`)
  SECOND_PASS,
  /// the automatic selection's long-run test (named parameter
  /// `long_run_test`): every candidate stopped at once, and a long run of a wide kernel changed the normals mostly in its
  /// first iteration, as noise correlated between vertices (a depth scan's)
  /// does and shape does not; the long run is the result (see
  /// `Intrinsic_denoising_report::long_run_first_share`)
  LONG_RUN
};

/// \ingroup PMP_denoising_grp
/// One candidate setting of the automatic selection of
/// `intrinsic_denoising()`, and the evidence it was judged on.
struct Intrinsic_candidate_report
{
  /// \f$\sigma_s = \sigma_r\f$ of the candidate
  double sigma = 0.;
  /// its radius relative to \f$d\f$
  double relative_neighbor_radius = 0.;
  /// the iterations it ran (it stopped at the first whose residual correlation
  /// reached the threshold, or at the limit)
  unsigned int iterations = 0;
  /// whether the residual correlation stopped it (`false`: the limit)
  bool stopped_by_correlation = false;
  /// the RMS of the residual (input minus result) at its stop, relative to the
  /// mean edge length
  double residual_rms = 0.;
  /// the residual correlation across edges at its stop
  double residual_correlation = 0.;
  /// the share of the interior edges of its result whose faces differ by less
  /// than 1 degree (-1: no interior edge)
  double flat_share = -1.;
  /// its score: the residual correlation where its residual RMS reached the
  /// common comparison level (the lowest wins, among the candidates whose
  /// `flat_share` is within 0.05 of the largest if that is at least 0.3)
  double score = 0.;
};

/// \ingroup PMP_denoising_grp
/// What `intrinsic_denoising()` did: the parameter values it used (given or
/// chosen automatically), the noise level, and how many iterations it ran.
struct Intrinsic_denoising_report
{
  /// whether the parameters not given were derived from the mesh
  bool automatic_parameters = false;
  /// the noise level, as a standard deviation relative to the mean edge length:
  /// with the automatic selection, the RMS of the kept candidate's residual
  /// (input minus result); otherwise estimated or given (0 if neither the
  /// automatic mode nor the stopping rule needed it)
  double noise_level = 0.;
  /// whether `noise_level` was estimated (`false`: given by the caller)
  bool noise_level_estimated = false;
  /// the mean edge length of the input mesh
  double mean_edge_length = 0.;
  /// \f$\sigma_s\f$ and \f$\sigma_r\f$ used
  double sigma_spatial = 0., sigma_range = 0.;
  /// the neighbourhood radius used, absolute and relative to \f$d\f$
  double neighbor_radius = 0., relative_neighbor_radius = 0.;
  /// \f$v_{iter}\f$ used
  unsigned int vertex_iterations = 0;
  /// the vertex update used
  Vertex_update vertex_update = Vertex_update::PAPER;
  /// the iteration limit, and the iterations run
  unsigned int maximum_iterations = 0, iterations = 0;
  /// why the iterations stopped
  Intrinsic_stop_reason stop_reason = Intrinsic_stop_reason::ITERATION_LIMIT;
  /// with the stopping rule or the automatic selection: the RMS vertex
  /// displacement from the input at the end, relative to the mean edge length
  double displacement = 0.;
  /// with the automatic selection: the correlation across edges of the kept
  /// candidate's residual at the vertices it did not flag as outliers (the
  /// sparse-noise test; 0 if not measured)
  double inlier_residual_correlation = 0.;
  /// with the automatic selection: the number of vertices taken for sparse
  /// (impulsive) noise, which alone were then denoised, all others staying in
  /// place; 0 if the noise was taken for dense (every vertex denoised)
  std::size_t outlier_vertices = 0;
  /// the number of vertices the relaxation along the surface moved after the
  /// last iteration (along the surface only, each by at most half as far as
  /// the denoising moved it; the outliers alone with sparse noise); 0 if it
  /// did not run (see the named parameter `relax_along_surface`)
  std::size_t relaxed_vertices = 0;
  /// with the automatic selection and dense noise, after a kept run of at
  /// most 8 iterations: the mean angle in degrees between the face normals
  /// of the input and those of the run's result (`change_angle`), and
  /// between those of the result and those of the result after as many
  /// iterations again of the kept kernel (`second_pass_angle`). A filter
  /// that removed noise changes its own result little: what it changes there
  /// is what it would take from a noise-free surface, shape. If the second
  /// angle is more than half the first, the input is returned unchanged
  /// (stop reason `Intrinsic_stop_reason::SECOND_PASS`). Both 0 if the
  /// second pass did not run.
  double change_angle = 0., second_pass_angle = 0.;
  /// with the automatic selection and dense noise: the self-check of the kept
  /// candidate. Its result is taken for the noise-free surface and given the
  /// noise it removed (the normal components of the residual, shuffled over
  /// the vertices); entry k is the mean angle in degrees between the face
  /// normals of that synthetic copy after k iterations of the kept kernel and
  /// those of the result (entry 0: the copy itself). The copy runs at least
  /// as many iterations as the candidate did, and on while its angle falls
  /// and stays within 2% of the smallest. If the candidate's entry is more
  /// than 2% above the smallest, the result kept is that of the largest
  /// smaller count within 2% of the smallest, or, if there is none, of the
  /// count of the smallest entry (a longer run); empty
  /// if the check did not run (the kept candidate ran no iteration, or the
  /// noise was sparse)
  std::vector<double> self_check_errors;
  /// with the automatic selection and dense noise: the radii (relative to
  /// \f$d\f$) on which the kept kernel ran on the synthetic copy, the kept
  /// candidate's first, then the candidates' other radii whose paths were
  /// still held (each run to the first iteration that brought the copy no
  /// closer), the larger ones from the candidate's upwards, then the smaller
  /// ones downwards, each walk ending at the first radius whose smallest
  /// angle is not below the best so far; empty if the check did not run
  std::vector<double> self_check_radii;
  /// the smallest angle (degrees) on the copy for each of `self_check_radii`.
  /// A radius other than the candidate's is used if its entry is more than
  /// 2% below the candidate's (the lowest such); `self_check_errors` are then
  /// its angles and `relative_neighbor_radius` says which it is
  std::vector<double> self_check_smallest_errors;
  /// with the automatic selection: why the kept candidate stopped, as the
  /// correlation of its residual (input minus its result) at the stop
  /// between vertices 1 to 8 edges apart (element h - 1: h edges), over
  /// breadth-first searches from up to 2,000 vertices spread over the mesh.
  /// The residual is that of the iteration its stopping rule rejected (the
  /// first whose correlation across edges reached the threshold), or of its
  /// last iteration if it ran to the limit. Independent noise removed leaves
  /// about 0 beyond one edge; shape removed, and the noise of depth scans,
  /// which is correlated from vertex to vertex, leave a residual correlated
  /// over several edges. Descriptive: no rule of the mode reads it
  std::vector<double> residual_hop_correlations;
  /// the number of edges over which `residual_hop_correlations` stays at
  /// least 0.5 (0 to 8)
  unsigned int residual_correlation_length = 0;
  /// the share of the same residual's energy along its principal direction:
  /// 1/3 for a residual spread evenly over the directions, near 1 for one
  /// along a single direction (as the noise of a depth image, along the
  /// viewing rays)
  double residual_axis_share = 0.;
  /// with the automatic selection and the named parameter `long_run_test`,
  /// when every candidate stopped by correlation within 3 iterations: the share of the turn of the face
  /// normals (mean angle from the input's) of a run of 64 iterations of
  /// sigma 0.8 on 6 d that its first iteration made. From 0.5 on the long
  /// run is the result (stop reason `LONG_RUN`): noise is used up early,
  /// shape is eroded steadily. -1 if the test did not run
  double long_run_first_share = -1.;
  /// the number of faces of the sample on which the automatic selection
  /// chose its setting, and of the patches they form (see the named
  /// parameter `selection_sample_faces`); both 0 if it ran on the whole mesh.
  /// The candidates, the self-check and the second pass above are then those
  /// of the sample, and the setting chosen ran once on the whole mesh.
  std::size_t selection_sample_faces = 0, selection_sample_patches = 0;
  /// the candidates of the automatic selection (empty if it did not run:
  /// see `intrinsic_denoising()` for when it does), in the order they ran
  std::vector<Intrinsic_candidate_report> candidates;
  /// the index in `candidates` of the one kept
  std::size_t chosen_candidate = 0;
  /// the constants of the stopping rule
  static constexpr double displacement_fraction = internal::Denoising::Automatic_rules::displacement_fraction;
  static constexpr double change_tolerance = internal::Denoising::Automatic_rules::change_tolerance;
  /// the default of the named parameter `selection_sample_faces`
  static constexpr std::size_t default_selection_sample_faces = internal::Denoising::Sample_rules::faces;
};

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
