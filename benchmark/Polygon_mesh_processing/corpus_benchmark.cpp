// The development corpus: every triangle mesh of CGAL's data set
// (meshes/*.off) with 1,000 to 60,000 faces, each with several kinds of
// seeded noise, and per input the automatic mode of intrinsic_denoising()
// against the fixed setting, the classic methods at their defaults and an
// oracle (the best E_n of a grid of the intrinsic filter's parameters).
//
// Usage:
//   corpus_benchmark --list                        the inputs, one a line
//   corpus_benchmark --build-reference FILE [--trace TRACE]
//       computes, for every input not yet in FILE, what depends only on the
//       input (noisy E_n and E_v, the oracle grid's best, the classic methods'
//       E_n) and appends it to FILE (tab-separated; resumable). With --trace,
//       every grid setting's E_n and residual statistics per iteration go to
//       TRACE. About an hour on 2 cores.
//   corpus_benchmark [--reference FILE] [--results OUT]
//       the everyday run: automatic mode and fixed setting on every input,
//       compared with FILE's figures; prints one row an input and the
//       distributions (regular meshes, irregular meshes, all inputs); writes
//       the rows to OUT (tab-separated). Each mesh's noise depends on its
//       place in the sorted list of meshes, so the run stops, naming them, if
//       the meshes of the directory and those of FILE differ.
//   --stride N --offset M  only inputs M, M+N, M+2N, ... (quick looks)
//   --long-run-test        the automatic mode with the named parameter
//                          long_run_test (everyday and noise-free runs)
//   --only TEXT            only inputs whose name contains TEXT
//   corpus_benchmark --candidates
//       per input and candidate of the automatic selection: E_n and
//       statistics of the residual at its stop (tab-separated, for study)
//   corpus_benchmark --irregular [--results OUT] [--no-baselines]
//       the vertex updates on the irregular meshes: each with Gaussian noise
//       at sigma_E 0.05, 0.1 and 0.3, seed 1; per input the noisy mesh, the
//       fixed setting and the automatic mode with eq. 10 and with the
//       least-squares update, CGAL's smooth_shape() at its best time step
//       and the classic methods at their defaults (E_n, E_v, faces turned
//       against the input); --no-baselines skips the last two (their
//       errors are written as nan). Also the error of the filtered normals
//       themselves, the targets of the vertex update (after the first pass
//       of the fixed setting, and after the last pass of the fixed setting
//       and of the automatic mode), and a table per noise level of how many
//       inputs left worse than the noisy one have filtered normals that are
//       already worse than the noisy face normals
//   corpus_benchmark --held-out [--results OUT] [--stride N] [--only TEXT]
//       the automatic mode and the fixed setting on inputs outside the
//       development corpus: every corpus mesh with noise of other kinds,
//       levels and seed (held_out_inputs()); E_n, E_v and times, and per
//       group how many inputs end worse than the noisy one and how the
//       automatic mode compares with the fixed setting. No oracle: nothing
//       is fitted to these inputs
//   corpus_benchmark --noise-free [--results OUT]
//       the automatic mode on every corpus mesh as it is, with no noise
//       added: how far it moves a mesh that needs no denoising (E_n and E_v
//       of its result against the mesh), the iterations kept and why
//
// Inputs (the rule, applied to the meshes sorted by file name, index i):
// Gaussian noise along vertex normals at sigma_E L[i mod 5] and
// L[(i + 2) mod 5], L = {0.1, 0.2, 0.3, 0.5, 0.7}; simulated depth-scan noise
// (add_depth_scan_noise) at 0.2 (odd i) or 0.4 (even i); and, for even i,
// impulsive noise (10% of the vertices, sigma_E 1.0). Seed 1 everywhere. A
// mesh whose longest edge is over 50 times its shortest is "irregular" and
// reported as a separate group.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_selection.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/residual_statistics.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_iterations.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <denoising_support/benchmark_common.h>
#include <denoising_support/classic_method_list.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace D = CGAL::Polygon_mesh_processing::internal::Denoising;
typedef CGAL::Parallel_if_available_tag Tag;

