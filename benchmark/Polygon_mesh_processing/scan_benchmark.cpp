// Depth-scan benchmark: simulated structured-light scans (the support code's
// depth_scan_simulation.h) of CGAL's data set, compared with a real Kinect v1
// scan, and the automatic mode of intrinsic_denoising() on both.
//
// Usage:
//   scan_benchmark --stats [--real DIR] [--tsv FILE]
//       residual statistics (noisy - ground truth) of the real cone scan of DIR
//       (kinect_cone_noisy.obj, kinect_cone_groundtruth.obj) and of a few
//       simulated scans: share of the residual's energy along the viewing rays,
//       RMS in mean edge lengths, RMS by depth, correlation of the residual's
//       normal component against graph hops, E_n of the noisy mesh. The
//       correlation curves go to FILE (default scan_correlation.tsv).
//   scan_benchmark --simulated [--results FILE] [--stride N]
//       8 meshes x 4 viewpoints x 2 noise levels, seeded: noisy E_n, automatic
//       mode, fixed setting and the oracle grid; a table and a summary.
//   scan_benchmark --real DIR [--out OUTDIR]
//       the automatic mode and the fixed setting on the real scans of DIR;
//       E_n where a ground truth exists (and the oracle grid on the cone);
//       noisy, automatic and fixed results as OFF files in OUTDIR.
//   scan_benchmark --probe [--real DIR] [--stride N] [--clean FILE]...
//       evidence the automatic mode could read, per input: the share of the
//       area facing the mean normal (a single view gives about 1), whether
//       every candidate of the selection stopped by correlation within 3
//       iterations, E_n of the noisy input, the automatic mode, the fixed
//       setting and sigma 0.8, r 6 d, k 60, and the mean turn of the face
//       normals of that setting from 0 to 30 and from 30 to 60 iterations.
//       On the real scans of DIR (without ground truth: E_n against the
//       input), on every stride-th simulated scan and on each noise-free
//       mesh FILE (E_n against itself); with --out OUTDIR, the simulated
//       scans' noisy and ground-truth meshes as OFF files there.
//   scan_benchmark --trace FILE [--real DIR] [--stride N] [--clean FILE]...
//       every iteration (1 to 64) of six fixed settings on the real scans,
//       the simulated scans, the noise-free meshes and controls with white
//       and with correlated noise along the normals: E_n, the turn of the
//       face normals from the input's, the residual's RMS and correlation,
//       at k = 2, 4, ..., 64 the turn from iteration k / 2, the share of
//       edges flatter than 1 degree, and the input's single-view share.
//   --long-run-test  the automatic mode with the named parameter long_run_test
//   --window W, --quantisation Q, --levels S1,S2,...  the simulation's
//       block-matching window (pixels), disparity step (pixels) and sigma_d.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/candidates.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/residual_statistics.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_iterations.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <denoising_support/benchmark_common.h>
#include <denoising_support/depth_scan_simulation.h>
#include <denoising_support/mesh_file.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <queue>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace ds = denoising_support;
namespace D = PMP::internal::Denoising;
using Mesh = ds::Scan_mesh;
using Point = ds::Scan_point;
using Vector = ds::Scan_vector;
using Tag = CGAL::Parallel_if_available_tag;

namespace {

constexpr int max_hops = 12;

// ---------------------------------------------------------------- statistics

struct Scan_statistics
{
  std::string name;
  std::size_t vertices = 0, faces = 0;
  double along_ray_share = 0.;                             // share of sum |r|^2 along the viewing rays
  double along_normal_share = 0.;                          // ... along the true vertex normals
  double along_axis_share = 0.;                            // ... along the optical axis
  double rms = 0.;                                         // RMS |r| in mean edge lengths
  double normal_rms = 0.;                                  // RMS of r . n in mean edge lengths
  Point fitted_centre;                                     // the point nearest to the lines (truth, residual)
  double fitted_ray_share = 0.;                            // share along rays from the fitted centre
  std::vector<double> bin_depth, bin_rms, bin_rms_over_z2; // by depth quintile (along-ray RMS)
  std::vector<double> correlation;                         // of r . n at 1..max_hops hops
  double noisy_En = 0.;
};

Vector unit(const Vector& v)
{
  const double l = std::sqrt(v.squared_length());
  return l > 0. ? v / l : v;
}

double mean_edge_length(const Mesh& m)
{
  double s = 0.;
  for(auto e : edges(m))
    s += std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
  return s / double(num_edges(m));
}

// The least-squares meeting point of the lines through p_i along d_i, weighted
// by w_i: solves sum w (I - d d^T) c = sum w (I - d d^T) p.
Point nearest_point_to_lines(const std::vector<Point>& p, const std::vector<Vector>& d, const std::vector<double>& w)
{
  double A[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, b[3] = {0, 0, 0};
  for(std::size_t i = 0; i < p.size(); ++i)
  {
    const Vector u = unit(d[i]);
    const double uu[3] = {u.x(), u.y(), u.z()}, pp[3] = {p[i].x(), p[i].y(), p[i].z()};
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c)
      {
        const double m = w[i] * ((r == c ? 1. : 0.) - uu[r] * uu[c]);
        A[r][c] += m;
        b[r] += m * pp[c];
      }
  }
  // Cramer's rule
  auto det = [](const double M[3][3]) {
    return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
           M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  };
  const double D = det(A);
  double x[3];
  for(int k = 0; k < 3; ++k)
  {
    double M[3][3];
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c)
        M[r][c] = c == k ? b[r] : A[r][c];
    x[k] = det(M) / D;
  }
  return Point(x[0], x[1], x[2]);
}

