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

#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_rules.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/candidates.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/residual_statistics.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/self_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/sparse_noise.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_iterations.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

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
  void run(double sigma) { runs_.push_back(run_again(kernel_of_width(sigma), Selection_rules::max_iterations)); }

  // The kernel of the current setup with sigma_s = sigma_r = `sigma` (a
  // candidate's kernel; the setups of the other radii have the same one).
  Intrinsic_kernel kernel_of_width(double sigma) const { return Denoising::kernel_of_width(setup_.kernel, sigma); }

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

  // Denoises the input again with `kernel` on the current paths, for
  // `iterations` iterations, every vertex held in place but those flagged in
  // `outlier` (input vertex order).
  Candidate_run run_outliers_only(const Intrinsic_kernel& kernel, unsigned int iterations,
                                  const std::vector<char>& outlier)
  {
    std::vector<char> fixed = fixed_;
    const std::vector<char> moving = setup_.mesh.vertex_values_from_input_order(outlier);
    for(std::size_t v = 0; v < fixed.size(); ++v)
      fixed[v] = fixed[v] || !moving[v];
    Candidate_run run;
    run.sigma = kernel.sigma_range;
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

  // The self-check of `run`, a candidate of kernel `kernel`, on the
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
  std::vector<std::vector<double>> self_check_errors(const Candidate_run& run, const Intrinsic_kernel& kernel,
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
            errors[i] = self_check_errors_on<ConcurrencyTag>(*setups[i], kernel, run.iterations, result, copy,
                                                             !(i == 0 && first_as_run), fixed_, vertex_iterations_,
                                                             guard_.enabled, recovery);
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

  // `kernel` on the current paths, run from the input for exactly
  // `iterations` iterations (no stopping rule).
  Candidate_run run_from_input(const Intrinsic_kernel& kernel, unsigned int iterations)
  {
    Candidate_run run;
    run.sigma = kernel.sigma_range;
    run.relative_radius = current_relative_radius();
    run.points = setup_.mesh.vertex_values_in_input_order(setup_.mesh.points);
    return run_on(std::move(run), kernel, iterations);
  }

  // The candidate of kernel `kernel` on the current paths, run from the
  // input for at most `iterations` iterations (run_candidate()). With fewer
  // iterations than it ran in the selection, its stopping rule, which did not
  // stop it before, does not now: the result is that of the shorter count.
  Candidate_run run_again(const Intrinsic_kernel& kernel, unsigned int iterations)
  {
    return run_candidate<ConcurrencyTag>(setup_, kernel, adjacency_, setup_.mesh.points, fixed_, vertex_iterations_,
                                         guard_, mean_edge_, keep_normals_, &recovery_, iterations);
  }

  // `run`, a candidate of kernel `kernel` on the current paths, run on
  // from its result for `more` iterations: the same (bit for bit) as running
  // it from the input for run.iterations + `more` without its stopping rule.
  Candidate_run run_on(Candidate_run&& run, const Intrinsic_kernel& kernel, unsigned int more)
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
        setup_, kernel, std::move(current), points, fixed_, vertex_iterations_, guard_, more,
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
  std::pair<double, double> second_pass_angles(const Candidate_run& run, const Intrinsic_kernel& kernel)
  {
    Candidate_run again = run_on(Candidate_run(run), kernel, run.iterations);
    Face_data result, second;
    compute_face_data<ConcurrencyTag>(setup_.mesh, setup_.mesh.vertex_values_from_input_order(run.points), result);
    compute_face_data<ConcurrencyTag>(setup_.mesh, setup_.mesh.vertex_values_from_input_order(again.points), second);
    return {mean_angle_degrees(result.normals, setup_.input_faces.normals),
            mean_angle_degrees(second.normals, result.normals)};
  }

  // The mean angle in degrees between the face normals of the result of
  // `run` and the input's.
  double turn_from_input(const Candidate_run& run) const
  {
    Face_data f;
    compute_face_data<ConcurrencyTag>(setup_.mesh, setup_.mesh.vertex_values_from_input_order(run.points), f);
    return mean_angle_degrees(f.normals, setup_.input_faces.normals);
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
            runs_[c] = run_candidate<ConcurrencyTag>(s, Denoising::kernel_of_width(s.kernel, candidates[c].sigma),
                                                     adjacency_, s.mesh.points, fixed_, vertex_iterations_, guard,
                                                     mean_edge_, keep_normals_, &recovery);
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