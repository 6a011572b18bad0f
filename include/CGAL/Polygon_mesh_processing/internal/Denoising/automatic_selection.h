// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The automatic mode of intrinsic_denoising() when no kernel width, radius or
// number of iterations is given: a few candidate settings of the filter run
// on the input, each stopped by the whiteness of its residual, and the one
// whose residual is the most noise-like is kept; its number of iterations
// can then be changed by a self-check on a synthetic noisy copy of its
// result. Every
// decision is read from the residual between the input and the candidates'
// results (residual_statistics.h), so it needs neither a noise estimate nor
// a classification of the surface.

#ifndef CGAL_PMP_INTERNAL_DENOISING_AUTOMATIC_SELECTION_H
#define CGAL_PMP_INTERNAL_DENOISING_AUTOMATIC_SELECTION_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter_iterations.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/residual_statistics.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/sparse_noise.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertex_update.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// The constants of the selection, measured on the development corpus
// (benchmark/Polygon_mesh_processing/corpus_benchmark.cpp: 64 meshes of
// CGAL's data set, Gaussian, impulsive and simulated depth-scan noise; see
// the user manual for the distributions and for what was tried).
struct Selection_rules
{
  struct Candidate
  {
    double sigma;           // sigma_s = sigma_r
    double relative_radius; // in d
  };
  // From a kernel that keeps sharp edges to one that is almost a Gaussian
  // smoothing of the normals, and a wide support for strong noise on
  // piecewise flat surfaces; the two on 3d share their paths.
  static constexpr Candidate candidates[] = {{0.5, 3.}, {0.8, 3.}, {0.8, 6.}, {1.4, 2.}};
  static constexpr std::size_t number_of_candidates = sizeof(candidates) / sizeof(candidates[0]);
  // A candidate stops before the first iteration whose residual correlation
  // across edges reaches this value. Independent noise removed gives a
  // correlation slightly below 0 (the residual is the noise less a low-pass
  // of it); shape removed pushes it up. On the corpus the E_n-best iteration
  // of a setting sits at a correlation of -0.03 to -0.07.
  static constexpr double stop_correlation = -0.05;
  // At most this many iterations per candidate. On the corpus, 60 instead
  // would lower the best candidate's E_n little (90th percentile of its ratio
  // to the oracle on the regular meshes 1.26 against 1.33, median the same)
  // for half as much time again on the slowest inputs.
  static constexpr unsigned int max_iterations = 40;
  // The candidates are compared where each has removed the same amount: this
  // fraction of the smallest residual RMS at which a candidate stopped. At
  // equal RMS removed, a lower correlation means more noise and less shape.
  static constexpr double comparison_fraction = 0.5;
  // Piecewise flat evidence: the share of interior edges of a candidate's
  // result whose faces differ by less than flat_angle degrees. Noise leaves
  // no edge that flat, and a curved surface few (0.04 to 0.25 on the
  // corpus's organic meshes, whatever the candidate); a CAD surface
  // denoised by a kernel that keeps its edges many (0.33 to 0.93). When the
  // largest share reaches min_flat_share, only the candidates within
  // flat_share_margin of it are compared: on such a surface a wide kernel
  // removes the noise fastest but rounds the edges, which the correlation
  // sees too late.
  static constexpr double flat_angle = 1.;
  static constexpr double min_flat_share = 0.3;
  static constexpr double flat_share_margin = 0.05;
  // The self-check (self_check_errors()) changes the kept run's number of
  // iterations only if its error on the synthetic copy is more than this
  // fraction above the smallest, and then to the largest smaller count
  // within it, or else to the count of the smallest (self_check_iterations()).
  // The copy takes the result for the noise-free surface, which it is not,
  // so differences this small are not evidence.
  // On the corpus, in a study that checked a grid of iteration counts: 0
  // shortened 107 of its 224 inputs (51 of them for the worse), 0.02 65 (30,
  // by at most 7.5%), 0.05 and 0.1 too few to matter. This implementation,
  // which checks every count, shortens 52 with 0.02 (24 for the worse, by at
  // most 6.6%); letting it lengthen runs too changes 13 more (11 for the
  // better, 2 for the worse by at most 0.5%), and lengthening to the count
  // of the smallest rather than to the first count within the tolerance
  // changes 18 more (14 for the better, 4 for the worse by at most 1.5%).
  static constexpr double self_check_tolerance = 0.02;
  // The self-check may lengthen the kept run up to this many iterations
  // (the candidates stop at max_iterations). A surface with no shape to lose
  // (a plane, a sphere) keeps gaining from more iterations, and the copy
  // shows it; the oracle grid of the corpus goes to 60. Against a ceiling of
  // 40 on the corpus: 15 inputs change, 13 for the better (by up to 13%: the
  // planes, spheres and the flat-faced cube), 2 for the worse by under
  // 0.1%; the copy runs longer only where its error is still falling.
  static constexpr unsigned int self_check_max_iterations = 60;
  // The self-check also runs the kept kernel on the copy with the paths of
  // the candidates' other radii (those still held: see kept_setup_bytes),
  // each to its first minimum, walking outwards from the candidate's radius
  // while each radius comes closer than the best so far, and takes the
  // radius whose smallest error is lowest if it is more than
  // self_check_tolerance below the candidate's own; the run is then redone
  // from the input with that radius and the count its copy asks for. (On
  // the corpus the walk gives the same choice as trying every radius on all
  // 224 inputs and skips the run on 6d on 132.) The candidates' radii are
  // few and tied to their kernels; on a surface with no shape to lose at
  // that scale (a sphere, a gently curved part, strong noise on an organic
  // model) the kept kernel gains from a wider support, which the copy shows. On the corpus against
  // the check of the candidate's radius alone: 24 inputs change, 20 for the
  // better (by up to 31%), 4 for the worse (depth scans, by up to 8%: the
  // copy's noise is white, the scan's low frequencies stay in the result).
  // The setups (mesh copy, face data and paths) of the radii already run are
  // kept for the kept candidate while they take at most this many bytes
  // together, so that its paths need not be built again; past it (meshes of
  // some hundred thousand faces) they are built again, as memory matters
  // more there. With Parallel_tag, when the setups of all the radii are
  // estimated to fit in it together, they are built first and the
  // candidates run as concurrent tasks (run_candidates()).
  static constexpr std::size_t kept_setup_bytes = std::size_t(256) << 20;
  // The second pass (second_pass_angles()): the kept kernel and radius run
  // again, from the result, for as many iterations as the result took. What
  // a filter that removed noise changes in its own result is what it would
  // remove from a noise-free surface: shape. If the second pass turns the
  // face normals by more than this share of the angle by which the result's
  // differ from the input's, most of the first pass's change was of that
  // kind, and the input is kept as it is. The share at which the result
  // starts to be worse than the input lies between 0.5 (shape and noise
  // removed add up) and 0.71 (they add in quadrature), and the second pass
  // under-reads the shape removed, as its input is smoother than the input
  // was; so the lower end. On the corpus the noise-free meshes that the
  // selection changes read 0.30 to 0.68, the noisy inputs 0.02 to 0.36 but
  // for coarse meshes at the edge of what can be denoised (up to 0.74).
  static constexpr double second_pass_share = 0.5;
  // The second pass runs only after a run of at most this many iterations
  // (it costs as many again): a longer run is evidence of noise in itself,
  // and on the corpus the share after one is at most 0.24 (111 inputs).
  static constexpr unsigned int second_pass_max_iterations = 8;
};