// Pearson correlation of s between vertices at exactly h graph hops, h = 1..max_hops,
// over breadth-first searches from every stride-th vertex.
std::vector<double> hop_correlation(const Mesh& m, const std::vector<double>& s)
{
  const std::size_t n = s.size();
  double mean = 0., var = 0.;
  for(double x : s)
    mean += x;
  mean /= double(n);
  for(double x : s)
    var += (x - mean) * (x - mean);
  var /= double(n);
  std::vector<double> cov(max_hops + 1, 0.);
  std::vector<std::size_t> count(max_hops + 1, 0);
  std::vector<int> hop(n, -1);
  std::vector<std::size_t> visited;
  const std::size_t stride = std::max<std::size_t>(1, n / 1500);
  for(std::size_t src = 0; src < n; src += stride)
  {
    std::queue<std::size_t> q;
    q.push(src);
    hop[src] = 0;
    visited.assign(1, src);
    while(!q.empty())
    {
      const std::size_t v = q.front();
      q.pop();
      if(hop[v] >= max_hops)
        continue;
      for(auto u : vertices_around_target(halfedge(Mesh::Vertex_index(Mesh::size_type(v)), m), m))
      {
        const std::size_t ui = std::size_t(u);
        if(hop[ui] >= 0)
          continue;
        hop[ui] = hop[v] + 1;
        visited.push_back(ui);
        cov[hop[ui]] += (s[src] - mean) * (s[ui] - mean);
        ++count[hop[ui]];
        q.push(ui);
      }
    }
    for(std::size_t v : visited)
      hop[v] = -1;
  }
  std::vector<double> c(max_hops + 1, 0.);
  for(int h = 1; h <= max_hops; ++h)
    c[h] = count[h] ? cov[h] / double(count[h]) / var : 0.;
  return c;
}

Scan_statistics scan_statistics(const std::string& name, const Mesh& noisy, Mesh truth, const Point& eye,
                                const Vector& axis)
{
  Scan_statistics st;
  st.name = name;
  st.vertices = num_vertices(noisy);
  st.faces = num_faces(noisy);
  const double L = mean_edge_length(truth);
  auto normals = truth.add_property_map<Mesh::Vertex_index, Vector>("v:scan_normal", CGAL::NULL_VECTOR).first;
  PMP::compute_vertex_normals(truth, normals);
  double e2 = 0., ray2 = 0., normal2 = 0., axis2 = 0.;
  std::vector<double> s;
  std::vector<Point> p;
  std::vector<Vector> r;
  std::vector<double> w;
  std::vector<std::pair<double, double>> depth_residual;
  for(auto v : vertices(truth))
  {
    const Vector res = noisy.point(v) - truth.point(v), ray = unit(truth.point(v) - eye);
    const double a = res * ray, nn = res * normals[v];
    e2 += res.squared_length();
    ray2 += a * a;
    normal2 += nn * nn;
    axis2 += (res * axis) * (res * axis);
    s.push_back(nn);
    p.push_back(truth.point(v));
    r.push_back(res);
    w.push_back(res.squared_length());
    depth_residual.emplace_back((truth.point(v) - eye) * axis, a);
  }
  truth.remove_property_map(normals);
  const double n = double(st.vertices);
  st.along_ray_share = ray2 / e2;
  st.along_normal_share = normal2 / e2;
  st.along_axis_share = axis2 / e2;
  st.rms = std::sqrt(e2 / n) / L;
  st.normal_rms = std::sqrt(normal2 / n) / L;
  st.fitted_centre = nearest_point_to_lines(p, r, w);
  double fit2 = 0.;
  for(std::size_t i = 0; i < p.size(); ++i)
  {
    const double a = r[i] * unit(p[i] - st.fitted_centre);
    fit2 += a * a;
  }
  st.fitted_ray_share = fit2 / e2;
  std::sort(depth_residual.begin(), depth_residual.end());
  const std::size_t bins = 5, q = depth_residual.size() / bins;
  for(std::size_t b = 0; b < bins && q > 0; ++b)
  {
    double z = 0., a2 = 0.;
    for(std::size_t i = b * q; i < (b + 1) * q; ++i)
    {
      z += depth_residual[i].first;
      a2 += depth_residual[i].second * depth_residual[i].second;
    }
    z /= double(q);
    st.bin_depth.push_back(z);
    st.bin_rms.push_back(std::sqrt(a2 / double(q)) / L);
    st.bin_rms_over_z2.push_back(std::sqrt(a2 / double(q)) / (z * z));
  }
  const double nearest = st.bin_rms_over_z2.empty() ? 1. : st.bin_rms_over_z2.front();
  for(double& x : st.bin_rms_over_z2)
    x /= nearest;
  st.correlation = hop_correlation(noisy, s);
  st.noisy_En = PMP::face_normal_error(noisy, truth);
  return st;
}

