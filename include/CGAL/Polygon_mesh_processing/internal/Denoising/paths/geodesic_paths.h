// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The paper's first formulation (section 3.2, eqs. 4 and 8-9 along "the
// geodesic path between p and q"): the path from face i to a neighbour j is
// the exact geodesic from centroid c_i to centroid c_j, computed with CGAL's
// Surface_mesh_shortest_path on a small copy of face i's neighbourhood patch.
// Its nodes are the faces the geodesic crosses, in order from i to j; the
// paths of one face are merged into a prefix tree (a Path_forest tree).
//
// The patch copy is geodesic_patch_mesh.h, the geodesic solver on it
// geodesic_patch_solver.h.

#ifndef CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATHS_H
#define CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATHS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/geodesic_patch_solver.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/path_forest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/enumerable_thread_specific.h>
#endif

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Options of the geodesic strategy.
struct Geodesic_path_options
{
  // Rings of faces (sharing a vertex) added around the neighbourhood to form
  // the patch the geodesics are computed on, so that a geodesic between two
  // neighbours may pass through faces whose centroid lies just outside the
  // radius; only faces that come within the distance of the farthest
  // neighbour centroid are added. 0 (default): the neighbourhood and face i
  // only, the patch of the issue; on the benchmark meshes 1 ring changes
  // E_n by < 0.001 degree and costs about 35% more path time.
  unsigned int patch_rings = 0;
  // Fill Path_forest::step with geodesic step lengths (eq. 4), divided by
  // `length_unit`; otherwise leave it empty (unit steps, eq. 8).
  bool step_length = false;
  double length_unit = 1.;
  // Time the phases of the path construction into Geodesic_path_statistics
  // (the *_seconds fields; for the benchmark). Off by default: two clock
  // reads per neighbour cost about 3% of the path time.
  bool time_phases = false;
};

// Step lengths along a geodesic path (eq. 4). Each face x of the path is
// represented by the point q_x of the geodesic at the middle (by length) of
// the part of the geodesic inside x; q_i = c_i and q_j = c_j. The step of the
// node of face path.faces[k] is the length of the geodesic from q of the
// previous face to q of this one, so the steps of a path sum to its length.
inline double geodesic_step(const Geodesic_path& path, std::size_t k)
{
  const std::size_t last = path.faces.size() - 1;
  const double before = k - 1 == 0 ? path.lengths[0] : 0.5 * path.lengths[k - 1];
  const double after = k == last ? path.lengths[k] : 0.5 * path.lengths[k];
  return before + after;
}

// A node of a face's prefix tree of geodesic paths, with the two per-node
// arrays of Path_forest the geodesic strategy fills.
struct Geodesic_tree_node
{
  std::uint32_t face;
  std::int32_t parent;
  char weighted;
  double step;
};

// Builds the prefix trees of faces one after the other (see
// geodesic_paths()) with one solver, keeping its buffers from face to face.
class Geodesic_tree_builder
{
public:
  Geodesic_tree_builder(Geodesic_patch_solver& solver, Geodesic_path_statistics& counts, const Face_data& fd,
                        const Csr& neighbors, double unit)
      : solver_(solver), counts_(counts), fd_(fd), neighbors_(neighbors), unit_(unit)
  {
  }

  // Appends the nodes of face i's tree to `out`.
  void build(std::size_t i, std::vector<Geodesic_tree_node>& out)
  {
    if(neighbors_.begin(i) == neighbors_.end(i))
      return;
    trace_paths(i);
    start_ = out.size();
    first_child_.clear();
    next_sibling_.clear();
    root_first_child_ = -1;
    const std::uint32_t nb = neighbors_.begin(i);
    for(const auto& o : order_)
    {
      const std::size_t k = o.second;
      std::int32_t node = Path_forest::root;
      if(reached_[k])
      {
        const Geodesic_path& p = paths_[k];
        for(std::size_t x = 1; x < p.faces.size(); ++x)
          node = child(out, node, p.faces[x], geodesic_step(p, x) / unit_);
      }
      else
        node = child(out, Path_forest::root, neighbors_.items[nb + k], o.first / unit_);
      out[start_ + node].weighted = 1;
    }
  }

private:
  // The geodesics from face i to its neighbours (or the direct path where
  // none is found), ordered by length.
  void trace_paths(std::size_t i)
  {
    const std::uint32_t nb = neighbors_.begin(i), ne = neighbors_.end(i);
    const std::size_t n = ne - nb;
    const bool patch_ok =
        solver_.set_source(std::uint32_t(i), neighbors_.items.begin() + nb, neighbors_.items.begin() + ne);
    if(!patch_ok)
      ++counts_.failed_patches;
    if(paths_.size() < n)
      paths_.resize(n);
    reached_.assign(n, 0);
    order_.clear();
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::uint32_t j = neighbors_.items[nb + k];
      reached_[k] = patch_ok && solver_.path_to(j, paths_[k]) ? 1 : 0;
      const double len = reached_[k] ? paths_[k].length() : norm(fd_.centroids[j] - fd_.centroids[i]);
      order_.emplace_back(len, k);
      ++counts_.paths;
      if(!reached_[k])
        ++counts_.fallbacks;
      else if(paths_[k].vertex_passages > 0)
        ++counts_.vertex_passages;
    }
    std::sort(order_.begin(), order_.end());
  }

  // Adds (or finds) the child of `parent` (local index or root) with face f.
  std::int32_t child(std::vector<Geodesic_tree_node>& out, std::int32_t parent, std::uint32_t f, double step)
  {
    std::int32_t k = parent == Path_forest::root ? root_first_child_ : first_child_[parent];
    for(; k != -1; k = next_sibling_[k])
      if(out[start_ + k].face == f)
        return k;
    const std::int32_t id = std::int32_t(out.size() - start_);
    out.push_back(Geodesic_tree_node{f, parent, 0, step});
    first_child_.push_back(-1);
    std::int32_t& head = parent == Path_forest::root ? root_first_child_ : first_child_[parent];
    next_sibling_.push_back(head);
    head = id;
    return id;
  }

  Geodesic_patch_solver& solver_;
  Geodesic_path_statistics& counts_;
  const Face_data& fd_;
  const Csr& neighbors_;
  double unit_;
  std::vector<Geodesic_path> paths_;
  std::vector<char> reached_;
  std::vector<std::pair<double, std::size_t>> order_;
  std::vector<std::int32_t> first_child_, next_sibling_;
  std::int32_t root_first_child_ = -1;
  std::size_t start_ = 0;
};