namespace {

constexpr std::size_t min_faces = 1000, max_faces = 60000;
constexpr double irregular_edge_ratio = 50.;
constexpr unsigned int seed = 1;

struct Corpus_mesh
{
  std::string file;
  std::size_t faces = 0;
  bool irregular = false;
};

struct Noise
{
  std::string label; // e.g. "gauss0.3", "impulse10%1.0", "depth0.4"
  enum Kind
  {
    GAUSSIAN,
    IMPULSIVE,
    DEPTH,
    ISOTROPIC // Gaussian in random directions (held-out inputs only)
  } kind;
  double sigma;
};

struct Input
{
  Corpus_mesh mesh;
  Noise noise;
  unsigned int noise_seed = seed;
  std::string key() const { return mesh.file + "\t" + noise.label + "\t" + std::to_string(noise_seed); }
  std::string name() const { return mesh.file + " " + noise.label; }
};

std::string meshes_dir() { return CGAL::data_file_path("meshes"); }

bool load(const std::string& file, Mesh& m)
{
  m.clear();
  return denoising_support::read_triangle_mesh(meshes_dir() + "/" + file, m);
}

double edge_length_ratio(const Mesh& m)
{
  double lo = 1e300, hi = 0.;
  for(auto e : edges(m))
  {
    const double l = std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
    if(l > 0.)
      lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  return hi > 0. && lo < 1e300 ? hi / lo : 0.;
}

std::vector<Corpus_mesh> corpus_meshes()
{
  std::vector<std::string> files;
  for(const auto& entry : std::filesystem::directory_iterator(meshes_dir()))
    if(entry.path().extension() == ".off")
      files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  std::vector<Corpus_mesh> out;
  for(const std::string& f : files)
  {
    Mesh m;
    if(!load(f, m))
      continue;
    const std::size_t nf = num_faces(m);
    if(nf < min_faces || nf > max_faces)
      continue;
    out.push_back({f, nf, edge_length_ratio(m) > irregular_edge_ratio});
  }
  return out;
}

// The inputs of `meshes` (corpus_meshes()).
std::vector<Input> corpus_inputs(const std::vector<Corpus_mesh>& meshes)
{
  const double levels[5] = {0.1, 0.2, 0.3, 0.5, 0.7};
  std::vector<Input> inputs;
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    char buf[64];
    for(double level : {levels[i % 5], levels[(i + 2) % 5]})
    {
      std::snprintf(buf, sizeof buf, "gauss%.1f", level);
      inputs.push_back({meshes[i], {buf, Noise::GAUSSIAN, level}});
    }
    const double depth = i % 2 == 0 ? 0.4 : 0.2;
    std::snprintf(buf, sizeof buf, "depth%.1f", depth);
    inputs.push_back({meshes[i], {buf, Noise::DEPTH, depth}});
    if(i % 2 == 0)
      inputs.push_back({meshes[i], {"impulse10%1.0", Noise::IMPULSIVE, 1.0}});
  }
  return inputs;
}

void make_noisy(const Input& in, Mesh& reference, Mesh& noisy)
{
  if(!load(in.mesh.file, reference))
  {
    std::cerr << "cannot read " << in.mesh.file << "\n";
    std::exit(1);
  }
  noisy = reference;
  const auto np = CGAL::parameters::random_seed(in.noise_seed);
  switch(in.noise.kind)
  {
  case Noise::GAUSSIAN:
    PMP::add_gaussian_noise(noisy, in.noise.sigma, np);
    break;
  case Noise::IMPULSIVE:
    PMP::add_impulsive_noise(noisy, 0.1, in.noise.sigma, np);
    break;
  case Noise::DEPTH:
    PMP::add_depth_scan_noise(noisy, in.noise.sigma, np);
    break;
  case Noise::ISOTROPIC:
    PMP::add_isotropic_gaussian_noise(noisy, in.noise.sigma, np);
    break;
  }
}

// The six classic methods at their defaults (denoising_support/classic_method_list.h).
const std::array<denoising_support::Classic_method<Mesh>, 6>& classic_methods()
{
  return denoising_support::classic_methods<Tag, Mesh>();
}
constexpr std::size_t n_classic = 6;

std::vector<double> classic_errors(const Mesh& noisy, const Mesh& reference)
{
  std::vector<double> errors;
  for(const auto& method : classic_methods())
  {
    Mesh m = noisy;
    method.run(m, false);
    errors.push_back(PMP::face_normal_error(m, reference));
  }
  return errors;
}

// What depends only on the input.
struct Reference
{
  std::size_t faces = 0;
  double noisy_En = 0., noisy_Ev = 0.;
  double oracle_En = 1e30, oracle_sigma = 0., oracle_radius = 0.;
  unsigned int oracle_k = 0;
  std::vector<double> classic;
};

// The oracle grid: sigma_s = sigma_r in {0.2, 0.3, 0.5, 0.8, 1.4}, r in
// {2, 3, 4, 6} d, v = 2, k = 1..60 (E_n read after every iteration), square
// pattern, fold safeguard on: the intrinsic filter's own loop.
void oracle(const Mesh& noisy, const Mesh& reference, Reference& out, std::FILE* trace, const std::string& name)
{
  const double sigmas[] = {0.2, 0.3, 0.5, 0.8, 1.4};
  const double radii[] = {2., 3., 4., 6.};
  constexpr unsigned int kmax = 60, v_iter = 2;
  const D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters> maps(noisy, CGAL::parameters::default_values());
  // the reference's own maps: a Surface_mesh's point map belongs to one mesh
  const D::Flat_mesh ref =
      D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters>(reference, CGAL::parameters::default_values())
          .flat(reference, "oracle");
  for(double r : radii)
  {
    const auto np = CGAL::parameters::relative_neighbor_radius(r);
    D::Intrinsic_setup base = D::make_intrinsic_setup<Tag>(noisy, D::read_filter_options(np), maps, "oracle");
    const double L = D::mean_edge_length(base.mesh);
    const D::Csr adjacency = D::vertex_adjacency(base.mesh);
    D::Face_data ref_fd;
    D::compute_face_data<CGAL::Sequential_tag>(base.mesh, ref.points, ref_fd);
    for(double sigma : sigmas)
    {
      D::Intrinsic_kernel kernel = base.kernel;
      kernel.sigma_spatial = kernel.sigma_range = sigma;
      std::vector<D::Vec3> points = base.mesh.points;
      const std::vector<D::Vec3> input_points = points;
      const std::vector<char> fixed(points.size(), 0);
      D::Fold_safeguard guard;
      guard.enabled = true;
      guard.reference = &base.input_faces.normals;
      D::iterate_filter<Tag>(base, kernel, base.input_faces, points, fixed, v_iter, guard, kmax,
                             [&](unsigned int k, const std::vector<D::Vec3>& p, std::vector<D::Vec3>&) {
                               D::Face_data fd;
                               D::compute_face_data<Tag>(base.mesh, p, fd);
                               const double En = D::mean_angle_degrees(fd.normals, ref_fd.normals);
                               if(En < out.oracle_En)
                               {
                                 out.oracle_En = En;
                                 out.oracle_sigma = sigma;
                                 out.oracle_radius = r;
                                 out.oracle_k = k;
                               }
                               if(trace)
                               {
                                 const D::Residual_statistics st =
                                     D::residual_statistics(adjacency, p, input_points, L);
                                 std::fprintf(trace, "%s\t%.1f\t%.1f\t%u\t%.4f\t%.5f\t%.5f\n", name.c_str(), sigma, r,
                                              k, En, st.rms, st.correlation);
                               }
                               return true;
                             });
    }
  }
}

// --candidates: for every candidate of the automatic selection, run on the
// input with its stopping rule, E_n and statistics of its residual at the
// stop, one tab-separated line each (for studying the selection).
void candidate_statistics(const Input& in, std::FILE* out)
{
  Mesh reference, noisy;
  make_noisy(in, reference, noisy);
  const auto np = CGAL::parameters::default_values();
  const D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters> maps(noisy, np);
  const D::Flat_mesh ref =
      D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters>(reference, np).flat(reference, "candidates");
  const D::Flat_mesh input = maps.flat(noisy, "candidates");
  const std::vector<char> constrained(num_vertices(noisy), 0);
  D::Face_data ref_fd, in_fd;
  D::compute_face_data<CGAL::Sequential_tag>(ref, ref.points, ref_fd);
  const D::Csr adjacency = D::vertex_adjacency(input);
  const double L = D::mean_edge_length(input);
  std::vector<std::vector<D::Vec3>> results;
  std::vector<D::Candidate_run> runs;
  D::Automatic_selection<Tag> selection(2, true, false);
  for(std::size_t c = 0; c < D::Selection_rules::number_of_candidates; ++c)
  {
    const auto& k = D::Selection_rules::candidates[c];
    if(c == 0 || k.relative_radius != D::Selection_rules::candidates[c - 1].relative_radius)
    {
      D::Setup_defaults d;
      d.sigma_spatial = d.sigma_range = k.sigma;
      d.relative_radius = k.relative_radius;
      selection.setup_paths(D::make_intrinsic_setup<Tag>(noisy, D::read_filter_options(np), maps, "candidates",
                                                         [&d](const D::Flat_mesh&) { return d; }),
                            constrained);
    }
    selection.run(k.sigma);
  }
  selection.choose();
  for(const D::Candidate_run& r : selection.runs())
  {
    // the result's face normals against the reference (input face order)
    D::Face_data fd;
    D::compute_face_data<CGAL::Sequential_tag>(input, r.points, fd);
    const double En = D::mean_angle_degrees(fd.normals, ref_fd.normals);
    // residual along the result's vertex normals
    D::Flat_mesh result = input;
    result.points = r.points;
    const std::vector<D::Vec3> vn = D::area_weighted_vertex_normals(result);
    std::vector<double> s(input.points.size(), 0.), mag(input.points.size(), 0.);
    double s2 = 0., s4 = 0.;
    std::size_t n = 0;
    for(std::size_t v = 0; v < s.size(); ++v)
    {
      const D::Vec3 rv = input.points[v] - r.points[v];
      mag[v] = D::norm(rv) / L;
      if(adjacency.begin(v) == adjacency.end(v))
        continue;
      s[v] = D::dot(rv, vn[v]) / L;
      s2 += s[v] * s[v];
      s4 += s[v] * s[v] * s[v] * s[v];
      ++n;
    }
    const double kurtosis = s2 > 0. ? double(n) * s4 / (s2 * s2) : 0.;
    const double rms = std::sqrt(s2 / double(std::max<std::size_t>(n, 1)));
    // correlation among the large residuals (both above twice the RMS)
    double tail_cross = 0., tail_energy = 0.;
    for(std::size_t v = 0; v < s.size(); ++v)
      for(std::uint32_t q = adjacency.begin(v); q < adjacency.end(v); ++q)
      {
        const std::uint32_t u = adjacency.items[q];
        if(u <= v || std::abs(s[v]) < 2. * rms || std::abs(s[u]) < 2. * rms)
          continue;
        tail_cross += s[u] * s[v];
        tail_energy += 0.5 * (s[u] * s[u] + s[v] * s[v]);
      }
    // share of the residual energy in the 5% largest
    std::vector<double> e2 = mag;
    for(double& x : e2)
      x *= x;
    std::sort(e2.begin(), e2.end(), std::greater<double>());
    double top = 0., all = 0.;
    for(std::size_t i = 0; i < e2.size(); ++i)
    {
      all += e2[i];
      if(i < e2.size() / 20)
        top += e2[i];
    }
    // flat-edge share of the result (1 degree)
    std::size_t flat = 0, edges_n = 0;
    for(std::size_t f = 0; f < input.number_of_faces(); ++f)
      D::for_each_edge_adjacent_face_after(input, f, [&](std::uint32_t g) {
        ++edges_n;
        flat += D::dot(fd.normals[f], fd.normals[g]) > std::cos(3.14159265358979 / 180.) ? 1 : 0;
      });
    // the result kept only at the vertices whose residual is far above the
    // median residual (the input elsewhere): E_n for 2, 3 and 4 medians
    std::vector<double> sorted_mag = mag;
    std::nth_element(sorted_mag.begin(), sorted_mag.begin() + sorted_mag.size() / 2, sorted_mag.end());
    const double median = sorted_mag[sorted_mag.size() / 2];
    double blended[3], rough_blend = 0., rough_result = 0.;
    std::size_t beyond4 = 0;
    for(double x : mag)
      beyond4 += x > 4. * median ? 1 : 0;
    for(int b = 0; b < 3; ++b)
    {
      std::vector<D::Vec3> pts = input.points;
      for(std::size_t v = 0; v < pts.size(); ++v)
        if(mag[v] > double(b + 2) * median)
          pts[v] = r.points[v];
      D::Face_data bfd;
      D::compute_face_data<CGAL::Sequential_tag>(input, pts, bfd);
      blended[b] = D::mean_angle_degrees(bfd.normals, ref_fd.normals);
      if(b == 2)
      {
        // mean dihedral angle (degrees) of the blend and of the result
        auto roughness = [&](const D::Face_data& x) {
          double sum = 0.;
          std::size_t count = 0;
          for(std::size_t f = 0; f < input.number_of_faces(); ++f)
            D::for_each_edge_adjacent_face_after(input, f, [&](std::uint32_t g) {
              sum += std::acos(std::max(-1., std::min(1., D::dot(x.normals[f], x.normals[g]))));
              ++count;
            });
          return count ? sum / double(count) * 180. / 3.14159265358979 : 0.;
        };
        rough_blend = roughness(bfd);
        rough_result = roughness(fd);
      }
    }
    const D::Residual_statistics st = r.iterations > 0 ? r.trajectory[r.iterations - 1] : D::Residual_statistics();
    std::fprintf(
        out,
        "%s\t%.1f\t%.1f\t%u\t%d\t%.4f\t%.5f\t%.5f\t%.5f\t%.4f\t%.5f\t%.4f\t%.4f\t%.4f\t%.4f\t%.4f\t%.5f\t%.4f\t%.4f\n",
        in.name().c_str(), r.sigma, r.relative_radius, r.iterations, int(r.stopped_by_correlation), En, st.rms,
        st.correlation, r.score, kurtosis, tail_energy > 0. ? tail_cross / tail_energy : 0., all > 0. ? top / all : 0.,
        edges_n ? double(flat) / double(edges_n) : 0., blended[0], blended[1], blended[2],
        double(beyond4) / double(mag.size()), rough_blend, rough_result);
  }
  std::fflush(out);
}

std::map<std::string, Reference> read_reference(const std::string& file)
{
  std::map<std::string, Reference> refs;
  std::ifstream in(file);
  std::string line;
  while(std::getline(in, line))
  {
    if(line.empty() || line[0] == '#')
      continue;
    std::istringstream ss(line);
    std::string mesh, noise, s;
    std::getline(ss, mesh, '\t');
    std::getline(ss, noise, '\t');
    std::getline(ss, s, '\t');
    Reference r;
    ss >> r.faces >> r.noisy_En >> r.noisy_Ev >> r.oracle_En >> r.oracle_sigma >> r.oracle_radius >> r.oracle_k;
    r.classic.resize(n_classic);
    for(double& c : r.classic)
      ss >> c;
    if(ss)
      refs[mesh + "\t" + noise + "\t" + s] = r;
  }
  return refs;
}

// The differences between the corpus meshes `meshes` (corpus_meshes()) and
// the meshes of `refs`: the file names in one and not in the other. Each mesh's noise
// depends on its place in the sorted list, so a file added to the meshes
// directory (a denoised output saved beside its input, say) or missing from
// it gives every mesh after it other inputs than those of the reference.
std::vector<std::string> meshes_unlike_reference(const std::map<std::string, Reference>& refs,
                                                 const std::vector<Corpus_mesh>& meshes)
{
  std::set<std::string> known, present;
  for(const auto& r : refs)
    known.insert(r.first.substr(0, r.first.find('\t')));
  for(const Corpus_mesh& m : meshes)
    present.insert(m.file);
  std::vector<std::string> differ;
  std::set_symmetric_difference(known.begin(), known.end(), present.begin(), present.end(), std::back_inserter(differ));
  return differ;
}

using denoising_support::quantile;

struct Row
{
  Input in;
  Reference ref;
  double auto_En = 0., auto_Ev = 0., fixed_En = 0., fixed_Ev = 0., auto_s = 0., fixed_s = 0.;
  // the noisy input's errors computed in this run: the reference file's are
  // rounded, and a result equal to the input must not count as worse
  double noisy_En = 0., noisy_Ev = 0.;
  std::string chosen;
};

// Makes `in` noisy, runs the automatic mode and the fixed setting on it (each
// timed), and fills the errors and times of `row`; returns the automatic
// mode's report.
// --long-run-test: the automatic mode with the named parameter long_run_test
bool long_run_test = false;

PMP::Intrinsic_denoising_report measure_auto_and_fixed(const Input& in, Row& row)
{
  Mesh reference, noisy;
  make_noisy(in, reference, noisy);
  Mesh a = noisy, f = noisy;
  denoising_support::Stopwatch watch;
  const PMP::Intrinsic_denoising_report rep =
      PMP::intrinsic_denoising<Tag>(a, CGAL::parameters::long_run_test(long_run_test));
  row.auto_s = watch.seconds();
  watch.restart();
  PMP::intrinsic_denoising<Tag>(f, CGAL::parameters::automatic_parameters(false));
  row.fixed_s = watch.seconds();
  row.auto_En = PMP::face_normal_error(a, reference);
  row.auto_Ev = PMP::vertex_position_error(a, reference);
  row.fixed_En = PMP::face_normal_error(f, reference);
  row.fixed_Ev = PMP::vertex_position_error(f, reference);
  row.noisy_En = PMP::face_normal_error(noisy, reference);
  row.noisy_Ev = PMP::vertex_position_error(noisy, reference);
  return rep;
}

// Inputs that meet a condition: how many, and their names.
struct Named_inputs
{
  std::size_t count = 0;
  std::string names; // ", "-separated, after a space
  void add(const std::string& name) { names += (count++ == 0 ? " " : ", ") + name; }
};

void summary(const std::vector<Row>& rows, const char* group)
{
  if(rows.empty())
    return;
  std::vector<double> vs_oracle, vs_fixed, vs_classic, time_ratio;
  std::size_t within10 = 0, within25 = 0, fixed_ok = 0, classic_ok = 0, depth = 0, depth_ok = 0, oracle_classic_ok = 0;
  // the inputs that miss a target; `unimproved`: those worse than the noisy
  // input that no method of the reference brings below it either
  Named_inputs worse_En, worse_Ev, unimproved, over_fixed_5, slow;
  for(const Row& r : rows)
  {
    const double best_classic = *std::min_element(r.ref.classic.begin(), r.ref.classic.end());
    vs_oracle.push_back(r.auto_En / r.ref.oracle_En);
    vs_fixed.push_back(r.auto_En / r.fixed_En);
    vs_classic.push_back(r.auto_En / best_classic);
    time_ratio.push_back(r.auto_s / r.fixed_s);
    if(r.auto_En > r.noisy_En)
    {
      worse_En.add(r.in.name());
      if(std::min(r.ref.oracle_En, best_classic) > r.noisy_En)
        unimproved.add(r.in.name());
    }
    if(r.auto_Ev > r.noisy_Ev)
      worse_Ev.add(r.in.name());
    within10 += r.auto_En <= 1.10 * r.ref.oracle_En;
    within25 += r.auto_En <= 1.25 * r.ref.oracle_En;
    fixed_ok += r.auto_En <= r.fixed_En;
    if(!(r.auto_En <= 1.05 * r.fixed_En))
      over_fixed_5.add(r.in.name());
    classic_ok += r.auto_En <= best_classic;
    oracle_classic_ok += r.ref.oracle_En <= best_classic;
    if(r.auto_s > 6. * r.fixed_s)
      slow.add(r.in.name());
    if(r.in.noise.kind == Noise::DEPTH)
    {
      ++depth;
      depth_ok += r.auto_En < r.fixed_En;
    }
  }
  const std::size_t fixed_5 = rows.size() - over_fixed_5.count;
  const double n = double(rows.size());
  std::printf("\n### %s: %zu inputs\n\n", group, rows.size());
  std::printf("| ratio | median | 90th percentile | worst |\n|---|---|---|---|\n");
  auto line = [](const char* name, const std::vector<double>& v) {
    std::printf("| %s | %.3f | %.3f | %.3f |\n", name, quantile(v, 0.5), quantile(v, 0.9), quantile(v, 1.));
  };
  line("auto / oracle (E_n)", vs_oracle);
  line("auto / fixed (E_n)", vs_fixed);
  line("auto / best classic default (E_n)", vs_classic);
  line("auto / fixed (seconds)", time_ratio);
  std::printf("\n- worse than the noisy input: E_n %zu, E_v %zu\n", worse_En.count, worse_Ev.count);
  if(worse_En.count > 0)
    std::printf("  - in E_n:%s; of these, %zu that neither the oracle nor any classic default brings below the noisy "
                "input either:%s\n",
                worse_En.names.c_str(), unimproved.count, unimproved.count == 0 ? " none" : unimproved.names.c_str());
  if(worse_Ev.count > 0)
    std::printf("  - in E_v:%s\n", worse_Ev.names.c_str());
  std::printf("- within 10%% of the oracle: %zu (%.1f%%); within 25%%: %zu (%.1f%%)\n", within10, 100. * within10 / n,
              within25, 100. * within25 / n);
  std::printf("- at least as good as the fixed setting: %zu (%.1f%%); within 5%% of it: %zu (%.1f%%)\n", fixed_ok,
              100. * fixed_ok / n, fixed_5, 100. * fixed_5 / n);
  if(over_fixed_5.count > 0)
    std::printf("  - more than 5%% worse:%s\n", over_fixed_5.names.c_str());
  std::printf("- no worse than the best classic default: %zu (%.1f%%); the oracle itself (the grid's best setting "
              "per input): %zu (%.1f%%)\n",
              classic_ok, 100. * classic_ok / n, oracle_classic_ok, 100. * oracle_classic_ok / n);
  std::printf("- depth-scan inputs better than the fixed setting: %zu of %zu\n", depth_ok, depth);
  std::printf("- over 6 times the fixed setting's time: %zu%s%s\n", slow.count, slow.count > 0 ? ":" : "",
              slow.names.c_str());
  std::vector<std::size_t> order(rows.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return vs_oracle[a] > vs_oracle[b]; });
  std::printf("- worst five by auto / oracle:");
  for(std::size_t i = 0; i < std::min<std::size_t>(5, order.size()); ++i)
    std::printf(" %s (%.2f)%s", rows[order[i]].in.name().c_str(), vs_oracle[order[i]], i + 1 < 5 ? "," : "");
  std::printf("\n");
}