void print_statistics(const Scan_statistics& st)
{
  std::printf("%s: %zu vertices, %zu faces\n", st.name.c_str(), st.vertices, st.faces);
  std::printf("  energy share: along rays from the camera %.3f, along the true normals %.3f, along the optical axis "
              "%.3f\n",
              st.along_ray_share, st.along_normal_share, st.along_axis_share);
  std::printf("  lines (truth, residual) meet nearest (%.4g, %.4g, %.4g); share along rays from there %.3f\n",
              st.fitted_centre.x(), st.fitted_centre.y(), st.fitted_centre.z(), st.fitted_ray_share);
  std::printf("  RMS |residual| %.3f L, RMS normal component %.3f L (L = mean edge length); noisy E_n %.2f deg\n",
              st.rms, st.normal_rms, st.noisy_En);
  std::printf("  along-ray RMS by depth quintile (depth: RMS/L, RMS/z^2 relative to the nearest):");
  for(std::size_t b = 0; b < st.bin_depth.size(); ++b)
    std::printf(" %.4g: %.3f, %.2f;", st.bin_depth[b], st.bin_rms[b], st.bin_rms_over_z2[b]);
  std::printf("\n  correlation of the normal component at 1..%d hops:", max_hops);
  for(int h = 1; h <= max_hops; ++h)
    std::printf(" %.2f", st.correlation[h]);
  std::printf("\n");
}

bool read_mesh(const std::string& path, Mesh& m)
{
  m.clear();
  return ds::read_triangle_mesh(path, m);
}

// ---------------------------------------------------------------- simulated inputs

struct Scan_input
{
  std::string mesh;
  double azimuth, elevation, sigma_disparity;
  std::uint64_t seed;
  std::string name() const
  {
    char b[160];
    std::snprintf(b, sizeof b, "%s@%g/%g:s%g", mesh.c_str(), azimuth, elevation, sigma_disparity);
    return b;
  }
};

const char* corpus_meshes[] = {"fandisk", "anchor", "blade", "rotor", "bunny00", "elephant", "armadillo", "pig"};
const double viewpoints[4][2] = {{30., 20.}, {120., 35.}, {210., 10.}, {300., 50.}};
// The simulation's settings of the benchmark (--window, --quantisation and
// --levels override them). A 25-pixel window and no quantisation step give
// the statistics nearest to the real Kinect scan of --stats (correlation of
// the normal component 0.92-0.98 at one hop and 0.19-0.46 at twelve, against
// the scan's 0.94 and 0.50; noisy E_n 8-12 degrees at sigma_d 0.1 for an
// RMS of 0.5-0.8 edge lengths, against the scan's 14.4 at 0.9): with the
// Kinect's 1/8-pixel step, E_n rises to 19-24 degrees at the same RMS, and
// a 9-pixel window gives a correlation of 0.02-0.11 at eight hops.
int scan_window = 25;
double scan_quantisation = 0.;
std::vector<double> noise_levels = {0.1, 0.2};

std::vector<Scan_input> simulated_inputs()
{
  std::vector<Scan_input> in;
  for(const char* m : corpus_meshes)
    for(const auto& vp : viewpoints)
      for(double s : noise_levels)
        in.push_back({m, vp[0], vp[1], s, std::uint64_t(1000 + in.size())});
  return in;
}

// Scans the input into `out`; false if its mesh cannot be read (the scan
// may be empty: a thin part seen edge-on).
bool scan(const Scan_input& in, ds::Depth_scan_result& out)
{
  Mesh source;
  if(!read_mesh(CGAL::data_file_path("meshes/" + in.mesh + ".off"), source))
  {
    std::fprintf(stderr, "cannot read %s\n", in.mesh.c_str());
    return false;
  }
  ds::Depth_scan_options o;
  o.sigma_disparity = in.sigma_disparity;
  o.window = scan_window;
  o.quantisation = scan_quantisation;
  o.seed = in.seed;
  out = ds::simulate_depth_scan(source, ds::frame_camera(source, in.azimuth, in.elevation), o);
  return true;
}

// ---------------------------------------------------------------- denoising runs

const char* stop_name(PMP::Intrinsic_stop_reason r)
{
  switch(r)
  {
  case PMP::Intrinsic_stop_reason::ITERATION_LIMIT:
    return "limit";
  case PMP::Intrinsic_stop_reason::NOISE_LEVEL_REACHED:
    return "noise";
  case PMP::Intrinsic_stop_reason::CONVERGED:
    return "converged";
  case PMP::Intrinsic_stop_reason::RESIDUAL_CORRELATED:
    return "correlated";
  case PMP::Intrinsic_stop_reason::SELF_CHECK:
    return "self-check";
  case PMP::Intrinsic_stop_reason::SECOND_PASS:
    return "second-pass";
  case PMP::Intrinsic_stop_reason::LONG_RUN:
    return "long-run";
  }
  return "?";
}

