// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A seeded simulation of a consumer structured-light / stereo depth camera
// (Kinect v1 like) scanning a triangle mesh, for tests and benchmarks on
// scanner-like noise:
//   - a pinhole camera; every pixel's ray is cast against the mesh (AABB tree)
//     and gives the true depth z along the optical axis;
//   - noise in the disparity domain d = f b / z: white Gaussian noise per pixel
//     averaged over a block-matching window (so errors are correlated over the
//     window), scaled to a standard deviation of sigma_d pixels, plus sub-pixel
//     quantisation of d; the noisy depth is f b / d', so depth noise grows as z^2;
//   - dropouts at grazing angles and at depth discontinuities;
//   - the depth image meshed like scanners do (grid, two triangles a quad,
//     long edges dropped), twice: at the noisy and at the true depth, with the
//     same vertices and faces.
// The baseline b is a fraction of the camera's distance to its target, so the
// model is scale-free: its noise, in pixel footprints, does not depend on the
// mesh's size nor on the image's resolution.

#ifndef DENOISING_SUPPORT_DEPTH_SCAN_SIMULATION_H
#define DENOISING_SUPPORT_DEPTH_SCAN_SIMULATION_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace denoising_support {

using Scan_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Scan_point = Scan_kernel::Point_3;
using Scan_vector = Scan_kernel::Vector_3;
using Scan_mesh = CGAL::Surface_mesh<Scan_point>;

// A pinhole camera: `eye` looks at `target`; `up` fixes the roll. Square
// pixels; the focal length in pixels follows from the horizontal field of view.
struct Depth_camera
{
  Scan_point eye = Scan_point(0, 0, 1);
  Scan_point target = Scan_point(0, 0, 0);
  Scan_vector up = Scan_vector(0, 1, 0);
  int width = 160, height = 120;
  double horizontal_fov_degrees = 57.;

  double focal_length() const
  {
    return 0.5 * width / std::tan(0.5 * horizontal_fov_degrees * 3.14159265358979323846 / 180.);
  }
};

// The camera's orthonormal frame: `right`, `down` (image x and y) and `forward`.
struct Camera_frame
{
  Scan_vector right, down, forward;
  double f = 1.;

  explicit Camera_frame(const Depth_camera& c) : f(c.focal_length())
  {
    forward = c.target - c.eye;
    const double l = std::sqrt(forward.squared_length());
    if(!(l > 0.))
      throw std::invalid_argument("Depth_camera: the eye and the target coincide.");
    forward = forward / l;
    right = CGAL::cross_product(forward, c.up);
    const double r = std::sqrt(right.squared_length());
    if(!(r > 1e-12))
      throw std::invalid_argument("Depth_camera: the up vector is parallel to the viewing direction.");
    right = right / r;
    down = CGAL::cross_product(forward, right);
  }

  // The ray direction of pixel (i, j) (its centre), scaled so that its
  // component along `forward` is 1: the point at depth z is eye + z * ray.
  Scan_vector ray(const Depth_camera& c, int i, int j) const
  {
    const double x = (i + 0.5 - 0.5 * c.width) / f, y = (j + 0.5 - 0.5 * c.height) / f;
    return forward + x * right + y * down;
  }
};

struct Depth_scan_options
{
  double sigma_disparity = 0.1;         // sigma_d: std of the disparity error, pixels
  int window = 9;                       // side of the block-matching (box) window, pixels; 1: white noise
  double quantisation = 0.125;          // sub-pixel step of the disparity, pixels; 0: none
  double baseline_ratio = 0.094;        // b / (distance eye-target); Kinect v1: 75 mm at 0.8 m
  double grazing_cosine = 0.17;         // pixels whose |cos(ray, normal)| is below are dropped
  double edge_factor = 3.5;             // a triangle edge longer than this many pixel footprints drops it
  std::size_t min_component_faces = 20; // smaller components are dropped
  std::uint64_t seed = 0;
};

struct Depth_scan_result
{
  Scan_mesh noisy, ground_truth; // same vertices (same order) and faces
  Scan_point camera_centre;
  Scan_vector forward; // the optical axis
  std::size_t pixels = 0, pixels_hit = 0;
  std::size_t dropped_grazing = 0, dropped_discontinuity = 0; // among the pixels hit
  std::size_t duplicated_vertices = 0, dropped_small_faces = 0;
};