// Faces of `m` whose normal points against (or is orthogonal to) the same
// face's normal in `input`; faces degenerate in either are not counted.
std::size_t turned_faces(const Mesh& m, const Mesh& input)
{
  std::size_t n = 0;
  for(auto f : faces(m))
  {
    const auto h = halfedge(f, m);
    const auto normal = [&](const Mesh& mm) {
      const K::Point_3 &a = mm.point(source(h, mm)), &b = mm.point(target(h, mm)),
                       &c = mm.point(target(next(h, mm), mm));
      return CGAL::cross_product(b - a, c - a);
    };
    const K::Vector_3 n0 = normal(input), n1 = normal(m);
    if(n0.squared_length() > 0. && n1.squared_length() > 0. && !(n0 * n1 > 0.))
      ++n;
  }
  return n;
}

struct Outcome
{
  double En = 0., Ev = 0.;
  std::size_t turned = 0;
  double seconds = 0.;
};

template <typename Method>
Outcome outcome(const Mesh& noisy, const Mesh& reference, const Method& method)
{
  Mesh m = noisy;
  const denoising_support::Stopwatch watch;
  method(m);
  Outcome o;
  o.seconds = watch.seconds();
  o.En = PMP::face_normal_error(m, reference);
  o.Ev = PMP::vertex_position_error(m, reference);
  o.turned = turned_faces(m, noisy);
  return o;
}