struct Run
{
  Mesh mesh;
  PMP::Intrinsic_denoising_report report;
  double seconds = 0.;
};

// --long-run-test: the automatic runs with the named parameter long_run_test
bool long_run_test = false;

Run run_auto(const Mesh& noisy)
{
  Run r;
  r.mesh = noisy;
  ds::Stopwatch w;
  r.report = PMP::intrinsic_denoising<Tag>(r.mesh, CGAL::parameters::long_run_test(long_run_test));
  r.seconds = w.seconds();
  return r;
}

Run run_fixed(const Mesh& noisy)
{
  Run r;
  r.mesh = noisy;
  ds::Stopwatch w;
  r.report = PMP::intrinsic_denoising<Tag>(r.mesh, CGAL::parameters::automatic_parameters(false));
  r.seconds = w.seconds();
  return r;
}

struct Oracle
{
  double En = 1e30, sigma = 0., radius = 0.;
  unsigned int k = 0;
};

Oracle run_oracle(const Mesh& noisy, const Mesh& truth)
{
  Oracle o;
  for(double sigma : {0.4, 0.8, 1.4})
    for(double radius : {3., 4., 6.})
      for(unsigned int k : {10u, 30u, 60u})
      {
        Mesh m = noisy;
        PMP::intrinsic_denoising<Tag>(m, CGAL::parameters::automatic_parameters(false)
                                             .sigma_spatial(sigma)
                                             .sigma_range(sigma)
                                             .relative_neighbor_radius(radius)
                                             .number_of_iterations(k));
        const double En = PMP::face_normal_error(m, truth);
        if(En < o.En)
          o = {En, sigma, radius, k};
      }
  return o;
}

// ---------------------------------------------------------------- modes

int stats_mode(const std::string& real_dir, const std::string& tsv)
{
  std::vector<Scan_statistics> all;
  if(!real_dir.empty())
  {
    Mesh noisy, truth;
    if(!read_mesh(real_dir + "/kinect_cone_noisy.obj", noisy) ||
       !read_mesh(real_dir + "/kinect_cone_groundtruth.obj", truth) || num_vertices(noisy) != num_vertices(truth))
    {
      std::fprintf(stderr, "cannot read the cone scan of %s\n", real_dir.c_str());
      return 1;
    }
    // the camera at the origin looking down -z
    all.push_back(scan_statistics("real kinect cone", noisy, truth, Point(0, 0, 0), Vector(0, 0, -1)));
    print_statistics(all.back());
  }
  const struct
  {
    const char* mesh;
    double azimuth, elevation;
  } views[] = {{"fandisk", 30., 20.}, {"bunny00", 120., 35.}, {"elephant", 210., 10.}, {"anchor", 300., 50.}};
  for(const auto& v : views)
    for(double s : noise_levels)
    {
      const Scan_input in{v.mesh, v.azimuth, v.elevation, s, 1};
      ds::Depth_scan_result r;
      if(!scan(in, r))
        return 1;
      all.push_back(scan_statistics("simulated " + in.name(), r.noisy, r.ground_truth, r.camera_centre, r.forward));
      print_statistics(all.back());
      std::printf("  pixels hit %zu, dropped at grazing angles %zu, at discontinuities %zu\n", r.pixels_hit,
                  r.dropped_grazing, r.dropped_discontinuity);
    }
  std::ofstream out(tsv);
  out << "scan\thops\tcorrelation\n";
  for(const auto& st : all)
    for(int h = 1; h <= max_hops; ++h)
      out << st.name << "\t" << h << "\t" << st.correlation[h] << "\n";
  std::printf("correlation curves written to %s\n", tsv.c_str());
  return 0;
}