// One candidate's run: its trajectory (residual statistics after each
// iteration) and its result at the stop.
struct Candidate_run
{
  double sigma = 0., relative_radius = 0.;
  std::vector<Residual_statistics> trajectory;
  unsigned int iterations = 0; // the iterations kept (trajectory[iterations - 1]; 0: the input)
  bool stopped_by_correlation = false;
  double flat_share = -1.; // of the result (Selection_rules::flat_angle); -1: no interior edge
  double score = 0.;
  std::vector<Vec3> points;  // in input vertex order
  std::vector<Vec3> normals; // last filtered normals, in input face order (if asked)
};

// The correlation where the RMS first reaches `level` along `trajectory`
// (linear between iterations); +infinity if it never does.
inline double correlation_at_rms(const std::vector<Residual_statistics>& trajectory, double level)
{
  double previous_rms = 0., previous_corr = 0.;
  for(std::size_t i = 0; i < trajectory.size(); ++i)
  {
    const Residual_statistics& s = trajectory[i];
    if(s.rms >= level)
    {
      if(i == 0 || !(s.rms > previous_rms))
        return s.correlation;
      const double t = (level - previous_rms) / (s.rms - previous_rms);
      return previous_corr + t * (s.correlation - previous_corr);
    }
    previous_rms = s.rms;
    previous_corr = s.correlation;
  }
  return std::numeric_limits<double>::infinity();
}

// The index of the candidate kept, and each candidate's score (set in runs):
// among the candidates whose result is about as piecewise flat as the
// flattest (if that one is flat enough to tell), or else among all, the
// lowest residual correlation at the common comparison level.
inline std::size_t choose_candidate(std::vector<Candidate_run>& runs)
{
  double smallest = std::numeric_limits<double>::infinity(), flattest = -1.;
  for(const Candidate_run& r : runs)
  {
    if(r.iterations > 0)
      smallest = std::min(smallest, r.trajectory[r.iterations - 1].rms);
    flattest = std::max(flattest, r.flat_share);
  }
  const double level = Selection_rules::comparison_fraction * smallest;
  const double min_share =
      flattest >= Selection_rules::min_flat_share ? flattest - Selection_rules::flat_share_margin : -1.;
  std::size_t best = runs.size();
  for(std::size_t c = 0; c < runs.size(); ++c)
  {
    runs[c].score = correlation_at_rms(runs[c].trajectory, level);
    if(runs[c].flat_share >= min_share && (best == runs.size() || runs[c].score < runs[best].score))
      best = c;
  }
  return best == runs.size() ? 0 : best;
}