// The filtered normals (one per face, by face index) that `method(m, map)`
// writes to a face_normal_map `map` of a copy `m` of `noisy`, and their E_n
// against `reference`: the mean angle to its face normals (mean_angle_degrees(),
// as face_normal_error() compares two meshes).
template <typename Method>
double filtered_normals_error(const Mesh& noisy, const Mesh& reference, const Method& method)
{
  Mesh m = noisy;
  auto map = m.add_property_map<Mesh::Face_index, K::Vector_3>("f:filtered", CGAL::NULL_VECTOR).first;
  method(m, map);
  std::vector<D::Vec3> filtered, exact;
  for(auto f : faces(reference))
  {
    const auto h = halfedge(f, reference);
    const K::Point_3 &a = reference.point(source(h, reference)), &b = reference.point(target(h, reference)),
                     &c = reference.point(target(next(h, reference), reference));
    const K::Vector_3 n = CGAL::cross_product(b - a, c - a), g = get(map, f);
    exact.push_back({n.x(), n.y(), n.z()});
    filtered.push_back({g.x(), g.y(), g.z()});
  }
  return D::mean_angle_degrees(filtered, exact);
}

// Per noise level of the irregular study: inputs that a mode leaves worse
// than the noisy input in E_n, and among them those whose filtered normals
// (the targets of the vertex update) are already further from the reference
// than the noisy face normals are.
struct Normals_tally
{
  std::size_t inputs = 0, fixed_worse = 0, fixed_worse_normals = 0, first_pass_worse = 0, auto_worse = 0,
              auto_worse_normals = 0, auto_at_most_smooth = 0, auto_normals_at_most_smooth = 0;
  Named_inputs auto_worse_names;
};