// Builds the geodesic path forest. For each face i, the neighbours are
// reached by geodesics inside i's patch (see Geodesic_patch_solver), taken by
// increasing geodesic length, and inserted into a prefix tree: a node per
// distinct prefix (sequence of faces from i), so shared prefixes are shared
// nodes. The node at the end of neighbour j's path is weighted; the nodes a
// path only passes through are not (`weighted` = 0), even when their face is
// a neighbour too (that neighbour has its own weighted node at the end of its
// own path). Each neighbour is thus weighted exactly once.
//
// Fallback: a neighbour that no geodesic reaches inside the patch (another
// component of the patch, a face of zero area, or a face i of zero area or
// whose patch could not be built) gets the direct path i -> j, as in the
// DIRECT strategy, with the Euclidean distance |c_j - c_i| as its step.
//
// With options.step_length, `step` holds geodesic_step() / length_unit of
// the path that created the node (the shortest path through that prefix).
template <typename ConcurrencyTag>
Path_forest geodesic_paths(const Flat_mesh& m, const Face_data& fd, const Csr& neighbors,
                           const Geodesic_path_options& options = Geodesic_path_options(),
                           Geodesic_path_statistics* statistics = nullptr)
{
  const double unit = options.length_unit > 0. ? options.length_unit : 1.;
  // What a thread keeps from one chunk to the next: its solver (whose stamps
  // are as large as the mesh) and its counts.
  struct Thread_state
  {
    std::unique_ptr<Geodesic_patch_solver> solver;
    Geodesic_path_statistics counts;
  };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<Thread_state> states;
#else
  std::vector<Thread_state> states(1);
#endif
  const auto make_builder = [&]() {
#ifdef CGAL_LINKED_WITH_TBB
    Thread_state& state = states.local();
#else
    Thread_state& state = states[0];
#endif
    if(!state.solver)
    {
      state.solver.reset(new Geodesic_patch_solver(m, fd, options.patch_rings));
      state.solver->set_collect_points(false);
      state.solver->set_phase_statistics(options.time_phases ? &state.counts : nullptr);
    }
    return Geodesic_tree_builder(*state.solver, state.counts, fd, neighbors, unit);
  };
  Path_forest forest;
  const auto append = [&](const std::vector<Geodesic_tree_node>& chunk) {
    forest.append_nodes(chunk);
    if(forest.weighted.capacity() < forest.offsets.back())
      forest.weighted.reserve(forest.offsets.back());
    if(options.step_length && forest.step.capacity() < forest.offsets.back())
      forest.step.reserve(forest.offsets.back());
    for(const Geodesic_tree_node& node : chunk)
    {
      forest.weighted.push_back(node.weighted);
      if(options.step_length)
        forest.step.push_back(node.step);
    }
  };
  build_lists<ConcurrencyTag, Geodesic_tree_node>(
      m.number_of_faces(), forest.offsets, make_builder,
      [](std::size_t i, Geodesic_tree_builder& builder, std::vector<Geodesic_tree_node>& out) {
        builder.build(i, out);
      },
      append, 32); // a face's geodesics take long, and the solver is per thread: small chunks balance the threads
  if(statistics)
  {
    *statistics = Geodesic_path_statistics();
    for(const Thread_state& state : states)
      statistics->add(state.counts);
  }
  return forest;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