int simulated_mode(const std::string& results, std::size_t stride)
{
  const std::vector<Scan_input> inputs = simulated_inputs();
  std::ofstream out;
  if(!results.empty())
  {
    out.open(results);
    out << "input\tvertices\tfaces\tnoisy_En\tauto_En\tauto_iterations\tauto_stop\tauto_seconds\tfixed_En\tfixed_"
           "seconds\toracle_En\toracle_sigma\toracle_radius\toracle_k\n";
  }
  std::printf("%-34s %6s %7s %7s %7s %4s %-11s %6s %7s %7s %s\n", "input", "faces", "noisy", "auto", "fixed", "k",
              "stop", "t_auto", "oracle", "t_fix", "oracle setting");
  std::vector<double> auto_fixed, auto_oracle;
  std::vector<std::string> names;
  std::size_t auto_le_fixed = 0, auto_near_oracle = 0;
  std::vector<std::string> auto_worse_than_noisy, fixed_worse_than_noisy;
  ds::Stopwatch total;
  for(std::size_t i = 0; i < inputs.size(); i += stride)
  {
    ds::Depth_scan_result s;
    if(!scan(inputs[i], s))
      return 1;
    const std::string name = inputs[i].name();
    if(num_faces(s.noisy) < 100)
    {
      std::printf("%-34s skipped: %zu faces seen\n", name.c_str(), std::size_t(num_faces(s.noisy)));
      continue;
    }
    const double noisy = PMP::face_normal_error(s.noisy, s.ground_truth);
    const Run a = run_auto(s.noisy), f = run_fixed(s.noisy);
    const double ea = PMP::face_normal_error(a.mesh, s.ground_truth),
                 ef = PMP::face_normal_error(f.mesh, s.ground_truth);
    const Oracle o = run_oracle(s.noisy, s.ground_truth);
    std::printf("%-34s %6zu %7.2f %7.2f %7.2f %4u %-11s %6.2f %7.2f %7.2f s%.1f r%.0f k%u\n", name.c_str(),
                std::size_t(num_faces(s.noisy)), noisy, ea, ef, a.report.iterations, stop_name(a.report.stop_reason),
                a.seconds, o.En, f.seconds, o.sigma, o.radius, o.k);
    std::fflush(stdout);
    if(out)
      out << name << "\t" << num_vertices(s.noisy) << "\t" << num_faces(s.noisy) << "\t" << noisy << "\t" << ea << "\t"
          << a.report.iterations << "\t" << stop_name(a.report.stop_reason) << "\t" << a.seconds << "\t" << ef << "\t"
          << f.seconds << "\t" << o.En << "\t" << o.sigma << "\t" << o.radius << "\t" << o.k << "\n";
    names.push_back(name);
    auto_fixed.push_back(ea / ef);
    auto_oracle.push_back(ea / o.En);
    auto_le_fixed += ea <= ef;
    auto_near_oracle += ea <= 1.1 * o.En;
    if(ea > noisy)
      auto_worse_than_noisy.push_back(name);
    if(ef > noisy)
      fixed_worse_than_noisy.push_back(name);
  }
  const std::size_t n = names.size();
  auto worst = [&](const std::vector<double>& v) {
    std::vector<std::size_t> idx(n);
    for(std::size_t i = 0; i < n; ++i)
      idx[i] = i;
    std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return v[a] > v[b]; });
    std::string s;
    for(std::size_t i = 0; i < std::min<std::size_t>(3, n); ++i)
      s += names[idx[i]] + " (" + std::to_string(v[idx[i]]).substr(0, 5) + ") ";
    return s;
  };
  std::printf("\n%zu inputs, %.0f s\n", n, total.seconds());
  std::printf("auto/fixed:  median %.3f, 90th percentile %.3f, worst %s\n", ds::quantile(auto_fixed, 0.5),
              ds::quantile(auto_fixed, 0.9), worst(auto_fixed).c_str());
  std::printf("auto/oracle: median %.3f, 90th percentile %.3f, worst %s\n", ds::quantile(auto_oracle, 0.5),
              ds::quantile(auto_oracle, 0.9), worst(auto_oracle).c_str());
  std::printf("auto <= fixed: %zu of %zu; auto within 10%% of the oracle: %zu of %zu\n", auto_le_fixed, n,
              auto_near_oracle, n);
  std::printf("auto worse than noisy: %zu", auto_worse_than_noisy.size());
  for(const auto& s : auto_worse_than_noisy)
    std::printf(" %s", s.c_str());
  std::printf("\nfixed worse than noisy: %zu", fixed_worse_than_noisy.size());
  for(const auto& s : fixed_worse_than_noisy)
    std::printf(" %s", s.c_str());
  std::printf("\n");
  return 0;
}

int real_mode(const std::string& dir, const std::string& outdir)
{
  if(!outdir.empty())
    std::filesystem::create_directories(outdir);
  const struct
  {
    const char* file;
    const char* truth;
  } scans[] = {{"kinect_cone_noisy.obj", "kinect_cone_groundtruth.obj"},
               {"angel.obj", nullptr},
               {"rabbit.obj", nullptr},
               {"iron.ply", nullptr}};
  for(const auto& sc : scans)
  {
    Mesh noisy, truth;
    if(!read_mesh(dir + "/" + sc.file, noisy))
    {
      std::fprintf(stderr, "cannot read %s/%s\n", dir.c_str(), sc.file);
      continue;
    }
    const bool has_truth = sc.truth && read_mesh(dir + "/" + sc.truth, truth) && num_faces(truth) == num_faces(noisy);
    const Run a = run_auto(noisy), f = run_fixed(noisy);
    std::printf("%s: %zu vertices, %zu faces\n", sc.file, std::size_t(num_vertices(noisy)),
                std::size_t(num_faces(noisy)));
    std::printf("  auto:  %u iterations, stop %s, %.2f s, sigma %.2f, r %.1f d, noise level %.3f", a.report.iterations,
                stop_name(a.report.stop_reason), a.seconds, a.report.sigma_spatial, a.report.relative_neighbor_radius,
                a.report.noise_level);
    if(has_truth)
      std::printf(", E_n %.2f", PMP::face_normal_error(a.mesh, truth));
    std::printf("\n  fixed: %u iterations, stop %s, %.2f s", f.report.iterations, stop_name(f.report.stop_reason),
                f.seconds);
    if(has_truth)
      std::printf(", E_n %.2f\n  noisy E_n %.2f", PMP::face_normal_error(f.mesh, truth),
                  PMP::face_normal_error(noisy, truth));
    std::printf("\n");
    if(has_truth)
    {
      const Oracle o = run_oracle(noisy, truth);
      std::printf("  oracle grid: E_n %.2f at sigma %.1f, r %.0f d, k %u\n", o.En, o.sigma, o.radius, o.k);
    }
    std::fflush(stdout);
    if(!outdir.empty())
    {
      const std::string stem = outdir + "/" + std::filesystem::path(sc.file).stem().string();
      CGAL::IO::write_polygon_mesh(stem + "_noisy.off", noisy, CGAL::parameters::stream_precision(10));
      CGAL::IO::write_polygon_mesh(stem + "_auto.off", a.mesh, CGAL::parameters::stream_precision(10));
      CGAL::IO::write_polygon_mesh(stem + "_fixed.off", f.mesh, CGAL::parameters::stream_precision(10));
    }
  }
  return 0;
}

