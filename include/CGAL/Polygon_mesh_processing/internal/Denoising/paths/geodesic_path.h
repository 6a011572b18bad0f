// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// One geodesic path as the geodesic strategy uses it (faces crossed,
// lengths, points), made from the events of CGAL's path sequence; the counts
// and phase times the path builder reports.

#ifndef CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATH_H
#define CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATH_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/vec3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Counts of what happened while building the paths (for tests and reports).
struct Geodesic_path_statistics
{
  std::size_t paths = 0;           // neighbour paths built (one per neighbour)
  std::size_t fallbacks = 0;       // of which direct i -> j (no geodesic found in the patch)
  std::size_t vertex_passages = 0; // geodesics through a vertex of the patch (pseudo-sources)
  std::size_t failed_patches = 0;  // faces whose patch could not be built (all paths direct)
  // With Geodesic_path_options::time_phases, seconds (summed over threads)
  // spent copying the patches, and inside CGAL's Surface_mesh_shortest_path:
  // building the sequence trees (build_sequence_tree()), freeing them
  // (clear()) and answering the queries
  // (shortest_path_sequence_to_source_points(), with the visitor that records
  // the crossed edges). Zero otherwise.
  double patch_seconds = 0., tree_seconds = 0., clear_seconds = 0., query_seconds = 0.;

  void add(const Geodesic_path_statistics& o)
  {
    paths += o.paths;
    fallbacks += o.fallbacks;
    vertex_passages += o.vertex_passages;
    failed_patches += o.failed_patches;
    patch_seconds += o.patch_seconds;
    tree_seconds += o.tree_seconds;
    clear_seconds += o.clear_seconds;
    query_seconds += o.query_seconds;
  }
};

// One geodesic path from c_i to c_j, in order from i to j.
// - faces: the faces whose interior the geodesic crosses (over a length
//   above a relative 1e-9 of the whole path), starting with i, ending with j;
//   consecutive faces are different.
// - lengths: for each face, the length of the geodesic inside it.
// - points: the polyline c_i, the points where it crosses an edge or passes
//   through a vertex (each point once), c_j (empty if the solver does not
//   collect them, see Geodesic_patch_solver::set_collect_points()).
struct Geodesic_path
{
  std::vector<std::uint32_t> faces;
  std::vector<double> lengths;
  std::vector<Vec3> points;
  std::size_t vertex_passages = 0;
  double length() const
  {
    double s = 0.;
    for(double l : lengths)
      s += l;
    return s;
  }
};