// --irregular: see the usage at the top.
void irregular_study(const std::vector<Input>& inputs, std::FILE* results, bool baselines)
{
  const char* const columns[] = {"fixed_paper", "fixed_ls", "auto_paper", "auto_ls", "smooth_shape", "best_classic"};
  if(results)
  {
    std::fprintf(results, "# mesh\tnoise\tseed\tnoisy_En\tnoisy_Ev");
    for(const char* c : columns)
      std::fprintf(results, "\t%s_En\t%s_Ev\t%s_turned\t%s_s", c, c, c, c);
    std::fprintf(results,
                 "\tsmooth_time\tfixed_first_pass_normals_En\tfixed_paper_normals_En\tauto_paper_normals_En\n");
  }
  std::map<double, Normals_tally> tally;
  std::printf(
      "| input | noisy | fixed eq.10 | fixed LS | auto eq.10 | auto LS | smooth_shape (best) | best classic | "
      "turned (fixed LS, auto LS) | s (fixed eq.10, fixed LS, auto LS) |\n|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> seen;
  for(const Input& in0 : inputs)
  {
    if(!in0.mesh.irregular || std::find(seen.begin(), seen.end(), in0.mesh.file) != seen.end())
      continue;
    seen.push_back(in0.mesh.file);
    for(double level : {0.05, 0.1, 0.3})
    {
      char label[32];
      std::snprintf(label, sizeof label, "gauss%.2f", level);
      const Input in{in0.mesh, {label, Noise::GAUSSIAN, level}};
      Mesh reference, noisy;
      make_noisy(in, reference, noisy);
      const double noisy_En = PMP::face_normal_error(noisy, reference);
      const double noisy_Ev = PMP::vertex_position_error(noisy, reference);
      const auto fixed = [](PMP::Vertex_update u) {
        return [u](Mesh& m) {
          PMP::intrinsic_denoising<Tag>(m, CGAL::parameters::automatic_parameters(false).vertex_update(u));
        };
      };
      const auto automatic = [](PMP::Vertex_update u) {
        return [u](Mesh& m) { PMP::intrinsic_denoising<Tag>(m, CGAL::parameters::vertex_update(u)); };
      };
      std::vector<Outcome> o;
      o.push_back(outcome(noisy, reference, fixed(PMP::Vertex_update::PAPER)));
      o.push_back(outcome(noisy, reference, fixed(PMP::Vertex_update::LEAST_SQUARES)));
      o.push_back(outcome(noisy, reference, automatic(PMP::Vertex_update::PAPER)));
      o.push_back(outcome(noisy, reference, automatic(PMP::Vertex_update::LEAST_SQUARES)));
      // smooth_shape: one step, time = c * (mean edge length)^2, best c
      double L = 0.;
      for(auto e : edges(noisy))
        L += std::sqrt(CGAL::squared_distance(noisy.point(source(e, noisy)), noisy.point(target(e, noisy))));
      L /= double(num_edges(noisy));
      Outcome best_smooth;
      best_smooth.En = 1e300;
      double best_time = 0.;
      for(double c : {0.01, 0.03, 0.1, 0.3, 1., 3., 10., 30.})
        if(baselines)
        {
          const Outcome s = outcome(noisy, reference, [&](Mesh& m) { PMP::smooth_shape(m, c * L * L); });
          if(s.En < best_smooth.En)
          {
            best_smooth = s;
            best_time = c;
          }
        }
      o.push_back(best_smooth);
      Outcome best_classic;
      best_classic.En = 1e300;
      for(const auto& c : classic_methods())
        if(baselines)
        {
          const Outcome r = outcome(noisy, reference, [&c](Mesh& m) { c.run(m, false); });
          if(r.En < best_classic.En)
            best_classic = r;
        }
      o.push_back(best_classic);
      // the filtered normals themselves: after the first pass of the fixed
      // setting (no vertex update yet) and after the last pass of the fixed
      // setting and of the automatic mode (eq. 10)
      const auto normals_of = [&](auto np) {
        return filtered_normals_error(
            noisy, reference, [&](Mesh& m, auto map) { PMP::intrinsic_denoising<Tag>(m, np.face_normal_map(map)); });
      };
      const double first_pass_normals =
          normals_of(CGAL::parameters::automatic_parameters(false).number_of_iterations(1));
      const double fixed_normals = normals_of(CGAL::parameters::automatic_parameters(false));
      const double auto_normals = normals_of(CGAL::parameters::automatic_parameters(true));
      if(!baselines) // not run: "nan" in the results file
        for(std::size_t i = 4; i < o.size(); ++i)
          o[i].En = o[i].Ev = std::numeric_limits<double>::quiet_NaN();
      char smooth[64] = "-", classic[32] = "-";
      if(baselines)
      {
        std::snprintf(smooth, sizeof smooth, "%.2f (%gL^2)", o[4].En, best_time);
        std::snprintf(classic, sizeof classic, "%.2f", o[5].En);
      }
      std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %s | %s | %zu, %zu | %.2f, %.2f, %.2f |\n",
                  in.name().c_str(), noisy_En, o[0].En, o[1].En, o[2].En, o[3].En, smooth, classic, o[1].turned,
                  o[3].turned, o[0].seconds, o[1].seconds, o[3].seconds);
      std::fflush(stdout);
      if(results)
      {
        std::fprintf(results, "%s\t%.4f\t%.4g", in.key().c_str(), noisy_En, noisy_Ev);
        for(const Outcome& x : o)
          std::fprintf(results, "\t%.4f\t%.4g\t%zu\t%.3f", x.En, x.Ev, x.turned, x.seconds);
        std::fprintf(results, "\t%g\t%.4f\t%.4f\t%.4f\n", best_time, first_pass_normals, fixed_normals, auto_normals);
        std::fflush(results);
      }
      Normals_tally& t = tally[level];
      ++t.inputs;
      t.first_pass_worse += first_pass_normals > noisy_En;
      if(o[0].En > noisy_En)
      {
        ++t.fixed_worse;
        t.fixed_worse_normals += fixed_normals > noisy_En;
      }
      if(o[2].En > noisy_En)
      {
        ++t.auto_worse;
        t.auto_worse_normals += auto_normals > noisy_En;
        t.auto_worse_names.add(in0.mesh.file);
      }
      t.auto_at_most_smooth += o[2].En <= o[4].En;
      t.auto_normals_at_most_smooth += auto_normals <= o[4].En;
    }
  }
  std::printf("\nWhere the error comes from: the filtered normals (the targets of the vertex update) against the "
              "noisy face normals, eq. 10\n\n| sigma_E | inputs | first pass of the fixed setting worse than noisy | "
              "fixed E_n worse than noisy / of them with filtered normals worse | automatic E_n worse than noisy / "
              "of them with filtered normals worse | automatic E_n at most smooth_shape's / its filtered normals "
              "at most smooth_shape's E_n |\n|---|---|---|---|---|---|\n");
  for(const auto& [level, t] : tally)
    std::printf("| %.2f | %zu | %zu | %zu / %zu | %zu / %zu%s | %zu / %zu |\n", level, t.inputs, t.first_pass_worse,
                t.fixed_worse, t.fixed_worse_normals, t.auto_worse, t.auto_worse_normals,
                t.auto_worse_names.names.c_str(), t.auto_at_most_smooth, t.auto_normals_at_most_smooth);
}

