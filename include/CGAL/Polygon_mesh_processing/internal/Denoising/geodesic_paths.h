// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The paper's first formulation (section 3.2, eqs. 4 and 8-9 along "the
// geodesic path between p and q"): the path from face i to a neighbour j is
// the exact geodesic from centroid c_i to centroid c_j, computed with CGAL's
// Surface_mesh_shortest_path on a small copy of face i's neighbourhood patch.
// Its nodes are the faces the geodesic crosses, in order from i to j; the
// paths of one face are merged into a prefix tree (a Path_forest tree).

#ifndef CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATHS_H
#define CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATHS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/square_pattern_paths.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
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

// Counts of what happened while building the paths (for tests and reports).
struct Geodesic_path_statistics
{
  std::size_t paths = 0;            // neighbour paths built (one per neighbour)
  std::size_t fallbacks = 0;        // of which direct i -> j (no geodesic found in the patch)
  std::size_t vertex_passages = 0;  // geodesics through a vertex of the patch (pseudo-sources)
  std::size_t failed_patches = 0;   // faces whose patch could not be built (all paths direct)
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

// The patch copy: a CGAL::Surface_mesh that also knows, for each of its
// vertices, whether a geodesic may pass through it (CGAL's pseudo-sources).
//
// CGAL's Surface_mesh_shortest_path makes a pseudo-source (a vertex from which
// new cones of geodesics are expanded) of every saddle vertex (angle sum at
// least 2 pi, up to CGAL's relative margin 100 eps) and of every border vertex.
// A shortest path through a border vertex makes, on its only side, an angle
// not larger than the interior angle of the surface there; a shortest path has
// no angle below pi at a vertex it passes through (it could be shortened), so
// it never passes through a border vertex of interior angle below pi. About
// 13 of the 22 border vertices of a patch are such convex corners; expanding
// cones from them only costs time (10 to 20% of the path time). The patch
// therefore flags a vertex as a pseudo-source if it is
// - interior: CGAL's own saddle test (the same angle formula, in degrees, and
//   the same bound), on angles computed once per mesh face corner;
// - on the border: interior angle at least (1 - 1e-9) pi (straight or
//   reflex; the margin keeps straight borders, where the angle is pi up to
//   rounding).
// The flags reach CGAL through its two customisation points: the traits'
// Is_saddle_vertex functor (Geodesic_patch_traits) and the BGL free function
// is_border(vertex, graph), overloaded below for this mesh type so that it
// reports a border vertex only where a geodesic may turn around it.
// is_border(v, g) for a vertex is used by Surface_mesh_shortest_path only to
// choose its pseudo-sources (CGAL 5.5); halfedge and edge border tests are
// untouched.
typedef CGAL::Simple_cartesian<double> Geodesic_patch_kernel;
class Geodesic_patch_mesh : public CGAL::Surface_mesh<Geodesic_patch_kernel::Point_3>
{
public:
  typedef CGAL::Surface_mesh<Geodesic_patch_kernel::Point_3> Base;
  std::vector<char> pseudo_source; // by vertex index
  std::vector<char> border;        // by vertex index
};

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#define CGAL_GRAPH_TRAITS_INHERITANCE_CLASS_NAME CGAL::Polygon_mesh_processing::internal::Denoising::Geodesic_patch_mesh
#define CGAL_GRAPH_TRAITS_INHERITANCE_BASE_CLASS_NAME                                                                  \
  CGAL::Surface_mesh<CGAL::Polygon_mesh_processing::internal::Denoising::Geodesic_patch_kernel::Point_3>
#include <CGAL/boost/graph/graph_traits_inheritance_macros.h>

namespace boost {
// as CGAL does for graph_traits<const Surface_mesh<P> >
template <>
struct graph_traits<const CGAL::Polygon_mesh_processing::internal::Denoising::Geodesic_patch_mesh>
    : public graph_traits<CGAL::Polygon_mesh_processing::internal::Denoising::Geodesic_patch_mesh>
{};
} // namespace boost

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Found by argument-dependent lookup from Surface_mesh_shortest_path (see
// Geodesic_patch_mesh): a border vertex that is a pseudo-source.
inline boost::optional<Geodesic_patch_mesh::Halfedge_index> is_border(Geodesic_patch_mesh::Vertex_index v,
                                                                     const Geodesic_patch_mesh& g)
{
  if(g.border[std::size_t(v)] && g.pseudo_source[std::size_t(v)])
    return g.halfedge(v); // the incoming border halfedge (see build_patch())
  return boost::none;
}

struct Geodesic_patch_traits
    : public CGAL::Surface_mesh_shortest_path_traits<Geodesic_patch_kernel, Geodesic_patch_mesh>
{
  struct Is_saddle_vertex
  {
    typedef bool result_type;
    template <typename VertexPointMap>
    bool operator()(Geodesic_patch_mesh::Vertex_index v, const Geodesic_patch_mesh& g, const VertexPointMap&) const
    {
      return g.pseudo_source[std::size_t(v)] != 0;
    }
    bool operator()(Geodesic_patch_mesh::Vertex_index v, const Geodesic_patch_mesh& g) const
    {
      return g.pseudo_source[std::size_t(v)] != 0;
    }
  };
  Is_saddle_vertex is_saddle_vertex_object() const { return Is_saddle_vertex(); }
};

// The angle of a triangle at q, in degrees, as CGAL's Is_saddle_vertex
// computes it (Surface_mesh_shortest_path/function_objects.h).
inline double corner_angle_degrees(const Vec3& p, const Vec3& q, const Vec3& r)
{
  const Vec3 u = p - q, v = r - q;
  const double product = std::sqrt((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  if(product == 0)
    return 0.;
  double cosine = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / product;
  cosine = (std::min)(1., (std::max)(-1., cosine));
  return std::acos(cosine) * 180. / CGAL_PI;
}

// Squared distance from p to the triangle (a, b, c) (closest point by the
// Voronoi regions of the vertices, edges and interior).
inline double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if(d1 <= 0. && d2 <= 0.)
    return squared_norm(ap);
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if(d3 >= 0. && d4 <= d3)
    return squared_norm(bp);
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0. && d1 >= 0. && d3 <= 0.)
    return squared_norm(ap - (d1 / (d1 - d3)) * ab);
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if(d6 >= 0. && d5 <= d6)
    return squared_norm(cp);
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0. && d2 >= 0. && d6 <= 0.)
    return squared_norm(ap - (d2 / (d2 - d6)) * ac);
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0. && (d4 - d3) >= 0. && (d5 - d6) >= 0.)
    return squared_norm(bp - ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b));
  const double denom = va + vb + vc;
  if(!(denom > 0.)) // degenerate triangle: nearest of its vertices
    return (std::min)({squared_norm(ap), squared_norm(bp), squared_norm(cp)});
  const double v = vb / denom, w = vc / denom;
  return squared_norm(ap - v * ab - w * ac);
}

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