// A camera on a sphere around the centre of `tmesh`'s bounding box, seeing it
// from (azimuth, elevation) in degrees (z up; elevation 90 looks down the z
// axis), at the distance where the bounding sphere spans `fill` of the image's
// height.
template <typename TriangleMesh>
Depth_camera frame_camera(const TriangleMesh& tmesh, double azimuth_degrees, double elevation_degrees, int width = 160,
                          int height = 120, double horizontal_fov_degrees = 57., double fill = 1.35)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(tmesh);
  Depth_camera c;
  c.width = width;
  c.height = height;
  c.horizontal_fov_degrees = horizontal_fov_degrees;
  c.target = Scan_point(0.5 * (b.xmin() + b.xmax()), 0.5 * (b.ymin() + b.ymax()), 0.5 * (b.zmin() + b.zmax()));
  const double dx = b.xmax() - b.xmin(), dy = b.ymax() - b.ymin(), dz = b.zmax() - b.zmin();
  const double radius = 0.5 * std::sqrt(dx * dx + dy * dy + dz * dz);
  const double half_vertical = std::atan(0.5 * height / c.focal_length());
  const double distance = radius / (fill * std::tan(half_vertical));
  const double pi = 3.14159265358979323846;
  const double az = azimuth_degrees * pi / 180., el = elevation_degrees * pi / 180.;
  const Scan_vector dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  c.eye = c.target + distance * dir;
  c.up = std::abs(std::sin(el)) > 0.99 ? Scan_vector(0, 1, 0) : Scan_vector(0, 0, 1);
  return c;
}