// ---------------------------------------------------------------- probe

// The share of the area of m's faces whose normal has a positive component
// along the area-weighted mean normal: 1 for a triangulated depth image of
// a surface seen under less than 90 degrees everywhere.
double single_view_share(const Mesh& m)
{
  Vector sum = CGAL::NULL_VECTOR;
  std::vector<Vector> n;
  for(auto f : faces(m))
  {
    const auto h = halfedge(f, m);
    const Point a = m.point(source(h, m)), b = m.point(target(h, m)), c = m.point(target(next(h, m), m));
    n.push_back(0.5 * CGAL::cross_product(b - a, c - a));
    sum = sum + n.back();
  }
  double front = 0., total = 0.;
  for(const Vector& x : n)
  {
    const double area = std::sqrt(x.squared_length());
    total += area;
    if(x * sum > 0.)
      front += area;
  }
  return total > 0. ? front / total : 0.;
}

Mesh run_setting(const Mesh& noisy, double sigma, double radius, unsigned int k)
{
  Mesh m = noisy;
  PMP::intrinsic_denoising<Tag>(m, CGAL::parameters::automatic_parameters(false)
                                       .sigma_spatial(sigma)
                                       .sigma_range(sigma)
                                       .relative_neighbor_radius(radius)
                                       .number_of_iterations(k));
  return m;
}

void probe_one(const std::string& name, const Mesh& noisy, const Mesh& truth)
{
  const Run a = run_auto(noisy);
  const Mesh f = run_setting(noisy, 0.4, 4., 30), s30 = run_setting(noisy, 0.8, 6., 30),
             s60 = run_setting(noisy, 0.8, 6., 60);
  const double a1 = PMP::face_normal_error(s30, noisy), a2 = PMP::face_normal_error(s60, s30);
  std::printf("%-34s %7zu %6.3f %5s %3u %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7.3f %6.3f\n", name.c_str(),
              std::size_t(num_faces(noisy)), single_view_share(noisy),
              denoising_support::short_selection(a.report) ? "short" : "-", a.report.iterations,
              PMP::face_normal_error(noisy, truth), PMP::face_normal_error(a.mesh, truth),
              PMP::face_normal_error(f, truth), PMP::face_normal_error(s60, truth), a1, a2, a2 / a1,
              a.report.second_pass_angle / std::max(1e-12, a.report.change_angle));
  std::fflush(stdout);
}

int probe_mode(const std::string& real_dir, const std::vector<std::string>& clean, std::size_t stride,
               const std::string& outdir)
{
  std::printf("%-34s %7s %6s %5s %3s %7s %7s %7s %7s %7s %7s %7s %6s\n", "input", "faces", "view", "sel", "k", "noisy",
              "auto", "fixed", "scan60", "a0-30", "a30-60", "ratio", "2nd");
  if(!real_dir.empty())
  {
    Mesh noisy, truth;
    if(read_mesh(real_dir + "/kinect_cone_noisy.obj", noisy) &&
       read_mesh(real_dir + "/kinect_cone_groundtruth.obj", truth))
      probe_one("real kinect cone", noisy, truth);
    for(const char* other : {"angel.obj", "rabbit.obj", "iron.ply"})
      if(read_mesh(real_dir + "/" + other, noisy))
        probe_one(std::string("real ") + other + " (no truth)", noisy, noisy);
  }
  const std::vector<Scan_input> inputs = simulated_inputs();
  for(std::size_t i = 0; i < inputs.size(); i += stride)
  {
    ds::Depth_scan_result s;
    if(!scan(inputs[i], s))
      return 1;
    if(num_faces(s.noisy) < 100)
      continue;
    probe_one(inputs[i].name(), s.noisy, s.ground_truth);
    if(!outdir.empty())
    {
      std::filesystem::create_directories(outdir);
      std::string stem = inputs[i].name();
      std::replace(stem.begin(), stem.end(), '/', '_');
      std::replace(stem.begin(), stem.end(), ':', '_');
      CGAL::IO::write_polygon_mesh(outdir + "/" + stem + "_noisy.off", s.noisy, CGAL::parameters::stream_precision(17));
      CGAL::IO::write_polygon_mesh(outdir + "/" + stem + "_truth.off", s.ground_truth,
                                   CGAL::parameters::stream_precision(17));
    }
  }
  for(const std::string& path : clean)
  {
    Mesh m;
    if(read_mesh(path, m) && num_faces(m) > 0)
      probe_one("clean " + std::filesystem::path(path).filename().string(), m, m);
  }
  return 0;
}