// Geodesics from the centroid of one face to the centroids of its neighbours,
// inside a patch of the mesh. Holds the scratch memory of one thread: make one
// per thread and call set_source() then path_to() for each face.
//
// The patch is a CGAL::Surface_mesh copy of face i, its neighbours and
// `patch_rings` rings of faces around them (only the faces that come within
// R_i of c_i, R_i the distance to the farthest neighbour centroid), plus the
// faces around each vertex where selected faces meet only at that vertex (the
// neighbourhood grows through shared vertices), without the faces of zero area
// (zero normal in Face_data). Faces of the mesh that only share a vertex
// inside the patch are kept apart in the copy (the vertex is duplicated per
// fan of faces connected through edges), so the copy is always a manifold:
// a geodesic cannot go from one fan to another through such a vertex.
class Geodesic_patch_solver
{
  // Plain double arithmetic, without filtered predicates: CGAL's algorithm
  // constructs its unfolded points inexactly anyway (as with Epick), and the
  // filters and their exact fallbacks cost about 15% of the path time while
  // giving the same paths on the benchmark meshes. A query whose result is
  // not a plausible path is rejected (see path_to()), and an exception from
  // CGAL makes the face's paths direct, as for any neighbour no geodesic
  // reaches.
  typedef Geodesic_patch_kernel Kernel;
  typedef Geodesic_patch_mesh Patch;
  typedef Geodesic_patch_traits Traits;
  typedef CGAL::Surface_mesh_shortest_path<Traits> Shortest_path;
  typedef Patch::Vertex_index vertex_descriptor;
  typedef Patch::Halfedge_index halfedge_descriptor;
  typedef Patch::Face_index face_descriptor;
  typedef Traits::Barycentric_coordinates Barycentric_coordinates;

  // One event of CGAL's path sequence (visited from the query back to the source).
  struct Event
  {
    enum Kind { FACE, EDGE, VERTEX } kind;
    std::uint32_t near_face, far_face; // EDGE: faces on the source side and on the query side
    Vec3 point;
  };