namespace internal {

// The disparity error field: per pixel, the mean of white Gaussian samples
// over a window x window box, scaled to standard deviation sigma.
inline std::vector<double> window_disparity_errors(int width, int height, int window, double sigma, std::uint64_t seed)
{
  const int w = std::max(window, 1), W = width + w - 1, H = height + w - 1;
  CGAL::Polygon_mesh_processing::internal::Denoising::Seeded_gaussian gaussian(seed);
  std::vector<double> white(std::size_t(W) * H);
  for(double& x : white)
    x = gaussian();
  std::vector<double> rows(std::size_t(W) * height, 0.); // vertical sums
  for(int j = 0; j < height; ++j)
    for(int i = 0; i < W; ++i)
    {
      double s = 0.;
      for(int k = 0; k < w; ++k)
        s += white[std::size_t(j + k) * W + i];
      rows[std::size_t(j) * W + i] = s;
    }
  std::vector<double> e(std::size_t(width) * height, 0.);
  const double scale = sigma / double(w); // the sum of w^2 unit samples has std w
  for(int j = 0; j < height; ++j)
    for(int i = 0; i < width; ++i)
    {
      double s = 0.;
      for(int k = 0; k < w; ++k)
        s += rows[std::size_t(j) * W + i + k];
      e[std::size_t(j) * width + i] = scale * s;
    }
  return e;
}

struct Depth_image
{
  std::vector<double> depth;        // true depth along the axis, 0 if no hit
  std::vector<double> cosine;       // |cos| between the ray and the hit face's normal
  std::vector<unsigned char> valid; // kept pixels
};

template <typename TriangleMesh>
Depth_image cast_rays(const TriangleMesh& tmesh, const Depth_camera& c, const Camera_frame& frame)
{
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Scan_kernel, Primitive>>;
  Tree tree(faces(tmesh).first, faces(tmesh).second, tmesh);
  tree.accelerate_distance_queries();
  const std::size_t n = std::size_t(c.width) * c.height;
  Depth_image im;
  im.depth.assign(n, 0.);
  im.cosine.assign(n, 0.);
  const auto vpm = get(CGAL::vertex_point, tmesh);
  for(int j = 0; j < c.height; ++j)
    for(int i = 0; i < c.width; ++i)
    {
      const Scan_vector r = frame.ray(c, i, j);
      const auto hit = tree.first_intersection(Scan_kernel::Ray_3(c.eye, r));
      if(!hit)
        continue;
      const Scan_point* p = boost::get<Scan_point>(&hit->first);
      if(p == nullptr) // the ray runs inside a face: grazing
        continue;
      const auto h = halfedge(hit->second, tmesh);
      const Scan_point a = get(vpm, source(h, tmesh)), b = get(vpm, target(h, tmesh)),
                       d = get(vpm, target(next(h, tmesh), tmesh));
      const Scan_vector normal = CGAL::cross_product(b - a, d - a);
      const double nl = std::sqrt(normal.squared_length()), rl = std::sqrt(r.squared_length());
      const std::size_t k = std::size_t(j) * c.width + i;
      im.depth[k] = (*p - c.eye) * frame.forward;
      im.cosine[k] = nl > 0. ? std::abs(normal * r) / (nl * rl) : 0.;
    }
  return im;
}

// Grid triangles of the valid pixels, oriented towards the camera, whose
// edges are at most edge_factor pixel footprints long (at the true depth).
inline std::vector<std::array<std::size_t, 3>> grid_triangles(const Depth_camera& c, const Depth_image& im,
                                                              const std::vector<Scan_point>& truth, double edge_factor,
                                                              double f)
{
  std::vector<std::array<std::size_t, 3>> tris;
  auto short_enough = [&](std::size_t a, std::size_t b) {
    const double z = std::max(im.depth[a], im.depth[b]), limit = edge_factor * z / f;
    return CGAL::squared_distance(truth[a], truth[b]) <= limit * limit;
  };
  auto add = [&](std::size_t a, std::size_t b, std::size_t d) {
    if(im.valid[a] && im.valid[b] && im.valid[d] && short_enough(a, b) && short_enough(b, d) && short_enough(d, a))
      tris.push_back({a, b, d});
  };
  const std::size_t w = std::size_t(c.width);
  for(int j = 0; j + 1 < c.height; ++j)
    for(int i = 0; i + 1 < c.width; ++i)
    {
      const std::size_t p00 = j * w + i, p10 = p00 + 1, p01 = p00 + w, p11 = p01 + 1;
      // image x right, y down: (p00, p11, p10) is counter-clockwise seen from the eye
      add(p00, p11, p10);
      add(p00, p01, p11);
    }
  return tris;
}

inline std::size_t find_root(std::vector<std::size_t>& parent, std::size_t x)
{
  while(parent[x] != x)
    x = parent[x] = parent[parent[x]];
  return x;
}

// Splits every vertex whose incident triangles form several fans (they only
// touch at the vertex) into one vertex per fan: appends to `source_pixel` the
// pixel of each new vertex and renumbers the triangles. Returns the number of
// vertices added.
inline std::size_t split_non_manifold_vertices(std::vector<std::array<std::size_t, 3>>& tris,
                                               std::vector<std::size_t>& source_pixel)
{
  const std::size_t nv = source_pixel.size();
  std::vector<std::size_t> start(nv + 1, 0);
  for(const auto& t : tris)
    for(std::size_t v : t)
      ++start[v + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::size_t> incident(start.back()), fill(start.begin(), start.end() - 1);
  for(std::size_t t = 0; t < tris.size(); ++t)
    for(std::size_t v : tris[t])
      incident[fill[v]++] = t;
  std::size_t added = 0;
  std::vector<std::size_t> parent;
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::size_t b = start[v], e = start[v + 1], m = e - b;
    if(m < 2)
      continue;
    parent.resize(m);
    std::iota(parent.begin(), parent.end(), 0);
    // two triangles around v are in the same fan if they share an edge at v
    for(std::size_t x = 0; x < m; ++x)
      for(std::size_t y = x + 1; y < m; ++y)
      {
        int shared = 0;
        for(std::size_t a : tris[incident[b + x]])
          for(std::size_t c : tris[incident[b + y]])
            shared += (a == c && a != v);
        if(shared > 0)
          parent[find_root(parent, x)] = find_root(parent, y);
      }
    // the fan of the first triangle keeps v; every other fan gets a copy
    std::vector<std::size_t> copy_of_root(m, std::size_t(-1));
    copy_of_root[find_root(parent, 0)] = v;
    for(std::size_t x = 0; x < m; ++x)
    {
      const std::size_t r = find_root(parent, x);
      if(copy_of_root[r] == std::size_t(-1))
      {
        copy_of_root[r] = source_pixel.size();
        source_pixel.push_back(source_pixel[v]);
        ++added;
      }
      for(std::size_t& u : tris[incident[b + x]])
        if(u == v)
          u = copy_of_root[r];
    }
  }
  return added;
}

// Keeps the triangles of the edge-connected components with at least
// min_faces triangles; returns the number dropped.
inline std::size_t drop_small_components(std::vector<std::array<std::size_t, 3>>& tris, std::size_t nv,
                                         std::size_t min_faces)
{
  std::vector<std::size_t> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  for(const auto& t : tris)
  {
    parent[find_root(parent, t[0])] = find_root(parent, t[1]);
    parent[find_root(parent, t[1])] = find_root(parent, t[2]);
  }
  std::vector<std::size_t> count(nv, 0);
  for(const auto& t : tris)
    ++count[find_root(parent, t[0])];
  std::vector<std::array<std::size_t, 3>> kept;
  kept.reserve(tris.size());
  for(const auto& t : tris)
    if(count[find_root(parent, t[0])] >= min_faces)
      kept.push_back(t);
  const std::size_t dropped = tris.size() - kept.size();
  tris.swap(kept);
  return dropped;
}

// Marks the pixels of `im` that keep their depth (im.valid) and counts them
// in `result`: a ray that hit, not at a grazing angle (o.grazing_cosine) nor
// at a depth discontinuity (a 4-neighbour missing or at a depth jump of more
// than o.edge_factor footprints; `f`: the focal length in pixels).
inline void mark_valid_pixels(Depth_image& im, const Depth_camera& c, const Depth_scan_options& o, double f,
                              Depth_scan_result& result)
{
  const std::size_t n = result.pixels, w = std::size_t(c.width);
  im.valid.assign(n, 0);
  for(std::size_t k = 0; k < n; ++k)
  {
    if(im.depth[k] <= 0.)
      continue;
    ++result.pixels_hit;
    if(im.cosine[k] < o.grazing_cosine)
    {
      ++result.dropped_grazing;
      continue;
    }
    const int i = int(k % w), j = int(k / w);
    bool edge = false;
    const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
    for(int q = 0; q < 4 && !edge; ++q)
    {
      const int a = i + di[q], b = j + dj[q];
      if(a < 0 || b < 0 || a >= c.width || b >= c.height)
        continue;
      const double z = im.depth[std::size_t(b) * w + a];
      edge = z <= 0. || std::abs(z - im.depth[k]) > o.edge_factor * std::max(z, im.depth[k]) / f;
    }
    if(edge)
      ++result.dropped_discontinuity;
    else
      im.valid[k] = 1;
  }
}

} // namespace internal