// ---------------------------------------------------------------- trace

// Gaussian noise along the vertex normals whose values are correlated over
// the surface: white draws smoothed by `rounds` passes of neighbour
// averaging (the correlation length grows as the square root of the
// rounds), scaled to an RMS of `sigma` mean edge lengths. Seeded.
void add_correlated_normal_noise(Mesh& m, double sigma, unsigned int rounds, unsigned int seed)
{
  std::mt19937 engine(seed);
  std::normal_distribution<double> normal(0., 1.);
  std::vector<double> s(num_vertices(m)), t(s.size());
  for(double& x : s)
    x = normal(engine);
  for(unsigned int r = 0; r < rounds; ++r)
  {
    for(auto v : vertices(m))
    {
      double sum = s[v.idx()];
      std::size_t n = 1;
      for(auto w : CGAL::vertices_around_target(halfedge(v, m), m))
      {
        sum += s[w.idx()];
        ++n;
      }
      t[v.idx()] = sum / double(n);
    }
    s.swap(t);
  }
  double sq = 0.;
  for(double x : s)
    sq += x * x;
  const double scale = sigma * mean_edge_length(m) / std::sqrt(sq / double(s.size()));
  auto normals = m.add_property_map<Mesh::Vertex_index, Vector>("v:trace_normal").first;
  PMP::compute_vertex_normals(m, normals);
  for(auto v : vertices(m))
    m.point(v) = m.point(v) + scale * s[v.idx()] * normals[v];
  m.remove_property_map(normals);
}

// Every iteration (1..kmax) of a few fixed settings on one input: E_n
// against `truth`, the mean turn of the face normals from the input's, the
// residual's RMS (mean edge lengths) and its correlation across edges.
void trace_one(std::FILE* out, const std::string& name, const Mesh& noisy, const Mesh& truth)
{
  constexpr unsigned int kmax = 64, v_iter = 2;
  const D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters> maps(noisy, CGAL::parameters::default_values());
  const D::Flat_mesh ref =
      D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters>(truth, CGAL::parameters::default_values())
          .flat(truth, "trace");
  const struct
  {
    double sigma, radius;
  } settings[] = {{0.4, 3.}, {0.4, 4.}, {0.8, 3.}, {0.8, 6.}, {1.4, 3.}, {1.4, 6.}};
  double last_radius = -1.;
  const double view = single_view_share(noisy);
  D::Intrinsic_setup base;
  for(const auto& st : settings)
  {
    if(st.radius != last_radius)
    {
      base = D::make_intrinsic_setup<Tag>(
          noisy, D::read_filter_options(CGAL::parameters::relative_neighbor_radius(st.radius)), maps, "trace");
      last_radius = st.radius;
    }
    const double L = D::mean_edge_length(base.mesh);
    const D::Csr adjacency = D::vertex_adjacency(base.mesh);
    D::Face_data ref_fd;
    D::compute_face_data<CGAL::Sequential_tag>(base.mesh, ref.points, ref_fd);
    D::Intrinsic_kernel kernel = base.kernel;
    kernel.sigma_spatial = kernel.sigma_range = st.sigma;
    std::vector<D::Vec3> points = base.mesh.points;
    const std::vector<D::Vec3> input_points = points;
    const std::vector<char> fixed(points.size(), 0);
    D::Fold_safeguard guard;
    guard.enabled = true;
    guard.reference = &base.input_faces.normals;
    std::vector<D::Vec3> half_normals = base.input_faces.normals; // at the last power of two
    std::fprintf(out, "%s\t%zu\t%.1f\t%.1f\t0\t%.4f\t0\t0\t0\t0\t%.4f\t%.4f\n", name.c_str(),
                 std::size_t(num_faces(noisy)), st.sigma, st.radius,
                 D::mean_angle_degrees(base.input_faces.normals, ref_fd.normals),
                 D::flat_edge_fraction<Tag>(base.mesh, base.input_faces.normals, 1.), view);
    D::iterate_filter<Tag>(base, kernel, base.input_faces, points, fixed, v_iter, guard, kmax,
                           [&](unsigned int k, const std::vector<D::Vec3>& p, std::vector<D::Vec3>&) {
                             D::Face_data fd;
                             D::compute_face_data<Tag>(base.mesh, p, fd);
                             const D::Residual_statistics rs = D::residual_statistics(adjacency, p, input_points, L);
                             const bool power = (k & (k - 1)) == 0;
                             const double half = power && k > 1 ? D::mean_angle_degrees(fd.normals, half_normals) : 0.;
                             if(power)
                               half_normals = fd.normals;
                             std::fprintf(out, "%s\t%zu\t%.1f\t%.1f\t%u\t%.4f\t%.4f\t%.5f\t%.5f\t%.4f\t%.4f\t%.4f\n",
                                          name.c_str(), std::size_t(num_faces(noisy)), st.sigma, st.radius, k,
                                          D::mean_angle_degrees(fd.normals, ref_fd.normals),
                                          D::mean_angle_degrees(fd.normals, base.input_faces.normals), rs.rms,
                                          rs.correlation, half, D::flat_edge_fraction<Tag>(base.mesh, fd.normals, 1.),
                                          view);
                             return true;
                           });
    std::fflush(out);
  }
}