  struct Visitor
  {
    const Geodesic_patch_solver* solver;
    std::vector<Event>* events;
    void operator()(halfedge_descriptor h, Kernel::FT t)
    {
      const Patch& p = solver->patch_;
      const Vec3 a = solver->to_vec(p.point(p.source(h))), b = solver->to_vec(p.point(p.target(h)));
      // t weighs the target of h (see Surface_mesh_shortest_path::point())
      const double s = CGAL::to_double(t);
      const face_descriptor fo = p.face(p.opposite(h));
      events->push_back({Event::EDGE, fo == Patch::null_face() ? no_face : solver->global_[std::size_t(fo)],
                         solver->global_[std::size_t(p.face(h))], (1. - s) * a + s * b});
    }
    void operator()(vertex_descriptor v)
    {
      events->push_back({Event::VERTEX, no_face, no_face, solver->to_vec(solver->patch_.point(v))});
    }
    void operator()(face_descriptor f, const Barycentric_coordinates& l)
    {
      const Patch& p = solver->patch_;
      const halfedge_descriptor h = p.halfedge(f);
      const Vec3 a = solver->to_vec(p.point(p.source(h))), b = solver->to_vec(p.point(p.target(h))),
                 c = solver->to_vec(p.point(p.target(p.next(h))));
      const std::uint32_t g = solver->global_[std::size_t(f)];
      // the barycentric coordinates of face f refer to its vertices in the
      // order source(halfedge(f)), target(halfedge(f)), target(next(...))
      events->push_back({Event::FACE, g, g,
                         CGAL::to_double(l[0]) * a + CGAL::to_double(l[1]) * b + CGAL::to_double(l[2]) * c});
    }
  };

public:
  static constexpr std::uint32_t no_face = std::uint32_t(-1);

  Geodesic_patch_solver(const Flat_mesh& m, const Face_data& fd, unsigned int patch_rings)
    : m_(m), fd_(fd), rings_(patch_rings), face_stamp_(m.number_of_faces(), no_face),
      face_local_(m.number_of_faces(), 0), vertex_stamp_(m.number_of_vertices(), no_face),
      tested_stamp_(m.number_of_faces(), no_face), bridge_stamp_(m.number_of_vertices(), no_face),
      corner_degrees_(3 * m.number_of_faces())
  {
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      for(int c = 0; c < 3; ++c)
      {
        const auto& t = m.triangles[f];
        corner_degrees_[3 * f + c] =
            corner_angle_degrees(m.points[t[(c + 2) % 3]], m.points[t[c]], m.points[t[(c + 1) % 3]]);
      }
    one_fan_.assign(m.number_of_vertices(), 0);
    for(std::uint32_t v = 0; v < m.number_of_vertices(); ++v)
    {
      fan_faces_.assign(m.vertex_faces.begin() + m.vertex_face_offsets[v],
                        m.vertex_faces.begin() + m.vertex_face_offsets[v + 1]);
      one_fan_[v] = group_fans(v) == 1;
    }
  }
  // shortest_path_ refers to patch_: neither copied nor moved
  Geodesic_patch_solver(const Geodesic_patch_solver&) = delete;
  Geodesic_patch_solver& operator=(const Geodesic_patch_solver&) = delete;