// The held-out inputs (--held-out): every corpus mesh with noise that the
// development inputs do not have, seed 2: Gaussian noise in random directions
// (add_isotropic_gaussian_noise()) at sigma_E 0.15 and 0.4, Gaussian noise
// along the normals at 0.4 and depth-scan noise at 0.3.
std::vector<Input> held_out_inputs(const std::vector<Corpus_mesh>& meshes)
{
  std::vector<Input> inputs;
  for(const Corpus_mesh& m : meshes)
    for(const Noise& n : {Noise{"isotropic0.15", Noise::ISOTROPIC, 0.15}, Noise{"isotropic0.4", Noise::ISOTROPIC, 0.4},
                          Noise{"gauss0.4", Noise::GAUSSIAN, 0.4}, Noise{"depth0.3", Noise::DEPTH, 0.3}})
      inputs.push_back({m, n, 2u});
  return inputs;
}

// --held-out: see the usage at the top.
void held_out_study(const std::vector<Input>& inputs, std::FILE* results)
{
  if(results)
    std::fprintf(results, "# mesh\tnoise\tseed\tgroup\tnoisy_En\tauto_En\tfixed_En\tnoisy_Ev\tauto_Ev\tfixed_Ev\t"
                          "auto_s\tfixed_s\n");
  std::printf("| input | noisy E_n | auto | fixed | noisy E_v | auto | fixed | auto s | fixed s |\n"
              "|---|---|---|---|---|---|---|---|---|\n");
  struct Group
  {
    std::vector<double> vs_fixed, time_ratio;
    std::size_t n = 0, fixed_ok = 0;
    Named_inputs worse_En, worse_Ev, over_fixed_5;
  };
  std::map<std::string, Group> groups; // "regular", "irregular", "all inputs"
  for(const Input& in : inputs)
  {
    Row r;
    measure_auto_and_fixed(in, r);
    const char* group = in.mesh.irregular ? "irregular" : "regular";
    std::printf("| %s | %.2f | %.2f | %.2f | %.3g | %.3g | %.3g | %.3f | %.3f |\n", in.name().c_str(), r.noisy_En,
                r.auto_En, r.fixed_En, r.noisy_Ev, r.auto_Ev, r.fixed_Ev, r.auto_s, r.fixed_s);
    std::fflush(stdout);
    if(results)
    {
      std::fprintf(results, "%s\t%s\t%.4f\t%.4f\t%.4f\t%.4g\t%.4g\t%.4g\t%.3f\t%.3f\n", in.key().c_str(), group,
                   r.noisy_En, r.auto_En, r.fixed_En, r.noisy_Ev, r.auto_Ev, r.fixed_Ev, r.auto_s, r.fixed_s);
      std::fflush(results);
    }
    for(const char* name : {group, "all inputs"})
    {
      Group& g = groups[name];
      ++g.n;
      g.vs_fixed.push_back(r.auto_En / r.fixed_En);
      g.time_ratio.push_back(r.auto_s / r.fixed_s);
      g.fixed_ok += r.auto_En <= r.fixed_En;
      if(r.auto_En > r.noisy_En)
        g.worse_En.add(in.name());
      if(r.auto_Ev > r.noisy_Ev)
        g.worse_Ev.add(in.name());
      if(!(r.auto_En <= 1.05 * r.fixed_En))
        g.over_fixed_5.add(in.name());
    }
  }
  for(const char* name : {"regular", "irregular", "all inputs"})
  {
    const auto it = groups.find(name);
    if(it == groups.end())
      continue;
    const Group& g = it->second;
    const double n = double(g.n);
    std::printf("\n### held-out inputs, %s: %zu\n\n", name, g.n);
    std::printf("- auto / fixed (E_n): median %.3f, 90th percentile %.3f, worst %.3f\n", quantile(g.vs_fixed, 0.5),
                quantile(g.vs_fixed, 0.9), quantile(g.vs_fixed, 1.));
    std::printf("- auto / fixed (seconds): median %.2f, 90th percentile %.2f, worst %.2f\n",
                quantile(g.time_ratio, 0.5), quantile(g.time_ratio, 0.9), quantile(g.time_ratio, 1.));
    std::printf("- worse than the noisy input: E_n %zu%s%s; E_v %zu%s%s\n", g.worse_En.count,
                g.worse_En.count ? ":" : "", g.worse_En.names.c_str(), g.worse_Ev.count, g.worse_Ev.count ? ":" : "",
                g.worse_Ev.names.c_str());
    std::printf("- at least as good as the fixed setting: %zu (%.1f%%); within 5%% of it: %zu (%.1f%%)%s%s\n",
                g.fixed_ok, 100. * g.fixed_ok / n, g.n - g.over_fixed_5.count, 100. * (g.n - g.over_fixed_5.count) / n,
                g.over_fixed_5.count ? "; more than 5% worse:" : "", g.over_fixed_5.names.c_str());
  }
}