// The fraction of the interior edges of m (pairs of faces sharing two
// vertices, both with a non-zero normal) whose faces' normals differ by less
// than `angle` degrees; -1 if there is no such edge. Parallel over faces;
// the counts are exact, so the result does not depend on the tag.
template <typename ConcurrencyTag>
double flat_edge_fraction(const Flat_mesh& m, const std::vector<Vec3>& normals, double angle)
{
  const std::size_t nf = m.number_of_faces();
  const double cos_angle = std::cos(angle * 3.14159265358979323846 / 180.);
  std::vector<std::uint32_t> flat(nf, 0), total(nf, 0);
  for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t f = b; f < e; ++f)
    {
      const Vec3& n = normals[f];
      if(squared_norm(n) == 0.)
        continue;
      for_each_edge_adjacent_face_after(m, f, [&](std::uint32_t g) {
        if(squared_norm(normals[g]) == 0.)
          return;
        ++total[f];
        // unit normals: the angle is under `angle` iff the cosine is above
        flat[f] += dot(n, normals[g]) > cos_angle ? 1u : 0u;
      });
    }
  });
  std::size_t flat_sum = 0, total_sum = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    flat_sum += flat[f];
    total_sum += total[f];
  }
  return total_sum == 0 ? -1. : double(flat_sum) / double(total_sum);
}

// Runs one candidate kernel on the paths of `s` (built on the input, whose
// vertices have been renumbered for locality), from `input_points`, until an
// iteration's residual correlation reaches Selection_rules::stop_correlation
// (the result is then the iterate before it, which may be the input itself)
// or `max_iterations`.
template <typename ConcurrencyTag>
Candidate_run run_candidate(const Intrinsic_setup& s, const Intrinsic_kernel& kernel, const Csr& adjacency,
                            const std::vector<Vec3>& input_points, const std::vector<char>& fixed,
                            unsigned int vertex_iterations, Fold_safeguard& guard, double unit, bool keep_normals,
                            Least_squares_recovery* recovery = nullptr,
                            unsigned int max_iterations = Selection_rules::max_iterations)
{
  Candidate_run run;
  run.sigma = kernel.sigma_spatial;
  run.relative_radius = s.centroid_distance > 0. ? s.radius / s.centroid_distance : 0.;
  std::vector<Vec3> points = input_points, kept = input_points;
  std::vector<Vec3> kept_normals = keep_normals ? s.input_faces.normals : std::vector<Vec3>();
  iterate_filter<ConcurrencyTag>(
      s, kernel, s.input_faces, points, fixed, vertex_iterations, guard, max_iterations,
      [&](unsigned int k, const std::vector<Vec3>& p, std::vector<Vec3>& filtered) {
        run.trajectory.push_back(residual_statistics(adjacency, p, input_points, unit));
        if(run.trajectory.back().correlation >= Selection_rules::stop_correlation)
        {
          run.stopped_by_correlation = true;
          return false;
        }
        run.iterations = k;
        kept = p;
        if(keep_normals)
          kept_normals.swap(filtered); // the next pass overwrites all of `filtered`
        return true;
      },
      recovery);
  Face_data current;
  compute_face_data<ConcurrencyTag>(s.mesh, kept, current);
  run.flat_share = flat_edge_fraction<ConcurrencyTag>(s.mesh, current.normals, Selection_rules::flat_angle);
  run.points = s.mesh.vertex_values_in_input_order(kept);
  if(keep_normals)
    run.normals = s.mesh.in_input_order(kept_normals);
  return run;
}

// A synthetic noisy copy of `result` (a denoised version of `input`, same
// mesh `m`, vertex order of `m`) with the noise removed from it: the normal
// components of the residual input - result along result's vertex normals,
// shuffled over the vertices that are free (not `fixed`) and have an edge.
// The shuffle keeps the residual's distribution (dense or sparse, light or
// heavy-tailed) and breaks its spatial coherence, which is what shape removed
// would have. Fisher-Yates with std::mt19937 (whose output the standard
// fixes) seeded with `seed`, sequential: the same copy on every platform and
// for every thread count.
inline std::vector<Vec3> synthetic_noisy_copy(const Flat_mesh& m, const Csr& adjacency, const std::vector<Vec3>& input,
                                              const std::vector<Vec3>& result, const std::vector<char>& fixed,
                                              std::uint32_t seed = 1)
{
  const std::vector<Vec3> normals = area_weighted_vertex_normals(m, result);
  std::vector<std::uint32_t> free;
  std::vector<double> along;
  for(std::size_t v = 0; v < result.size(); ++v)
    if(!fixed[v] && adjacency.begin(v) != adjacency.end(v))
    {
      free.push_back(std::uint32_t(v));
      along.push_back(dot(input[v] - result[v], normals[v]));
    }
  std::mt19937 engine(seed);
  for(std::size_t i = along.size(); i > 1; --i)
    std::swap(along[i - 1], along[engine() % i]);
  std::vector<Vec3> copy = result;
  for(std::size_t i = 0; i < free.size(); ++i)
    copy[free[i]] = result[free[i]] + along[i] * normals[free[i]];
  return copy;
}