  // Builds the patch of face i with the given neighbours and the shortest-path
  // structure rooted at c_i. Returns false (every path_to() then fails) if
  // face i has zero area or the patch could not be built.
  template <typename NeighborIterator>
  bool set_source(std::uint32_t i, NeighborIterator nb, NeighborIterator ne)
  {
    source_ = i;
    ready_ = false;
    Phase_clock clock(phases_);
    shortest_path_.clear(); // frees the sequence tree of the previous face
    clock.add_to(&Geodesic_path_statistics::clear_seconds);
    patch_.resize(0, 0, 0);
    global_.clear();
    ++stamp_;
    if(stamp_ == no_face) // wrapped around: reset the stamps
    {
      std::fill(face_stamp_.begin(), face_stamp_.end(), no_face);
      std::fill(vertex_stamp_.begin(), vertex_stamp_.end(), no_face);
      std::fill(tested_stamp_.begin(), tested_stamp_.end(), no_face);
      std::fill(bridge_stamp_.begin(), bridge_stamp_.end(), no_face);
      stamp_ = 0;
    }
    if(is_degenerate(i))
      return false;
    select(i);
    const Vec3& ci = fd_.centroids[i];
    double reach2 = 0.; // squared distance to the farthest neighbour centroid
    for(NeighborIterator it = nb; it != ne; ++it)
    {
      select(*it);
      reach2 = (std::max)(reach2, squared_norm(fd_.centroids[*it] - ci));
    }
    // where selected faces meet at a vertex only (the neighbourhood grows
    // through shared vertices), the faces around that vertex are added, so
    // that the patch is connected through edges wherever the neighbourhood is
    const std::size_t selected = global_.size();
    for(std::size_t k = 0; k < selected; ++k)
      for(std::uint32_t v : m_.triangles[global_[k]])
      {
        if(bridge_stamp_[v] == stamp_)
          continue;
        bridge_stamp_[v] = stamp_;
        if(selected_fans(v) > 1)
          for(std::uint32_t q = m_.vertex_face_offsets[v]; q < m_.vertex_face_offsets[v + 1]; ++q)
            select(m_.vertex_faces[q]);
      }
    // rings: faces sharing a vertex with the patch that come within that
    // distance of c_i (any face a straight segment from c_i to a neighbour's
    // centroid crosses does)
    std::size_t ring_begin = 0;
    for(unsigned int r = 0; r < rings_; ++r)
    {
      const std::size_t ring_end = global_.size();
      for(std::size_t k = ring_begin; k < ring_end; ++k)
        for(std::uint32_t v : m_.triangles[global_[k]])
          for(std::uint32_t q = m_.vertex_face_offsets[v]; q < m_.vertex_face_offsets[v + 1]; ++q)
          {
            const std::uint32_t g = m_.vertex_faces[q];
            if(tested_stamp_[g] == stamp_)
              continue;
            tested_stamp_[g] = stamp_;
            const auto& t = m_.triangles[g];
            if(squared_distance_to_triangle(ci, m_.points[t[0]], m_.points[t[1]], m_.points[t[2]]) <= reach2)
              select(g);
          }
      ring_begin = ring_end;
    }
    const bool built = build_patch();
    clock.add_to(&Geodesic_path_statistics::patch_seconds);
    if(!built)
    {
      patch_.resize(0, 0, 0);
      global_.clear();
      return false;
    }
    try
    {
      shortest_path_.add_source_point(face_descriptor(0), centroid_location());
      shortest_path_.build_sequence_tree();
    }
    catch(const std::exception&) // CGAL::Failure_exception derives from it
    {
      shortest_path_.clear();
      return false;
    }
    clock.add_to(&Geodesic_path_statistics::tree_seconds);
    ready_ = true;
    return true;
  }

  // Whether path_to() fills Geodesic_path::points (default true; the forest
  // does not need them).
  void set_collect_points(bool b) { points_ = b; }

  // Where set_source() and path_to() add the seconds of their phases (the
  // *_seconds fields of Geodesic_path_statistics); nullptr (default): not
  // timed.
  void set_phase_statistics(Geodesic_path_statistics* s) { phases_ = s; }

  // The geodesic from c_i to c_j inside the patch. Returns false if j is not
  // in the patch or not reachable from c_i inside it, or if CGAL's answer is
  // not a plausible path (an exception, a distance that is negative, not
  // finite or shorter than |c_j - c_i|, a sequence not from face j to face i).
  bool path_to(std::uint32_t j, Geodesic_path& out)
  {
    out.faces.clear();
    out.lengths.clear();
    out.points.clear();
    out.vertex_passages = 0;
    if(!ready_ || j >= face_stamp_.size() || face_stamp_[j] != stamp_ || j == source_)
      return false;
    events_.clear();
    Visitor visitor{this, &events_};
    double distance = -1.;
    Phase_clock clock(phases_);
    try
    {
      distance = CGAL::to_double(shortest_path_
                                     .shortest_path_sequence_to_source_points(face_descriptor(face_local_[j]),
                                                                              centroid_location(), visitor)
                                     .first);
    }
    catch(const std::exception&)
    {
      return false;
    }
    clock.add_to(&Geodesic_path_statistics::query_seconds);
    if(!(distance >= 0.) || !std::isfinite(distance) || events_.size() < 2 || events_.front().kind != Event::FACE ||
       events_.back().kind != Event::FACE || events_.back().far_face != source_)
      return false;
    // no path on the surface is shorter than the straight segment: a shorter
    // one comes from a numerical failure
    if(distance < (1. - 1e-9) * norm(fd_.centroids[j] - fd_.centroids[source_]))
      return false;
    return trace(j, out);
  }

private:
  bool is_degenerate(std::uint32_t f) const { return squared_norm(fd_.normals[f]) == 0.; }

