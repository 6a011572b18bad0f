// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Geodesics from the centroid of a face to the centroids of its neighbours
// on a small patch copy of the mesh (Geodesic_patch_solver): the patch's
// faces are selected, copied into a Geodesic_patch_mesh, and CGAL's
// Surface_mesh_shortest_path answers the queries.

#ifndef CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATCH_SOLVER_H
#define CGAL_PMP_INTERNAL_DENOISING_GEODESIC_PATCH_SOLVER_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/vec3.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/vertex_fans.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/geodesic_patch_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/geodesic_path.h>

#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

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

  typedef Geodesic_event Event;

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
      events->push_back(
          {Event::FACE, g, g, CGAL::to_double(l[0]) * a + CGAL::to_double(l[1]) * b + CGAL::to_double(l[2]) * c});
    }
  };

public:
  static constexpr std::uint32_t no_face = std::uint32_t(-1);

  Geodesic_patch_solver(const Flat_mesh& m, const Face_data& fd, unsigned int patch_rings)
      : m_(m), fd_(fd), rings_(patch_rings), face_stamp_(m.number_of_faces(), no_face),
        face_local_(m.number_of_faces(), 0), vertex_stamp_(m.number_of_vertices(), no_face),
        tested_stamp_(m.number_of_faces(), no_face), bridge_stamp_(m.number_of_vertices(), no_face), fans_(m),
        corner_degrees_(3 * m.number_of_faces())
  {
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      for(int c = 0; c < 3; ++c)
      {
        const auto& t = m.triangles[f];
        corner_degrees_[3 * f + c] =
            corner_angle_degrees(m.points[t[(c + 2) % 3]], m.points[t[c]], m.points[t[(c + 1) % 3]]);
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
    next_stamp();
    if(is_degenerate(i))
      return false;
    const double reach2 = select_neighborhood(i, nb, ne);
    bridge_vertex_contacts();
    add_rings(fd_.centroids[i], reach2);
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
      distance = CGAL::to_double(
          shortest_path_
              .shortest_path_sequence_to_source_points(face_descriptor(face_local_[j]), centroid_location(), visitor)
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
    return trace_geodesic_path(events_, source_, j, points_, portions_, out);
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

  // A new stamp for the face about to be set up (all stamps reset when the
  // counter wraps around).
  void next_stamp()
  {
    ++stamp_;
    if(stamp_ == no_face)
    {
      std::fill(face_stamp_.begin(), face_stamp_.end(), no_face);
      std::fill(vertex_stamp_.begin(), vertex_stamp_.end(), no_face);
      std::fill(tested_stamp_.begin(), tested_stamp_.end(), no_face);
      std::fill(bridge_stamp_.begin(), bridge_stamp_.end(), no_face);
      stamp_ = 0;
    }
  }

  // Selects face i and its neighbours; returns the squared distance from c_i
  // to the farthest neighbour centroid.
  template <typename NeighborIterator>
  double select_neighborhood(std::uint32_t i, NeighborIterator nb, NeighborIterator ne)
  {
    select(i);
    const Vec3& ci = fd_.centroids[i];
    double reach2 = 0.;
    for(NeighborIterator it = nb; it != ne; ++it)
    {
      select(*it);
      reach2 = (std::max)(reach2, squared_norm(fd_.centroids[*it] - ci));
    }
    return reach2;
  }

  // Where selected faces meet at a vertex only (the neighbourhood grows
  // through shared vertices), selects the faces around that vertex, so that
  // the patch is connected through edges wherever the neighbourhood is.
  void bridge_vertex_contacts()
  {
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
  }

  // The rings: faces sharing a vertex with the patch that come within
  // sqrt(reach2) of ci (any face a straight segment from c_i to a
  // neighbour's centroid crosses does), `rings_` times.
  void add_rings(const Vec3& ci, double reach2)
  {
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
  }

  // Groups the selected faces around v into fans (in fans_); returns their number.
  std::size_t selected_fans(std::uint32_t v)
  {
    return fans_.group_selected(v, [this](std::uint32_t g) { return face_stamp_[g] == stamp_; });
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
    copy_vertices();
    const std::size_t nv = vertex_points_.size(), nf = global_.size();
    // the elements are made by one resize of patch_'s arrays (in the memory
    // of the previous patch), with room for 3 nf edges, cut down to the
    // edges made at the end
    patch_.resize(0, 0, 0);
    patch_.resize(nv, 3 * nf, nf);
    for(std::size_t v = 0; v < nv; ++v)
      patch_.point(vertex_descriptor(std::uint32_t(v))) =
          Kernel::Point_3(vertex_points_[v][0], vertex_points_[v][1], vertex_points_[v][2]);
    std::size_t ne = 0;
    if(!link_faces(ne))
      return false;
    patch_.resize(nv, ne, nf);
    if(!link_border())
      return false;
    flag_pseudo_sources();
    return true;
  }

  // The patch vertices: one copy of each mesh vertex per fan of selected
  // faces around it (`vertex_points_`), the patch vertex of each local face
  // corner (`corner_`) and the angle sum at each patch vertex.
  void copy_vertices()
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
        const std::size_t n = fans_.size();
        fan_vertex_.assign(n, vertex_descriptor());
        const Vec3& p = m_.points[v];
        for(std::size_t a = 0; a < n; ++a)
        {
          const std::size_t r = fans_.find(a);
          if(fan_vertex_[r] == vertex_descriptor())
          {
            fan_vertex_[r] = vertex_descriptor(std::uint32_t(vertex_points_.size()));
            vertex_points_.push_back(p);
            angle_sum_.push_back(0.);
          }
          const std::uint32_t g = fans_.face(a);
          const auto& t = m_.triangles[g];
          const int cg = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
          corner_[3 * face_local_[g] + cg] = std::uint32_t(fan_vertex_[r]);
          angle_sum_[std::size_t(fan_vertex_[r])] += corner_degrees_[3 * g + cg];
        }
      }
  }

  // The faces' halfedges, an edge made at the first of its two faces
  // (`ne` counts them); out_first_[v] / out_next_[h] list the halfedges
  // leaving v. False if a face has two equal corners or an edge two faces on
  // one side.
  bool link_faces(std::size_t& ne)
  {
    const std::size_t nv = vertex_points_.size(), nf = global_.size();
    out_first_.assign(nv, no_face);
    out_next_.assign(6 * nf, no_face);
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
    return true;
  }

  // Border halfedges: the next one leaves the vertex this one enters; a
  // border vertex refers to its incoming border halfedge. False if a vertex
  // has two border gaps.
  bool link_border()
  {
    border_out_.assign(vertex_points_.size(), no_face);
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
    return true;
  }

  // Pseudo-sources (see Geodesic_patch_mesh): saddles as CGAL tests them,
  // border vertices where the interior angle is not below pi.
  void flag_pseudo_sources()
  {
    const std::size_t nv = vertex_points_.size();
    patch_.border.assign(nv, 0);
    patch_.pseudo_source.assign(nv, 0);
    const double saddle_bound = (1. - 100. * std::numeric_limits<double>::epsilon()) * 2 * CGAL_PI;
    for(std::size_t v = 0; v < nv; ++v)
    {
      const double angle = angle_sum_[v] * (CGAL_PI / 180.);
      patch_.border[v] = border_out_[v] != no_face;
      patch_.pseudo_source[v] = patch_.border[v] ? angle >= (1. - 1e-9) * CGAL_PI : angle >= saddle_bound;
    }
  }

  const Flat_mesh& m_;
  const Face_data& fd_;
  unsigned int rings_;
  std::uint32_t stamp_ = 0;
  std::uint32_t source_ = no_face;
  std::vector<std::uint32_t> face_stamp_, face_local_, vertex_stamp_, tested_stamp_, bridge_stamp_;
  std::vector<std::uint32_t> global_; // local face -> mesh face
  std::vector<std::uint32_t> corner_; // local face corner -> patch vertex
  Vertex_fans fans_;
  std::vector<vertex_descriptor> fan_vertex_;
  std::vector<std::uint32_t> out_first_, out_next_, border_out_;
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

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