// The iterations of a self-check kept from its errors (errors[k]: after k
// iterations) for a run of `iterations` iterations. If a count no greater
// than `iterations` has an error within Selection_rules::self_check_tolerance
// of the smallest, the largest such count (the run is kept or shortened as
// little as the tolerance allows). Otherwise the run is lengthened, to the
// count of the smallest error: the copy's reference is the run's own
// result, which keeps whatever low-frequency noise the run left, so running
// on is penalised on the copy, and a minimum beyond the run's count in spite
// of that bias is evidence for the farther count rather than for the first
// one within the tolerance.
inline unsigned int self_check_iterations(const std::vector<double>& errors, unsigned int iterations)
{
  if(errors.empty())
    return 0;
  const auto smallest = std::min_element(errors.begin(), errors.end());
  const double limit = *smallest * (1. + Selection_rules::self_check_tolerance);
  if(std::isnan(limit))
    return iterations; // a NaN error: no evidence
  const std::size_t last = std::min<std::size_t>(iterations, errors.size() - 1);
  for(std::size_t i = last + 1; i-- > 0;)
    if(errors[i] <= limit)
      return unsigned(i);
  return unsigned(smallest - errors.begin());
}

// Whether two relative radii (radius / d, rounded) are the same: equal
// within a relative 1e-9.
inline bool same_relative_radius(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); }

// The bytes held by the arrays of the paths `p`.
inline std::size_t path_bytes(const Path_forest& p)
{
  return sizeof(std::uint32_t) * (p.offsets.size() + p.face.size() + p.parent.size()) + sizeof(double) * p.step.size() +
         sizeof(p.square_regions[0]) * p.square_regions.size() + p.weighted.size();
}

// The bytes held by the arrays of `s` (its mesh copy, face data and paths).
inline std::size_t setup_bytes(const Intrinsic_setup& s)
{
  const Flat_mesh& m = s.mesh;
  const Face_data& f = s.input_faces;
  return sizeof(Vec3) * (m.points.size() + f.normals.size() + f.centroids.size()) +
         sizeof(m.triangles[0]) * m.triangles.size() +
         sizeof(std::uint32_t) *
             (m.vertex_face_offsets.size() + m.vertex_faces.size() + m.input_face.size() + m.input_vertex.size()) +
         sizeof(double) * f.areas.size() + path_bytes(s.paths);
}

// The selection's steps, in the order intrinsic_denoising() calls them: for
// each radius of the candidates, set up the paths once on the input
// (`setup_paths`) and run the candidates on that radius (`run`); then
// `choose`, and go back to the kept candidate's paths (`reuse_paths`, or
// `setup_paths` again if they were not kept). The setups are built from the
// mesh with make_intrinsic_setup().
template <typename ConcurrencyTag>
class Automatic_selection
{
public:
  Automatic_selection(unsigned int vertex_iterations, bool prevent_folds, bool keep_normals,
                      Vertex_update vertex_update = Vertex_update::PAPER)
      : vertex_iterations_(vertex_iterations), keep_normals_(keep_normals),
        recovery_(make_vertex_recovery(vertex_update))
  {
    guard_.enabled = prevent_folds;
  }

  // Takes the setup of one radius (paths on the input mesh) and the
  // constrained vertices in input order. The setup it replaces is kept
  // within Selection_rules::kept_setup_bytes.
  void setup_paths(Intrinsic_setup&& s, const std::vector<char>& constrained_in_input_order)
  {
    keep_current_setup();
    setup_ = std::move(s);
    if(!setup_.mesh.input_face.empty())
      reorder_vertices_for_locality(setup_.mesh);
    use_setup(constrained_in_input_order);
  }

  // Makes the setup of `relative_radius` (in d) the current one if it is
  // held: current already, or kept; returns whether it was (if not, the
  // paths must be set up again).
  bool reuse_paths(double relative_radius, const std::vector<char>& constrained_in_input_order)
  {
    const Intrinsic_setup* held = held_setup(relative_radius);
    if(held == nullptr || held == &setup_)
      return held != nullptr;
    const std::ptrdiff_t i = held - kept_setups_.data();
    Intrinsic_setup s = std::move(kept_setups_[std::size_t(i)]);
    kept_setups_.erase(kept_setups_.begin() + i);
    kept_radius_.erase(kept_radius_.begin() + i);
    keep_current_setup();
    setup_ = std::move(s);
    use_setup(constrained_in_input_order);
    return true;
  }

  // Runs the candidate of kernel width `sigma` on the current paths.
  void run(double sigma) { runs_.push_back(run_again(sigma, Selection_rules::max_iterations)); }