  static Barycentric_coordinates centroid_location()
  {
    return {{Kernel::FT(1. / 3.), Kernel::FT(1. / 3.), Kernel::FT(1. / 3.)}};
  }

  Vec3 to_vec(const Kernel::Point_3& p) const { return {p.x(), p.y(), p.z()}; }

  void select(std::uint32_t f)
  {
    if(face_stamp_[f] == stamp_ || is_degenerate(f))
      return;
    face_stamp_[f] = stamp_;
    face_local_[f] = std::uint32_t(global_.size());
    global_.push_back(f);
  }

  // Groups the selected faces around v (in fan_faces_) into fans of faces
  // connected through edges (v, w) (fan_find() gives a fan's representative);
  // returns the number of fans.
  std::size_t selected_fans(std::uint32_t v)
  {
    fan_faces_.clear();
    for(std::uint32_t q = m_.vertex_face_offsets[v]; q < m_.vertex_face_offsets[v + 1]; ++q)
    {
      const std::uint32_t g = m_.vertex_faces[q];
      if(face_stamp_[g] == stamp_)
        fan_faces_.push_back(g);
    }
    const std::size_t n = fan_faces_.size();
    fan_root_.resize(n);
    // all the faces around a vertex whose faces form one fan: one fan (the
    // common case, inside the patch)
    if(one_fan_[v] && n == m_.vertex_face_offsets[v + 1] - m_.vertex_face_offsets[v])
    {
      std::fill(fan_root_.begin(), fan_root_.end(), std::size_t(0));
      return n == 0 ? 0 : 1;
    }
    return group_fans(v);
  }