// A stopwatch for Geodesic_path_options::time_phases: add_to(field) adds the
// seconds since the last add_to() (or construction) to that field of
// `statistics` and restarts; with no statistics it reads no clock.
class Phase_clock
{
public:
  explicit Phase_clock(Geodesic_path_statistics* statistics) : statistics_(statistics)
  {
    if(statistics_)
      last_ = std::chrono::steady_clock::now();
  }
  void add_to(double Geodesic_path_statistics::*field)
  {
    if(!statistics_)
      return;
    const auto now = std::chrono::steady_clock::now();
    statistics_->*field += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

private:
  Geodesic_path_statistics* statistics_;
  std::chrono::steady_clock::time_point last_;
};

// One event of CGAL's path sequence, as the solver's visitor records it
// (from the query back to the source): the source or query point in a face,
// an edge crossing, or a passage through a vertex.
struct Geodesic_event
{
  enum Kind
  {
    FACE,
    EDGE,
    VERTEX
  } kind;
  std::uint32_t near_face, far_face; // EDGE: faces on the source side and on the query side; FACE: the face
  Vec3 point;
};

// The lengths of the geodesic inside each face it runs through, from c_j
// back to c_i (`portions`, one entry per run, a face possibly twice), and
// its points from c_i to c_j (with `collect_points`). The geodesic's segment
// between two consecutive events lies in one face: before an edge crossing
// (towards c_j) in the face on the query side, after it in the face on the
// source side. At a vertex, the faces around it are not crossed; the path
// goes on in the face of the next edge crossing (or face i).
inline void geodesic_portions(const std::vector<Geodesic_event>& events, bool collect_points,
                              std::vector<std::pair<std::uint32_t, double>>& portions, Geodesic_path& out)
{
  const std::uint32_t no_face = std::uint32_t(-1);
  portions.clear();
  out.points.clear();
  std::uint32_t current = events.front().far_face; // face j
  double run = 0.;
  Vec3 last = events.front().point;
  if(collect_points)
    out.points.push_back(last);
  auto close = [&]() {
    if(current != no_face)
      portions.emplace_back(current, run);
    run = 0.;
  };
  for(std::size_t k = 1; k < events.size(); ++k)
  {
    const Geodesic_event& e = events[k];
    if(e.kind == Geodesic_event::EDGE)
    {
      if(current != e.far_face)
      {
        close();
        current = e.far_face;
      }
      run += norm(e.point - last);
      close();
      current = e.near_face;
    }
    else if(e.kind == Geodesic_event::VERTEX)
    {
      run += norm(e.point - last);
      close();
      current = no_face;
      ++out.vertex_passages;
    }
    else // FACE: the source, last event
    {
      if(current != e.far_face)
      {
        close();
        current = e.far_face;
      }
      run += norm(e.point - last);
      close();
    }
    last = e.point;
    if(collect_points)
      out.points.push_back(last);
  }
  std::reverse(out.points.begin(), out.points.end());
}

// The faces and lengths of `out` from the portions (from j back to i): the
// faces only touched (at a vertex or an edge end, length at most `touched`)
// dropped, repeats merged, starting at i (`source`) and ending the first
// time the path reaches j.
inline void geodesic_faces(const std::vector<std::pair<std::uint32_t, double>>& portions, double touched,
                           std::uint32_t source, std::uint32_t j, Geodesic_path& out)
{
  for(std::size_t k = portions.size(); k-- > 0;)
  {
    const auto& p = portions[k];
    const bool end = k == 0 || k + 1 == portions.size();
    if(!end && !(p.second > touched))
      continue;
    if(!out.faces.empty() && out.faces.back() == p.first)
      out.lengths.back() += p.second;
    else
    {
      out.faces.push_back(p.first);
      out.lengths.push_back(p.second);
    }
  }
  if(out.faces.empty() || out.faces.front() != source)
  {
    out.faces.insert(out.faces.begin(), source);
    out.lengths.insert(out.lengths.begin(), 0.);
  }
  const auto first_j = std::find(out.faces.begin() + 1, out.faces.end(), j);
  if(first_j == out.faces.end())
  {
    out.faces.push_back(j);
    out.lengths.push_back(0.);
  }
  else
  {
    const std::size_t n = std::size_t(first_j - out.faces.begin()) + 1;
    out.faces.resize(n);
    out.lengths.resize(n);
  }
}

// Turns `events` (from c_j back to c_i, as recorded by the solver; the first
// and the last are FACE events) into the faces the geodesic crosses, their
// lengths and (with `collect_points`) its points, from i (`source`) to j.
// `portions` is scratch memory. Returns false if the length is not finite.
inline bool trace_geodesic_path(const std::vector<Geodesic_event>& events, std::uint32_t source, std::uint32_t j,
                                bool collect_points, std::vector<std::pair<std::uint32_t, double>>& portions,
                                Geodesic_path& out)
{
  geodesic_portions(events, collect_points, portions, out);
  double total = 0.;
  for(const auto& p : portions)
    total += p.second;
  if(!std::isfinite(total))
    return false;
  // points met twice (a crossing exactly at a vertex is reported once per
  // edge around it) are kept once
  const double touched = 1e-9 * total;
  std::size_t kept = out.points.empty() ? 0 : 1;
  for(std::size_t k = 1; k < out.points.size(); ++k)
    if(norm(out.points[k] - out.points[kept - 1]) > touched || k + 1 == out.points.size())
      out.points[kept++] = out.points[k];
  out.points.resize(kept);
  geodesic_faces(portions, touched, source, j, out);
  return true;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