  // Runs the `n` candidates `candidates` on the input, into runs() in their
  // order, each on the paths that `make_setup(candidate)` builds for its
  // radius (consecutive candidates of the same radius share them), and
  // calls `progress(c + 1, n)` for each from the calling thread. With
  // Parallel_tag, if the setups of all the radii are estimated to fit in
  // Selection_rules::kept_setup_bytes together, they are all built first and
  // the candidates then run as concurrent tasks, each parallel inside too:
  // on a small mesh one run alone leaves a thread idle at each of its many
  // short parallel loops. Otherwise they run one after the other, the setup
  // of a radius built when its first candidate comes. Each run is the same
  // either way; the setups end as the sequential order leaves them.
  template <typename MakeSetup, typename Progress>
  void run_candidates(const Selection_rules::Candidate* candidates, std::size_t n, const MakeSetup& make_setup,
                      const std::vector<char>& constrained, const Progress& progress)
  {
    runs_.clear();
    std::size_t c = 0;
    if constexpr(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
    {
      if(n > 1)
      {
        setup_paths(make_setup(candidates[0]), constrained);
        if(setups_fit_together(candidates, n))
        {
          run_concurrently(candidates, n, make_setup, constrained);
          for(std::size_t i = 0; i < n; ++i)
            progress(i + 1, n);
          return;
        }
        run(candidates[0].sigma); // its setup is built
        progress(1, n);
        c = 1;
      }
    }
    for(; c < n; ++c)
    {
      if(starts_radius(candidates, c))
        setup_paths(make_setup(candidates[c]), constrained);
      run(candidates[c].sigma);
      progress(c + 1, n);
    }
  }

  // Scores the candidates and returns the index of the one kept.
  std::size_t choose() { return choose_candidate(runs_); }

  // The sparse-noise test (sparse_noise.h) on the result of `run` (one of
  // runs()); the flags are returned in input vertex order.
  Sparse_noise_test test_sparse_noise(const Candidate_run& run) const
  {
    Sparse_noise_test t = sparse_noise_test(setup_.mesh, adjacency_, setup_.mesh.points,
                                            setup_.mesh.vertex_values_from_input_order(run.points), fixed_);
    t.outlier = setup_.mesh.vertex_values_in_input_order(t.outlier);
    return t;
  }

  // Relaxes the result of `run` along the surface (relax_tangentially()) on
  // the current setup; with a non-empty `moving` (input vertex order), only
  // the vertices flagged in it may move. Returns the number that moved.
  std::size_t relax(Candidate_run& run, const std::vector<char>& moving = std::vector<char>())
  {
    std::vector<Vec3> points = setup_.mesh.vertex_values_from_input_order(run.points);
    std::vector<char> held = fixed_;
    if(!moving.empty())
    {
      const std::vector<char> m = setup_.mesh.vertex_values_from_input_order(moving);
      for(std::size_t v = 0; v < held.size(); ++v)
        held[v] = held[v] || !m[v];
    }
    const std::size_t moved = relax_tangentially<ConcurrencyTag>(setup_.mesh, setup_.mesh.points, points, held, guard_);
    run.points = setup_.mesh.vertex_values_in_input_order(points);
    return moved;
  }

  // Denoises the input again with the kernel of width `sigma` on the current
  // paths, for `iterations` iterations, every vertex held in place but those
  // flagged in `outlier` (input vertex order).
  Candidate_run run_outliers_only(double sigma, unsigned int iterations, const std::vector<char>& outlier)
  {
    const Intrinsic_kernel kernel = kernel_of_width(sigma);
    std::vector<char> fixed = fixed_;
    const std::vector<char> moving = setup_.mesh.vertex_values_from_input_order(outlier);
    for(std::size_t v = 0; v < fixed.size(); ++v)
      fixed[v] = fixed[v] || !moving[v];
    Candidate_run run;
    run.sigma = sigma;
    run.relative_radius = current_relative_radius();
    std::vector<Vec3> points = setup_.mesh.points,
                      normals = keep_normals_ ? setup_.input_faces.normals : std::vector<Vec3>();
    run.iterations = iterate_filter<ConcurrencyTag>(
        setup_, kernel, setup_.input_faces, points, fixed, vertex_iterations_, guard_, iterations,
        [&](unsigned int, const std::vector<Vec3>&, std::vector<Vec3>& filtered) {
          if(keep_normals_)
            normals.swap(filtered); // the next pass overwrites all of `filtered`
          return true;
        },
        &recovery_);
    run.trajectory.push_back(residual_statistics(adjacency_, points, setup_.mesh.points, mean_edge_));
    run.points = setup_.mesh.vertex_values_in_input_order(points);
    if(keep_normals_)
      run.normals = setup_.mesh.in_input_order(normals);
    return run;
  }

  // The self-check of `run`, a candidate of kernel width `sigma`, on the
  // held paths (see held_radii()) of each radius of `radii`: the same kernel
  // runs on `copy_in_input_order`, a synthetic noisy copy of its result
  // (synthetic_copy()). On the first radius, if `first_as_run` (the
  // candidate's own), for as many iterations as the run did, and on (up to
  // Selection_rules::self_check_max_iterations) while each iteration brings
  // the copy closer and the error stays within the tolerance of the
  // smallest, so that a minimum after run.iterations is found when the
  // errors fall to it and rise after it; on the others, to the first
  // iteration that brings the copy no closer (another radius: only its
  // smallest error is wanted, which comes first). Returns, per radius, the
  // mean angle in degrees between the face normals of the copy after k
  // iterations and those of the result, from k = 0 (the copy itself); the
  // iterations kept are self_check_iterations() of the candidate's. With
  // Parallel_tag the radii run as concurrent tasks (each parallel inside
  // too); the current setup does not change.
  std::vector<std::vector<double>> self_check_errors(const Candidate_run& run, double sigma,
                                                     const std::vector<Vec3>& copy_in_input_order,
                                                     const std::vector<double>& radii, bool first_as_run)
  {
    std::vector<const Intrinsic_setup*> setups;
    for(double r : radii)
    {
      setups.push_back(held_setup(r));
      if(setups.back() == nullptr)
        throw std::logic_error("self_check_errors(): the paths of a radius are not held");
    }
    // the setups' meshes are the same (see run_concurrently())
    const std::vector<Vec3> result = setup_.mesh.vertex_values_from_input_order(run.points);
    const std::vector<Vec3> copy = setup_.mesh.vertex_values_from_input_order(copy_in_input_order);
    std::vector<std::vector<double>> errors(radii.size());
    for_each_chunk<ConcurrencyTag>(
        radii.size(),
        [&](std::size_t b, std::size_t e) {
          for(std::size_t i = b; i < e; ++i)
          {
            Least_squares_recovery recovery = recovery_;
            errors[i] = errors_on(*setups[i], run.iterations, sigma, result, copy, !(i == 0 && first_as_run), recovery);
          }
        },
        1);
    return errors;
  }

  // The synthetic noisy copy (synthetic_noisy_copy()) of the result of `run`,
  // made on the current setup, in input vertex order.
  std::vector<Vec3> synthetic_copy(const Candidate_run& run) const
  {
    const std::vector<Vec3> result = setup_.mesh.vertex_values_from_input_order(run.points);
    return setup_.mesh.vertex_values_in_input_order(
        synthetic_noisy_copy(setup_.mesh, adjacency_, setup_.mesh.points, result, fixed_));
  }

  // The radii (in d) whose paths are held: the current setup's, then the
  // kept ones in the order they were set up.
  std::vector<double> held_radii() const
  {
    std::vector<double> radii;
    if(!setup_.mesh.points.empty())
      radii.push_back(current_relative_radius());
    radii.insert(radii.end(), kept_radius_.begin(), kept_radius_.end());
    return radii;
  }

  // The kernel of width `sigma` on the current paths, run from the input for
  // exactly `iterations` iterations (no stopping rule).
  Candidate_run run_from_input(double sigma, unsigned int iterations)
  {
    Candidate_run run;
    run.sigma = sigma;
    run.relative_radius = current_relative_radius();
    run.points = setup_.mesh.vertex_values_in_input_order(setup_.mesh.points);
    return run_on(std::move(run), sigma, iterations);
  }

  // The candidate of kernel width `sigma` on the current paths, run from the
  // input for at most `iterations` iterations (run_candidate()). With fewer
  // iterations than it ran in the selection, its stopping rule, which did not
  // stop it before, does not now: the result is that of the shorter count.
  Candidate_run run_again(double sigma, unsigned int iterations)
  {
    return run_candidate<ConcurrencyTag>(setup_, kernel_of_width(sigma), adjacency_, setup_.mesh.points, fixed_,
                                         vertex_iterations_, guard_, mean_edge_, keep_normals_, &recovery_, iterations);
  }

  // `run`, a candidate of kernel width `sigma` on the current paths, run on
  // from its result for `more` iterations: the same (bit for bit) as running
  // it from the input for run.iterations + `more` without its stopping rule.
  Candidate_run run_on(Candidate_run&& run, double sigma, unsigned int more)
  {
    std::vector<Vec3> points = setup_.mesh.vertex_values_from_input_order(run.points);
    Face_data current;
    const bool no_normals = keep_normals_ && run.normals.empty();
    if(more > 0 || no_normals)
      compute_face_data<ConcurrencyTag>(setup_.mesh, points, current);
    if(more == 0)
    {
      // nothing to run: a run that has not run either (from the input) has
      // as "last filtered normals" the face normals of its points
      if(no_normals)
        run.normals = setup_.mesh.in_input_order(current.normals);
      return std::move(run);
    }
    std::vector<Vec3> normals;
    run.trajectory.resize(run.iterations);
    iterate_filter<ConcurrencyTag>(
        setup_, kernel_of_width(sigma), std::move(current), points, fixed_, vertex_iterations_, guard_, more,
        [&](unsigned int, const std::vector<Vec3>& p, std::vector<Vec3>& filtered) {
          run.trajectory.push_back(residual_statistics(adjacency_, p, setup_.mesh.points, mean_edge_));
          if(keep_normals_)
            normals.swap(filtered); // the next pass overwrites all of `filtered`
          return true;
        },
        &recovery_);
    run.iterations += more;
    run.points = setup_.mesh.vertex_values_in_input_order(points);
    if(keep_normals_)
      run.normals = setup_.mesh.in_input_order(normals);
    return std::move(run);
  }

  // The second pass of Selection_rules::second_pass_share on the result of
  // `run`, a run of kernel width `sigma` on the current paths: the mean
  // angles in degrees between the face normals of the input and of the
  // result, and between those of the result and of the result after
  // run.iterations more iterations of the kernel (run_on()).
  std::pair<double, double> second_pass_angles(const Candidate_run& run, double sigma)
  {
    Candidate_run again = run_on(Candidate_run(run), sigma, run.iterations);
    Face_data result, second;
    compute_face_data<ConcurrencyTag>(setup_.mesh, setup_.mesh.vertex_values_from_input_order(run.points), result);
    compute_face_data<ConcurrencyTag>(setup_.mesh, setup_.mesh.vertex_values_from_input_order(again.points), second);
    return {mean_angle_degrees(result.normals, setup_.input_faces.normals),
            mean_angle_degrees(second.normals, result.normals)};
  }

  std::vector<Candidate_run>& runs() { return runs_; }
  const std::vector<Candidate_run>& runs() const { return runs_; }
  double mean_edge_length_of_input() const { return mean_edge_; }
  double centroid_distance() const { return setup_.centroid_distance; }

private:
  // The held setup of `relative_radius` (the current one or a kept one), or
  // null.
  const Intrinsic_setup* held_setup(double relative_radius) const
  {
    if(!setup_.mesh.points.empty() && same_relative_radius(current_relative_radius(), relative_radius))
      return &setup_;
    for(std::size_t i = 0; i < kept_setups_.size(); ++i)
      if(same_relative_radius(kept_radius_[i], relative_radius))
        return &kept_setups_[i];
    return nullptr;
  }

  // One self-check run (self_check_errors()) on the paths of `s`, from
  // `copy` towards `result` (both in the vertex order of the setups), for a
  // run of `iterations` iterations.
  std::vector<double> errors_on(const Intrinsic_setup& s, unsigned int iterations, double sigma,
                                const std::vector<Vec3>& result, std::vector<Vec3> copy, bool to_first_minimum,
                                Least_squares_recovery& recovery) const
  {
    const Intrinsic_kernel kernel = kernel_of_width(s, sigma);
    Face_data target, current;
    compute_face_data<ConcurrencyTag>(s.mesh, result, target);
    compute_face_data<ConcurrencyTag>(s.mesh, copy, current);
    std::vector<double> errors(1, mean_angle_degrees(current.normals, target.normals));
    Fold_safeguard guard; // folds checked against the copy's own orientation
    guard.enabled = guard_.enabled;
    const std::vector<Vec3> copy_normals = current.normals;
    guard.reference = guard.enabled ? &copy_normals : nullptr;
    Face_data faces;
    double smallest = errors.front();
    iterate_filter<ConcurrencyTag>(
        s, kernel, std::move(current), copy, fixed_, vertex_iterations_, guard,
        Selection_rules::self_check_max_iterations,
        [&](unsigned int k, const std::vector<Vec3>& p, std::vector<Vec3>&) {
          compute_face_data<ConcurrencyTag>(s.mesh, p, faces);
          errors.push_back(mean_angle_degrees(faces.normals, target.normals));
          const double e = errors.back(), before = errors[k - 1];
          smallest = std::min(smallest, e);
          if(to_first_minimum)
            return e < before;
          return k < iterations || (e < before && e <= smallest * (1. + Selection_rules::self_check_tolerance));
        },
        &recovery);
    return errors;
  }

  // Whether candidate c of `candidates` needs a setup of its own: the first,
  // or one whose radius differs from the candidate's before it (those of the
  // same radius in a row share their paths).
  static bool starts_radius(const Selection_rules::Candidate* candidates, std::size_t c)
  {
    return c == 0 || !same_relative_radius(candidates[c].relative_radius, candidates[c - 1].relative_radius);
  }

  // Whether the setups of all the radii of `candidates` would fit in
  // Selection_rules::kept_setup_bytes together, estimated from the current
  // setup (of the first candidate's radius): the mesh and face data as they
  // are, the paths scaled by the square of the radius ratio (a path per face
  // of each neighbourhood).
  bool setups_fit_together(const Selection_rules::Candidate* candidates, std::size_t n) const
  {
    const double r0 = current_relative_radius();
    if(!(r0 > 0.))
      return false;
    const double paths = double(path_bytes(setup_.paths)), rest = double(setup_bytes(setup_)) - paths;
    double total = 0.;
    for(std::size_t c = 0; c < n; ++c)
      if(starts_radius(candidates, c))
      {
        const double ratio = candidates[c].relative_radius / r0;
        total += rest + paths * ratio * ratio;
      }
    return total <= double(Selection_rules::kept_setup_bytes);
  }

  // run_candidates() with every setup built first (the first one is the
  // current setup), then the candidates as concurrent tasks. The setups are
  // built from the same input, so their meshes (vertex and face orders
  // included) are the same: the constrained flags, adjacency and input
  // normals of the current one serve all. Each task has its own fold
  // safeguard and recovery scratch space.
  template <typename MakeSetup>
  void run_concurrently(const Selection_rules::Candidate* candidates, std::size_t n, const MakeSetup& make_setup,
                        const std::vector<char>& constrained)
  {
    std::vector<Intrinsic_setup> setups;
    std::vector<std::size_t> setup_of(n, 0);
    setups.push_back(std::move(setup_));
    setup_ = Intrinsic_setup();
    for(std::size_t c = 1; c < n; ++c)
    {
      if(starts_radius(candidates, c))
      {
        Intrinsic_setup s = make_setup(candidates[c]);
        if(!s.mesh.input_face.empty())
          reorder_vertices_for_locality(s.mesh);
        CGAL_assertion(s.mesh.input_face == setups.front().mesh.input_face &&
                       s.mesh.input_vertex == setups.front().mesh.input_vertex);
        setups.push_back(std::move(s));
      }
      setup_of[c] = setups.size() - 1;
    }
    runs_.assign(n, Candidate_run());
    for_each_chunk<ConcurrencyTag>(
        n,
        [&](std::size_t b, std::size_t e) {
          for(std::size_t c = b; c < e; ++c)
          {
            const Intrinsic_setup& s = setups[setup_of[c]];
            Fold_safeguard guard = guard_;
            Least_squares_recovery recovery = recovery_;
            runs_[c] =
                run_candidate<ConcurrencyTag>(s, kernel_of_width(s, candidates[c].sigma), adjacency_, s.mesh.points,
                                              fixed_, vertex_iterations_, guard, mean_edge_, keep_normals_, &recovery);
          }
        },
        1);
    setup_ = std::move(setups.front());
    for(std::size_t i = 1; i < setups.size(); ++i)
    {
      keep_current_setup();
      setup_ = std::move(setups[i]);
    }
    use_setup(constrained);
  }

  // The current setup's radius in d.
  double current_relative_radius() const
  {
    return setup_.centroid_distance > 0. ? setup_.radius / setup_.centroid_distance : 0.;
  }

  // Moves the current setup to the kept ones if all of them then fit in
  // Selection_rules::kept_setup_bytes, or else drops it.
  void keep_current_setup()
  {
    if(setup_.mesh.points.empty())
      return;
    std::size_t bytes = setup_bytes(setup_);
    for(const Intrinsic_setup& k : kept_setups_)
      bytes += setup_bytes(k);
    if(bytes <= Selection_rules::kept_setup_bytes)
    {
      kept_radius_.push_back(current_relative_radius());
      kept_setups_.push_back(std::move(setup_));
    }
    setup_ = Intrinsic_setup();
  }

  // What the runs read of the current setup (whose vertices are in their
  // local order).
  void use_setup(const std::vector<char>& constrained_in_input_order)
  {
    fixed_ = setup_.mesh.vertex_values_from_input_order(constrained_in_input_order);
    input_normals_ = setup_.input_faces.normals;
    guard_.reference = guard_.enabled ? &input_normals_ : nullptr;
    adjacency_ = vertex_adjacency(setup_.mesh);
    mean_edge_ = mean_edge_length(setup_.mesh);
  }

  // The kernel of setup `s` (by default the current one) with sigma_s =
  // sigma_r = `sigma`.
  static Intrinsic_kernel kernel_of_width(const Intrinsic_setup& s, double sigma)
  {
    Intrinsic_kernel kernel = s.kernel;
    kernel.sigma_spatial = kernel.sigma_range = sigma;
    return kernel;
  }
  Intrinsic_kernel kernel_of_width(double sigma) const { return kernel_of_width(setup_, sigma); }

  unsigned int vertex_iterations_;
  bool keep_normals_;
  Fold_safeguard guard_;
  // scratch space only: shared by the setups, whose meshes are the same
  Least_squares_recovery recovery_;
  Intrinsic_setup setup_;
  // setups of radii run before, and their relative radii
  std::vector<Intrinsic_setup> kept_setups_;
  std::vector<double> kept_radius_;
  std::vector<char> fixed_;
  std::vector<Vec3> input_normals_;
  Csr adjacency_;
  double mean_edge_ = 0.;
  std::vector<Candidate_run> runs_;
};

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