// --noise-free: see the usage at the top. Every mesh of `inputs` once.
void noise_free_study(const std::vector<Input>& inputs, std::FILE* results)
{
  std::set<std::string> seen;
  std::vector<double> changes;
  Named_inputs moved;
  std::printf("| mesh | faces | E_n (deg) | E_v | iterations | stop |\n|---|---|---|---|---|---|\n");
  if(results)
    std::fprintf(results, "# mesh\tfaces\tauto_En\tauto_Ev\titerations\tstop\tchange_angle\tsecond_pass_angle\n");
  for(const Input& in : inputs)
  {
    if(!seen.insert(in.mesh.file).second)
      continue;
    Mesh reference;
    if(!load(in.mesh.file, reference))
    {
      std::cerr << "cannot read " << in.mesh.file << "\n";
      std::exit(1);
    }
    Mesh m = reference;
    const PMP::Intrinsic_denoising_report rep =
        PMP::intrinsic_denoising<Tag>(m, CGAL::parameters::long_run_test(long_run_test));
    const double En = PMP::face_normal_error(m, reference), Ev = PMP::vertex_position_error(m, reference);
    const char* stop = rep.stop_reason == PMP::Intrinsic_stop_reason::SECOND_PASS           ? "second pass"
                       : rep.stop_reason == PMP::Intrinsic_stop_reason::SELF_CHECK          ? "self-check"
                       : rep.stop_reason == PMP::Intrinsic_stop_reason::RESIDUAL_CORRELATED ? "residual"
                       : rep.stop_reason == PMP::Intrinsic_stop_reason::LONG_RUN            ? "long run"
                                                                                            : "limit";
    std::printf("| %s%s | %zu | %.3f | %.3g | %u | %s |\n", in.mesh.file.c_str(),
                in.mesh.irregular ? " (irregular)" : "", in.mesh.faces, En, Ev, rep.iterations, stop);
    std::fflush(stdout);
    if(results)
    {
      std::fprintf(results, "%s\t%zu\t%.4f\t%.5g\t%u\t%s\t%.4f\t%.4f\n", in.mesh.file.c_str(), in.mesh.faces, En, Ev,
                   rep.iterations, stop, rep.change_angle, rep.second_pass_angle);
      std::fflush(results);
    }
    changes.push_back(En);
    if(En > 1.)
      moved.add(in.mesh.file + " (" + std::to_string(En).substr(0, 5) + ")");
  }
  std::printf("\n%zu noise-free meshes: E_n of the automatic mode's result against the mesh: median %.3f, 90th "
              "percentile %.3f, worst %.3f degrees; unchanged (E_n 0): %zu; over 1 degree: %zu%s\n",
              changes.size(), quantile(changes, 0.5), quantile(changes, 0.9), quantile(changes, 1.),
              std::size_t(std::count(changes.begin(), changes.end(), 0.)), moved.count, moved.names.c_str());
}

} // namespace