  // Union-find of fan_faces_ (around v) by shared edges; returns the number of fans.
  std::size_t group_fans(std::uint32_t v)
  {
    const std::size_t n = fan_faces_.size();
    fan_root_.resize(n);
    for(std::size_t a = 0; a < n; ++a)
      fan_root_[a] = a;
    std::size_t fans = n;
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = a + 1; b < n; ++b)
        if(share_edge_at(fan_faces_[a], fan_faces_[b], v))
        {
          const std::size_t ra = fan_find(a), rb = fan_find(b);
          if(ra != rb)
          {
            fan_root_[ra] = rb;
            --fans;
          }
        }
    return fans;
  }

  std::size_t fan_find(std::size_t a)
  {
    while(fan_root_[a] != a)
      a = fan_root_[a] = fan_root_[fan_root_[a]];
    return a;
  }

  // Copies the selected faces into patch_, one vertex copy per fan of
  // selected faces around each mesh vertex; local face k is global_[k]. The
  // halfedge structure is built directly (the copy is a manifold by
  // construction), in patch_'s memory of the previous face (no allocation
  // once it is large enough). Returns false if an edge would get two faces
  // on one side or a vertex two border gaps (not expected; the patch then
  // fails and its paths are direct).
  bool build_patch()
  {
    const std::size_t nf = global_.size();
    corner_.assign(3 * nf, 0);
    angle_sum_.clear();
    vertex_points_.clear();
    for(std::size_t k = 0; k < nf; ++k)
      for(int c = 0; c < 3; ++c)
      {
        const std::uint32_t v = m_.triangles[global_[k]][c];
        if(vertex_stamp_[v] == stamp_)
          continue;
        vertex_stamp_[v] = stamp_;
        selected_fans(v);
        const std::size_t n = fan_faces_.size();
        fan_vertex_.assign(n, vertex_descriptor());
        const Vec3& p = m_.points[v];
        for(std::size_t a = 0; a < n; ++a)
        {
          const std::size_t r = fan_find(a);
          if(fan_vertex_[r] == vertex_descriptor())
          {
            fan_vertex_[r] = vertex_descriptor(std::uint32_t(vertex_points_.size()));
            vertex_points_.push_back(p);
            angle_sum_.push_back(0.);
          }
          const std::uint32_t g = fan_faces_[a];
          const auto& t = m_.triangles[g];
          const int cg = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
          corner_[3 * face_local_[g] + cg] = std::uint32_t(fan_vertex_[r]);
          angle_sum_[std::size_t(fan_vertex_[r])] += corner_degrees_[3 * g + cg];
        }
      }
    // the elements are made by one resize of patch_'s arrays (in the memory
    // of the previous patch), with room for 3 nf edges, cut down to the
    // edges made at the end
    const std::size_t nv = vertex_points_.size();
    patch_.resize(0, 0, 0);
    patch_.resize(nv, 3 * nf, nf);
    for(std::size_t v = 0; v < nv; ++v)
      patch_.point(vertex_descriptor(std::uint32_t(v))) =
          Kernel::Point_3(vertex_points_[v][0], vertex_points_[v][1], vertex_points_[v][2]);
    // halfedges: out_first_[v] / out_next_[h] list the halfedges leaving v
    out_first_.assign(nv, no_face);
    out_next_.assign(6 * nf, no_face);
    std::size_t ne = 0;
    const halfedge_descriptor null_h = Patch::null_halfedge();
    for(std::size_t k = 0; k < nf; ++k)
    {
      const face_descriptor f = face_descriptor(std::uint32_t(k));
      std::array<halfedge_descriptor, 3> h;
      for(int c = 0; c < 3; ++c)
      {
        const std::uint32_t a = corner_[3 * k + c], b = corner_[3 * k + (c + 1) % 3];
        if(a == b)
          return false;
        h[c] = null_h;
        for(std::uint32_t e = out_first_[a]; e != no_face; e = out_next_[e])
          if(std::uint32_t(patch_.target(halfedge_descriptor(e))) == b)
          {
            h[c] = halfedge_descriptor(e);
            break;
          }
        if(h[c] == null_h)
        {
          h[c] = halfedge_descriptor(std::uint32_t(2 * ne++));
          const halfedge_descriptor o = patch_.opposite(h[c]);
          patch_.set_target(h[c], vertex_descriptor(b));
          patch_.set_target(o, vertex_descriptor(a));
          patch_.set_face(o, Patch::null_face());
          out_next_[std::size_t(h[c])] = out_first_[a];
          out_first_[a] = std::uint32_t(h[c]);
          out_next_[std::size_t(o)] = out_first_[b];
          out_first_[b] = std::uint32_t(o);
        }
        else if(patch_.face(h[c]) != Patch::null_face())
          return false;
      }
      for(int c = 0; c < 3; ++c)
      {
        patch_.set_next(h[c], h[(c + 1) % 3]);
        patch_.set_face(h[c], f);
        patch_.set_halfedge(patch_.target(h[c]), h[c]);
      }
      patch_.set_halfedge(f, h[2]); // as Euler::add_face: the halfedge into the first corner
    }
    patch_.resize(nv, ne, nf);
    // border halfedges: the next one leaves the vertex this one enters; a
    // border vertex refers to its incoming border halfedge
    border_out_.assign(nv, no_face);
    const std::size_t nh = patch_.number_of_halfedges();
    for(std::size_t e = 0; e < nh; ++e)
      if(patch_.face(halfedge_descriptor(e)) == Patch::null_face())
      {
        std::uint32_t& out = border_out_[std::size_t(patch_.source(halfedge_descriptor(e)))];
        if(out != no_face)
          return false;
        out = std::uint32_t(e);
      }
    for(std::size_t e = 0; e < nh; ++e)
      if(patch_.face(halfedge_descriptor(e)) == Patch::null_face())
      {
        const vertex_descriptor v = patch_.target(halfedge_descriptor(e));
        patch_.set_next(halfedge_descriptor(e), halfedge_descriptor(border_out_[std::size_t(v)]));
        patch_.set_halfedge(v, halfedge_descriptor(e));
      }
    // pseudo-sources (see Geodesic_patch_mesh): saddles as CGAL tests them,
    // border vertices where the interior angle is not below pi
    patch_.border.assign(nv, 0);
    patch_.pseudo_source.assign(nv, 0);
    const double saddle_bound = (1. - 100. * std::numeric_limits<double>::epsilon()) * 2 * CGAL_PI;
    for(std::size_t v = 0; v < nv; ++v)
    {
      const double angle = angle_sum_[v] * (CGAL_PI / 180.);
      patch_.border[v] = border_out_[v] != no_face;
      patch_.pseudo_source[v] = patch_.border[v] ? angle >= (1. - 1e-9) * CGAL_PI : angle >= saddle_bound;
    }
    return true;
  }

  bool share_edge_at(std::uint32_t f, std::uint32_t g, std::uint32_t v) const
  {
    const auto& a = m_.triangles[f];
    const auto& b = m_.triangles[g];
    for(std::uint32_t x : a)
      if(x != v && (b[0] == x || b[1] == x || b[2] == x))
        return true;
    return false;
  }

  // Turns the events (from c_j back to c_i) into faces crossed, lengths and
  // points, from i to j. The geodesic's segment between two consecutive
  // events lies in one face: before an edge crossing (towards c_j) in the
  // face on the query side, after it in the face on the source side. At a
  // vertex, the faces around it are not crossed; the path goes on in the
  // face of the next edge crossing (or face i).
  bool trace(std::uint32_t j, Geodesic_path& out)
  {
    portions_.clear();
    out.points.clear();
    std::uint32_t current = events_.front().far_face; // face j
    double run = 0.;
    Vec3 last = events_.front().point;
    if(points_)
      out.points.push_back(last);
    auto close = [&]() {
      if(current != no_face)
        portions_.emplace_back(current, run);
      run = 0.;
    };
    for(std::size_t k = 1; k < events_.size(); ++k)
    {
      const Event& e = events_[k];
      if(e.kind == Event::EDGE)
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
      else if(e.kind == Event::VERTEX)
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
      if(points_)
        out.points.push_back(last);
    }
    std::reverse(out.points.begin(), out.points.end());
    double total = 0.;
    for(const auto& p : portions_)
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
    // from i to j: drop the faces only touched (at a vertex or an edge end),
    // merge repeats, and make sure the path runs from i to j
    for(std::size_t k = portions_.size(); k-- > 0;)
    {
      const auto& p = portions_[k];
      const bool end = k == 0 || k + 1 == portions_.size();
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
    if(out.faces.empty() || out.faces.front() != source_)
    {
      out.faces.insert(out.faces.begin(), source_);
      out.lengths.insert(out.lengths.begin(), 0.);
    }
    // the path ends at the first time it reaches j
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
    return true;
  }

  const Flat_mesh& m_;
  const Face_data& fd_;
  unsigned int rings_;
  std::uint32_t stamp_ = 0;
  std::uint32_t source_ = no_face;
  std::vector<std::uint32_t> face_stamp_, face_local_, vertex_stamp_, tested_stamp_, bridge_stamp_;
  std::vector<std::uint32_t> global_; // local face -> mesh face
  std::vector<std::uint32_t> corner_; // local face corner -> patch vertex
  std::vector<std::uint32_t> fan_faces_;
  std::vector<std::size_t> fan_root_;
  std::vector<vertex_descriptor> fan_vertex_;
  std::vector<std::uint32_t> out_first_, out_next_, border_out_;
  std::vector<char> one_fan_;          // by mesh vertex: its faces are connected through edges around it
  std::vector<double> corner_degrees_; // by mesh face corner: angle (CGAL's formula)
  std::vector<double> angle_sum_;      // by patch vertex: sum of its corner angles in the patch, degrees
  std::vector<Vec3> vertex_points_;    // by patch vertex
  std::vector<Event> events_;
  std::vector<std::pair<std::uint32_t, double>> portions_;
  Patch patch_;
  // built once on patch_, which it refers to; cleared and rebuilt per face
  Shortest_path shortest_path_{patch_};
  bool ready_ = false;
  bool points_ = true;
  Geodesic_path_statistics* phases_ = nullptr;
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
  const std::size_t nf = m.number_of_faces();
  struct Chunk
  {
    std::vector<std::uint32_t> face;
    std::vector<std::int32_t> parent;
    std::vector<char> weighted;
    std::vector<double> step;
    Geodesic_path_statistics statistics;
  };
  const std::size_t chunk_size = 32;
  const std::size_t nchunks = (nf + chunk_size - 1) / chunk_size;
  std::vector<Chunk> chunks(nchunks);
  std::vector<std::uint32_t> counts(nf, 0);
  const double unit = options.length_unit > 0. ? options.length_unit : 1.;

  // one solver per thread (its stamps are as large as the mesh), made on the
  // thread's first chunk and kept for its next ones
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<std::unique_ptr<Geodesic_patch_solver>> solvers;
#endif
  for_each_chunk<ConcurrencyTag>(
      nchunks,
      [&](std::size_t cb, std::size_t ce) {
#ifdef CGAL_LINKED_WITH_TBB
        std::unique_ptr<Geodesic_patch_solver>& solver_ptr = solvers.local();
#else
        std::unique_ptr<Geodesic_patch_solver> solver_ptr;
#endif
        if(!solver_ptr)
        {
          solver_ptr.reset(new Geodesic_patch_solver(m, fd, options.patch_rings));
          solver_ptr->set_collect_points(false);
        }
        Geodesic_patch_solver& solver = *solver_ptr;
        // the phase seconds of this call go to its first chunk's statistics
        solver.set_phase_statistics(options.time_phases ? &chunks[cb].statistics : nullptr);
        std::vector<Geodesic_path> paths;
        std::vector<char> reached;
        std::vector<std::pair<double, std::size_t>> order;
        std::vector<std::int32_t> first_child, next_sibling;
        for(std::size_t c = cb; c < ce; ++c)
        {
          Chunk& chunk = chunks[c];
          const std::size_t last = (std::min)(nf, (c + 1) * chunk_size);
          for(std::size_t i = c * chunk_size; i < last; ++i)
          {
            const std::uint32_t nb = neighbors.begin(i), ne = neighbors.end(i);
            const std::size_t n = ne - nb;
            const std::size_t start = chunk.face.size();
            if(n == 0)
            {
              counts[i] = 0;
              continue;
            }
            const bool patch_ok =
                solver.set_source(std::uint32_t(i), neighbors.items.begin() + nb, neighbors.items.begin() + ne);
            if(!patch_ok)
              ++chunk.statistics.failed_patches;
            if(paths.size() < n)
              paths.resize(n);
            reached.assign(n, 0);
            order.clear();
            for(std::size_t k = 0; k < n; ++k)
            {
              const std::uint32_t j = neighbors.items[nb + k];
              reached[k] = patch_ok && solver.path_to(j, paths[k]) ? 1 : 0;
              const double len = reached[k] ? paths[k].length() : norm(fd.centroids[j] - fd.centroids[i]);
              order.emplace_back(len, k);
              ++chunk.statistics.paths;
              if(!reached[k])
                ++chunk.statistics.fallbacks;
              else if(paths[k].vertex_passages > 0)
                ++chunk.statistics.vertex_passages;
            }
            std::sort(order.begin(), order.end());
            first_child.clear();
            next_sibling.clear();
            std::int32_t root_first_child = -1;
            // adds (or finds) the child of `parent` (local index or root) with face f
            auto child = [&](std::int32_t parent, std::uint32_t f, double step, bool& created) {
              std::int32_t k = parent == Path_forest::root ? root_first_child : first_child[parent];
              for(; k != -1; k = next_sibling[k])
                if(chunk.face[start + k] == f)
                {
                  created = false;
                  return k;
                }
              created = true;
              const std::int32_t id = std::int32_t(chunk.face.size() - start);
              chunk.face.push_back(f);
              chunk.parent.push_back(parent);
              chunk.weighted.push_back(0);
              chunk.step.push_back(step);
              first_child.push_back(-1);
              std::int32_t& head = parent == Path_forest::root ? root_first_child : first_child[parent];
              next_sibling.push_back(head);
              head = id;
              return id;
            };
            for(const auto& o : order)
            {
              const std::size_t k = o.second;
              const std::uint32_t j = neighbors.items[nb + k];
              bool created = false;
              std::int32_t node = Path_forest::root;
              if(reached[k])
              {
                const Geodesic_path& p = paths[k];
                for(std::size_t x = 1; x < p.faces.size(); ++x)
                  node = child(node, p.faces[x], geodesic_step(p, x) / unit, created);
              }
              else
                node = child(Path_forest::root, j, o.first / unit, created);
              chunk.weighted[start + node] = 1;
            }
            counts[i] = std::uint32_t(chunk.face.size() - start);
          }
        }
      },
      1);

  Path_forest forest;
  forest.offsets.assign(nf + 1, 0);
  for(std::size_t f = 0; f < nf; ++f)
    forest.offsets[f + 1] = forest.offsets[f] + counts[f];
  const std::size_t total = forest.offsets[nf];
  forest.face.reserve(total);
  forest.parent.reserve(total);
  forest.weighted.reserve(total);
  if(options.step_length)
    forest.step.reserve(total);
  Geodesic_path_statistics stats;
  for(const Chunk& c : chunks)
  {
    forest.face.insert(forest.face.end(), c.face.begin(), c.face.end());
    forest.parent.insert(forest.parent.end(), c.parent.begin(), c.parent.end());
    forest.weighted.insert(forest.weighted.end(), c.weighted.begin(), c.weighted.end());
    if(options.step_length)
      forest.step.insert(forest.step.end(), c.step.begin(), c.step.end());
    stats.add(c.statistics);
  }
  if(statistics)
    *statistics = stats;
  return forest;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