// --trace FILE: trace_one() on the real scans of DIR (E_n against the input
// where there is no ground truth), on every stride-th simulated scan, on
// each noise-free mesh FILE, and on controls: corpus meshes with white and
// with correlated Gaussian noise along the normals.
int trace_mode(const std::string& real_dir, const std::vector<std::string>& clean, std::size_t stride,
               const std::string& path)
{
  std::FILE* out = std::fopen(path.c_str(), "w");
  if(!out)
    return 1;
  std::fprintf(out, "input\tfaces\tsigma\tradius\tk\tEn\tturn\trms\tcorrelation\thalf\tflat\tview\n");
  if(!real_dir.empty())
  {
    Mesh noisy, truth;
    if(read_mesh(real_dir + "/kinect_cone_noisy.obj", noisy) &&
       read_mesh(real_dir + "/kinect_cone_groundtruth.obj", truth))
      trace_one(out, "real:cone", noisy, truth);
    for(const char* other : {"angel.obj", "rabbit.obj", "iron.ply"})
      if(read_mesh(real_dir + "/" + other, noisy))
        trace_one(out, std::string("real-nt:") + other, noisy, noisy);
  }
  const std::vector<Scan_input> inputs = simulated_inputs();
  for(std::size_t i = 0; i < inputs.size(); i += stride)
  {
    ds::Depth_scan_result s;
    if(!scan(inputs[i], s))
      return 1;
    if(num_faces(s.noisy) >= 100)
      trace_one(out, "sim:" + inputs[i].name(), s.noisy, s.ground_truth);
  }
  for(const std::string& file : clean)
  {
    Mesh m;
    if(read_mesh(file, m) && num_faces(m) > 0)
      trace_one(out, "clean:" + std::filesystem::path(file).filename().string(), m, m);
  }
  unsigned int seed = 1;
  for(const char* name : corpus_meshes)
  {
    Mesh truth;
    if(!read_mesh(CGAL::data_file_path(std::string("meshes/") + name + ".off"), truth))
      continue;
    for(double sigma : {0.1, 0.3})
    {
      Mesh white = truth;
      PMP::add_gaussian_noise(white, sigma, CGAL::parameters::random_seed(seed++));
      trace_one(out, "white:" + std::string(name) + ":s" + std::to_string(sigma).substr(0, 3), white, truth);
      Mesh correlated = truth;
      add_correlated_normal_noise(correlated, 2. * sigma, 8, seed++);
      trace_one(out, "corr8:" + std::string(name) + ":s" + std::to_string(2. * sigma).substr(0, 3), correlated, truth);
    }
  }
  std::fclose(out);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  std::string mode, real_dir, results, outdir, tsv = "scan_correlation.tsv";
  std::size_t stride = 1;
  std::vector<std::string> clean;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
      {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if(a == "--stats" || a == "--simulated" || a == "--probe")
      mode = a;
    else if(a == "--trace")
    {
      mode = a;
      results = value();
    }
    else if(a == "--real")
    {
      real_dir = value();
      if(mode.empty())
        mode = a;
    }
    else if(a == "--results")
      results = value();
    else if(a == "--out")
      outdir = value();
    else if(a == "--tsv")
      tsv = value();
    else if(a == "--window")
      scan_window = std::max(1, std::atoi(value().c_str()));
    else if(a == "--quantisation")
      scan_quantisation = std::atof(value().c_str());
    else if(a == "--levels")
    {
      noise_levels.clear();
      std::stringstream list(value());
      for(std::string x; std::getline(list, x, ',');)
        noise_levels.push_back(std::atof(x.c_str()));
    }
    else if(a == "--long-run-test")
      long_run_test = true;
    else if(a == "--clean")
      clean.push_back(value());
    else if(a == "--stride")
      stride = std::max(1, std::atoi(value().c_str()));
    else
    {
      std::fprintf(stderr, "unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  if(mode == "--stats")
    return stats_mode(real_dir, tsv);
  if(mode == "--simulated")
    return simulated_mode(results, stride);
  if(mode == "--probe")
    return probe_mode(real_dir, clean, stride, outdir);
  if(mode == "--real")
    return real_mode(real_dir, outdir);
  if(mode == "--trace")
    return trace_mode(real_dir, clean, stride, results);
  std::fprintf(stderr,
               "usage: scan_benchmark --stats [--real DIR] [--tsv FILE] | --simulated [--results FILE] "
               "[--stride N] | --real DIR [--out OUTDIR] | --probe [--real DIR] [--stride N] [--clean FILE]...\n"
               "  | --trace FILE [--real DIR] [--stride N] [--clean FILE]...\n"
               "  [--long-run-test] [--window W] [--quantisation Q] [--levels S1,S2,...]\n");
  return 2;
}