int main(int argc, char** argv)
{
  std::string reference_file = std::string(CORPUS_DIR) + "/corpus_reference.tsv", build_file, trace_file, results_file,
              only;
  bool list = false, candidates = false, irregular_mode = false, baselines = true, noise_free = false, held_out = false;
  std::size_t stride = 1, offset = 0;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if(i + 1 >= argc)
      {
        std::cerr << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if(a == "--list")
      list = true;
    else if(a == "--candidates")
      candidates = true;
    else if(a == "--irregular")
      irregular_mode = true;
    else if(a == "--noise-free")
      noise_free = true;
    else if(a == "--held-out")
      held_out = true;
    else if(a == "--long-run-test")
      long_run_test = true;
    else if(a == "--no-baselines")
      baselines = false;
    else if(a == "--build-reference")
      build_file = next();
    else if(a == "--trace")
      trace_file = next();
    else if(a == "--reference")
      reference_file = next();
    else if(a == "--results")
      results_file = next();
    else if(a == "--stride")
      stride = std::max<std::size_t>(1, std::stoul(next()));
    else if(a == "--offset")
      offset = std::stoul(next());
    else if(a == "--only")
      only = next();
    else
    {
      std::cerr
          << "usage: corpus_benchmark [--list] [--build-reference FILE [--trace FILE]] [--reference FILE] "
             "[--results FILE] [--stride N] [--offset M] [--only TEXT] [--candidates] [--irregular [--no-baselines]] "
             "[--noise-free] [--held-out]\n";
      return 2;
    }
  }
  const std::vector<Corpus_mesh> meshes = corpus_meshes(); // each file read once
  std::vector<Input> inputs;
  {
    const std::vector<Input> all = held_out ? held_out_inputs(meshes) : corpus_inputs(meshes);
    for(std::size_t i = offset; i < all.size(); i += stride)
      if(only.empty() || all[i].name().find(only) != std::string::npos)
        inputs.push_back(all[i]);
  }
  if(list)
  {
    for(const Input& in : inputs)
      std::printf("%s\t%zu faces\t%s\n", in.name().c_str(), in.mesh.faces, in.mesh.irregular ? "irregular" : "regular");
    return 0;
  }
  // a study with its results file (none without --results)
  const auto study = [&](const auto& run) {
    std::FILE* results = results_file.empty() ? nullptr : std::fopen(results_file.c_str(), "w");
    run(results);
    if(results)
      std::fclose(results);
    return 0;
  };
  if(irregular_mode)
    return study([&](std::FILE* results) { irregular_study(inputs, results, baselines); });
  if(held_out)
    return study([&](std::FILE* results) { held_out_study(inputs, results); });
  if(noise_free)
    return study([&](std::FILE* results) { noise_free_study(inputs, results); });
  if(candidates)
  {
    for(const Input& in : inputs)
      candidate_statistics(in, stdout);
    return 0;
  }
  if(!build_file.empty())
  {
    const std::map<std::string, Reference> done = read_reference(build_file);
    std::FILE* out = std::fopen(build_file.c_str(), "a");
    std::FILE* trace = trace_file.empty() ? nullptr : std::fopen(trace_file.c_str(), "a");
    if(out == nullptr || (!trace_file.empty() && trace == nullptr))
    {
      std::cerr << "cannot write " << build_file << " or " << trace_file << "\n";
      return 1;
    }
    for(const Input& in : inputs)
    {
      if(done.count(in.key()))
        continue;
      const denoising_support::Stopwatch watch;
      Mesh reference, noisy;
      make_noisy(in, reference, noisy);
      Reference r;
      r.faces = num_faces(noisy);
      r.noisy_En = PMP::face_normal_error(noisy, reference);
      r.noisy_Ev = PMP::vertex_position_error(noisy, reference);
      oracle(noisy, reference, r, trace, in.name());
      r.classic = classic_errors(noisy, reference);
      std::fprintf(out, "%s\t%zu\t%.6g\t%.6g\t%.6g\t%.2f\t%.1f\t%u", in.key().c_str(), r.faces, r.noisy_En, r.noisy_Ev,
                   r.oracle_En, r.oracle_sigma, r.oracle_radius, r.oracle_k);
      for(double c : r.classic)
        std::fprintf(out, "\t%.6g", c);
      std::fprintf(out, "\n");
      std::fflush(out);
      if(trace)
        std::fflush(trace);
      std::printf("%s: oracle %.3f (sigma %.1f, r %.0fd, k %u), %.1f s\n", in.name().c_str(), r.oracle_En,
                  r.oracle_sigma, r.oracle_radius, r.oracle_k, watch.seconds());
      std::fflush(stdout);
    }
    std::fclose(out);
    if(trace)
      std::fclose(trace);
    return 0;
  }

  const std::map<std::string, Reference> refs = read_reference(reference_file);
  if(!refs.empty())
  {
    const std::vector<std::string> differ = meshes_unlike_reference(refs, meshes);
    if(!differ.empty())
    {
      std::cerr << "corpus_benchmark: the corpus meshes of " << meshes_dir() << " and those of the reference "
                << reference_file << " differ (in one and not in the other):";
      for(const std::string& f : differ)
        std::cerr << " " << f;
      std::cerr << "\nThe noise of each mesh depends on its place in the sorted list of meshes, so every mesh after "
                   "them would get other inputs than the reference's. Restore the directory, or rebuild the "
                   "reference (--build-reference).\n";
      return 1;
    }
  }
  std::FILE* results = results_file.empty() ? nullptr : std::fopen(results_file.c_str(), "w");
  if(results)
    std::fprintf(results, "# mesh\tnoise\tseed\tgroup\tnoisy_En\toracle_En\tauto_En\tfixed_En\tbest_classic_En\t"
                          "noisy_Ev\tauto_Ev\tfixed_Ev\tauto_s\tfixed_s\tchosen\n");
  std::printf(
      "| input | faces | noisy | oracle | auto | fixed | best classic | auto/oracle | auto s | fixed s | chosen |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<Row> regular, irregular;
  std::size_t missing = 0;
  for(const Input& in : inputs)
  {
    const auto it = refs.find(in.key());
    if(it == refs.end())
    {
      ++missing;
      continue;
    }
    Row row;
    row.in = in;
    row.ref = it->second;
    const PMP::Intrinsic_denoising_report rep = measure_auto_and_fixed(in, row);
    char changed[48] = "";
    if(rep.stop_reason == PMP::Intrinsic_stop_reason::SELF_CHECK)
      std::snprintf(changed, sizeof changed, " (self-check, from %u)", rep.candidates[rep.chosen_candidate].iterations);
    else if(rep.stop_reason == PMP::Intrinsic_stop_reason::SECOND_PASS)
      std::snprintf(changed, sizeof changed, " (second pass %.2f of %.2f: input kept)", rep.second_pass_angle,
                    rep.change_angle);
    char chosen[192];
    std::snprintf(chosen, sizeof chosen,
                  "sigma %.2f r %.1fd k %u%s noise %.3f inlier corr %.3f outliers %zu relaxed %zu", rep.sigma_spatial,
                  rep.relative_neighbor_radius, rep.iterations, changed, rep.noise_level,
                  rep.inlier_residual_correlation, rep.outlier_vertices, rep.relaxed_vertices);
    row.chosen = chosen;
    const double best_classic = *std::min_element(row.ref.classic.begin(), row.ref.classic.end());
    std::printf("| %s%s | %zu | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f | %.2f | %.2f | %s |\n", in.name().c_str(),
                in.mesh.irregular ? " (irregular)" : "", row.ref.faces, row.ref.noisy_En, row.ref.oracle_En,
                row.auto_En, row.fixed_En, best_classic, row.auto_En / row.ref.oracle_En, row.auto_s, row.fixed_s,
                chosen);
    std::fflush(stdout);
    if(results)
      std::fprintf(results, "%s\t%s\t%.4f\t%.4f\t%.4f\t%.4f\t%.4f\t%.4g\t%.4g\t%.4g\t%.3f\t%.3f\t%s\n",
                   in.key().c_str(), in.mesh.irregular ? "irregular" : "regular", row.ref.noisy_En, row.ref.oracle_En,
                   row.auto_En, row.fixed_En, best_classic, row.ref.noisy_Ev, row.auto_Ev, row.fixed_Ev, row.auto_s,
                   row.fixed_s, chosen);
    (in.mesh.irregular ? irregular : regular).push_back(row);
  }
  if(results)
    std::fclose(results);
  if(missing > 0)
    std::printf("\n%zu inputs have no reference figures (run --build-reference)\n", missing);
  summary(regular, "regular meshes");
  summary(irregular, "irregular meshes (longest edge over 50 times the shortest)");
  std::vector<Row> all = regular;
  all.insert(all.end(), irregular.begin(), irregular.end());
  summary(all, "all inputs");
  return 0;
}