// Scans `tmesh` (a triangle mesh whose points are Epick points) with camera `c`.
template <typename TriangleMesh>
Depth_scan_result simulate_depth_scan(const TriangleMesh& tmesh, const Depth_camera& c,
                                      const Depth_scan_options& o = Depth_scan_options())
{
  if(c.width < 2 || c.height < 2)
    throw std::invalid_argument("simulate_depth_scan(): the image needs at least 2 x 2 pixels.");
  const Camera_frame frame(c);
  const double f = frame.f;
  Depth_scan_result result;
  result.camera_centre = c.eye;
  result.forward = frame.forward;
  result.pixels = std::size_t(c.width) * c.height;

  internal::Depth_image im = internal::cast_rays(tmesh, c, frame);
  // dropouts: grazing angles, then depth discontinuities
  internal::mark_valid_pixels(im, c, o, f, result);
  const std::size_t n = result.pixels, w = std::size_t(c.width);

  // noisy depth through the disparity domain
  const double baseline = o.baseline_ratio * std::sqrt(CGAL::squared_distance(c.eye, c.target));
  const std::vector<double> e =
      internal::window_disparity_errors(c.width, c.height, o.window, o.sigma_disparity, o.seed);
  std::vector<Scan_point> truth(n, c.eye), noisy(n, c.eye);
  for(std::size_t k = 0; k < n; ++k)
  {
    if(!im.valid[k])
      continue;
    const Scan_vector r = frame.ray(c, int(k % w), int(k / w));
    double d = f * baseline / im.depth[k] + e[k];
    if(o.quantisation > 0.)
      d = o.quantisation * std::round(d / o.quantisation);
    if(!(d > 0.))
    {
      im.valid[k] = 0; // no match
      continue;
    }
    truth[k] = c.eye + im.depth[k] * r;
    noisy[k] = c.eye + (f * baseline / d) * r;
  }

  // mesh: triangles, manifold vertices, no small islands, used vertices only
  std::vector<std::array<std::size_t, 3>> tris = internal::grid_triangles(c, im, truth, o.edge_factor, f);
  std::vector<std::size_t> source_pixel(n);
  std::iota(source_pixel.begin(), source_pixel.end(), 0);
  result.duplicated_vertices = internal::split_non_manifold_vertices(tris, source_pixel);
  result.dropped_small_faces = internal::drop_small_components(tris, source_pixel.size(), o.min_component_faces);
  std::vector<std::size_t> new_index(source_pixel.size(), std::size_t(-1));
  std::vector<Scan_mesh::Vertex_index> vn, vt;
  for(auto& t : tris)
    for(std::size_t& v : t)
    {
      if(new_index[v] == std::size_t(-1))
      {
        new_index[v] = vn.size();
        vn.push_back(result.noisy.add_vertex(noisy[source_pixel[v]]));
        vt.push_back(result.ground_truth.add_vertex(truth[source_pixel[v]]));
      }
      v = new_index[v];
    }
  for(const auto& t : tris)
  {
    const auto fa = result.noisy.add_face(vn[t[0]], vn[t[1]], vn[t[2]]);
    const auto fb = result.ground_truth.add_face(vt[t[0]], vt[t[1]], vt[t[2]]);
    if((fa == Scan_mesh::null_face()) != (fb == Scan_mesh::null_face()))
      throw std::logic_error("simulate_depth_scan(): the two meshes' connectivity differs.");
  }
  return result;
}

} // namespace denoising_support

#endif
