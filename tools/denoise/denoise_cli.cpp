// `denoise`: the package's command-line tool. Denoises an OFF, OBJ, PLY or
// STL triangle mesh with the intrinsic filter (Algorithm 1 of "Mesh denoising
// via generalized intrinsic filter on 2D manifold"), with every parameter of
// CGAL::Polygon_mesh_processing::intrinsic_denoising() on the command line;
// optionally adds seeded noise first and prints E_n / E_v against a reference.
//
// Run `denoise --help` for the manual (also in doc/Polygon_mesh_processing/denoise_help.txt).
// Exit status: 0 success, 1 bad input or I/O error, 2 bad usage.

#include <denoising_support/classic_method_list.h>
#include <denoising_support/comparison_report.h>
#include <denoising_support/mesh_file.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/program_options.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <unistd.h>

namespace po = boost::program_options;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef denoising_support::Mesh Mesh;

namespace {

const int exit_ok = 0, exit_input = 1, exit_usage = 2;

int fail(int code, const std::string& message)
{
  std::string line = message;
  for(char& c : line)
    if(c == '\n' || c == '\r')
      c = ' ';
  std::cerr << "denoise: " << (code == exit_usage ? "usage error: " : "error: ") << line
            << (code == exit_usage ? " (see denoise --help)\n" : "\n");
  return code;
}

struct Settings
{
  std::string input, output, reference, noisy_output;
  // signed, so that a negative value is caught (Boost would wrap it into an unsigned)
  // k, sigmas, radii and the noise level are forwarded only when given: the
  // automatic mode of intrinsic_denoising() chooses the others
  long long iterations = 30, vertex_iterations = 2, patch_rings = 0, seed = 1;
  long long selection_sample =
      static_cast<long long>(CGAL::Polygon_mesh_processing::Intrinsic_denoising_report::default_selection_sample_faces);
  double sigma_spatial = 0.4, sigma_range = 0.4, radius = 0., relative_radius = 4., noise_level = 0.;
  bool fixed = false, progress = false;
  std::string stop_when_converged;
  double spatial_exponent = 1., range_exponent = 1.;
  std::string paths = "square", threads = "all", vertex_update = "paper", relax;
  bool step_length = false, self_weight = false, no_fold_guard = false, quiet = false, long_run_test = false;
  double noise = 0., impulsive = 1.;
  std::string noise_kind = "normal";
};

const char* const help_head = R"(NAME
    denoise - feature-preserving mesh denoising with the intrinsic filter

SYNOPSIS
    denoise [OPTIONS] INPUT [-o OUTPUT]
    denoise --help

DESCRIPTION
    Denoises the triangle mesh INPUT (OFF, OBJ, PLY or STL, chosen by the file
    extension) with CGAL::Polygon_mesh_processing::intrinsic_denoising(), the
    intrinsic filter of "Mesh denoising via generalized intrinsic filter on 2D
    manifold" (Algorithm 1): face normals are averaged over a geometric
    neighbourhood of radius r with weights that integrate normal differences
    along a path from each face to its neighbour (eqs. 8-9), the vertices then
    follow the filtered normals (eq. 10), and the two steps are repeated.
    Sharp edges and corners are kept; noise is removed.

    By default the parameters are automatic: four candidate settings (sigma
    0.5 and 0.8 on r = 3d, 0.8 on r = 6d, 1.4 on r = 2d) run on INPUT, each
    stopped before the residual (input minus result) becomes correlated across
    edges, which is when it starts to remove shape rather than noise; among
    the flattest results (if at least 30% of their edges are flatter than 1
    degree) or else among all, the one whose residual is the least correlated
    at a common residual size is kept. If that result's residual shows sparse
    noise (a few vertices far off, smooth residual at the others: impulsive
    noise on exact vertices), INPUT is denoised again with the same setting,
    only those vertices moving; otherwise the setting runs on a synthetic
    noisy copy of its result (the noise it removed, shuffled over the
    vertices), and if fewer or more iterations recovered the copy better,
    INPUT is denoised with that many. A run of at most 8 iterations then
    runs again, as many, on its own result: if that second pass turns the
    face normals by more than half as much as the run turned those of
    INPUT, the run removed mostly shape, not noise, and INPUT is written
    unchanged. On a mesh of more than 300,000 faces all of this runs on a
    sample of 100,000 faces in five patches of the mesh (--selection-sample),
    and the setting chosen then runs once on the whole mesh. Last, as the
    vertex update (eq. 10)
    moves vertices along the normals only, each vertex that moved is relaxed
    along the surface (toward the centroid of its faces, in the directions
    its faces leave free: none at a corner, along the crease on an edge), by
    at most half as far as the denoising moved it. If some of sigma, r, k or the noise
    level are given, the others follow the noise level of INPUT (estimated,
    or given with --noise-level), and unless k is given the iterations stop when
    the vertices have moved by about the noise level or the filtered normals
    no longer change. Only the options given on the command line replace the
    automatic choices; --fixed uses the paper's fixed parameters instead (k =
    30, v = 2, r = 4d, sigma = 0.4, no stopping rule). After the run, the
    candidates and the one kept (or the noise level), the parameters used and
    why the iterations stopped are printed. When every candidate stopped
    within 3 iterations, a note says that the automatic mode cannot tell a
    mesh with little noise from noise correlated between neighbouring
    vertices (depth scans), and which parameters to give for a scan.

    Neighbourhoods and paths are computed once, on the input. Paths follow the
    paper's square pattern (section 4) by default; --paths chooses the exact
    geodesic (section 3.2, slower), the direct path i-j (a bilateral normal
    filter) or shortest paths in the face graph.

    --method runs one of the package's classic denoisers instead, with its
    documented defaults: FDC03 (bilateral_mesh_denoising), JDD03
    (non_iterative_denoising), SRML07 (fast_feature_preserving_denoising),
    ZFAT11 (bilateral_normal_denoising), HS13 (l0_denoising) or ZDZ15
    (guided_normal_denoising); the options of the intrinsic filter (-k, -v,
    sigmas, radii, exponents, paths) then do not apply and are refused, but
    --relax yes ends the three normal-filtering methods (SRML07, ZFAT11,
    ZDZ15) with the same relaxation along the surface.

    With --report FILE.html, a self-contained comparison page is written: the
    input (noisy input with --noise), the result and, with --reference, the
    reference, drawn with three.js side by side with linked cameras (drag one,
    all follow), a per-face normal error heat map (with --reference) and the
    table of E_n, E_v and seconds; the table also goes to FILE.csv.

    With --noise, seeded Gaussian noise is added to INPUT first (as in the
    paper's experiments, section 5.2); --noise-kind chooses it along the
    vertex normals, in random directions or as a simulated depth scan. With
    --reference, the errors E_n (mean face normal angle, degrees, eq. 12) and
    E_v (area-weighted distance to the reference, eq. 11) of the input and of
    the result are printed; the reference must have the same faces as INPUT
    (same count and order).

    The result is written as OUTPUT (format from its extension; default
    INPUT_denoised.off next to INPUT) through a temporary file and a rename,
    never over INPUT. Results go to standard output; errors are one line on
    standard error. While the intrinsic filter runs, a progress bar
    ([#####.....] 12/100 iterations 0.8 s) is redrawn on standard error after
    each iteration if it is a terminal (or with --progress); the limit shown is
    the iteration limit, the stopping rule may end the run earlier (in the
    automatic selection the bar counts the candidates instead).

)";

const char* const help_tail = R"(
EXIT STATUS
    0   success
    1   bad input or I/O error: unreadable, truncated or malformed file, not a
        triangle mesh, NaN or infinite coordinates, reference with other faces,
        output not writable
    2   bad usage: unknown option, missing or malformed value, value out of range

EXAMPLES
    Denoise a scan with the automatic parameters:
        denoise scan.off -o scan_clean.off

    The paper's fixed parameters (k = 30, v = 2, r = 4d, sigma = 0.4):
        denoise scan.off --fixed -o scan_clean.off

    The paper's fandisk experiment: noise sigma_E = 0.3 (seed 1), then E_n/E_v:
        denoise fandisk.off --noise 0.3 --reference fandisk.off -o out.off

    Organic, finely detailed mesh: larger sigmas, fewer iterations:
        denoise bunny.ply --sigma-spatial 0.6 --sigma-range 0.6 --iterations 10 -o bunny_clean.ply

    A classic method on the same noisy input, with a comparison page:
        denoise fandisk.off --noise 0.3 --reference fandisk.off --method ZDZ15 --report zdz15.html -o out.off

    Exact geodesic paths with step lengths, single thread:
        denoise part.stl --paths geodesic --step-length --threads 1 -o part_clean.stl

SEE ALSO
    doc/Polygon_mesh_processing/ (the package manual), README.md
)";

po::options_description make_options(Settings& s)
{
  po::options_description general("", 80, 40);
  // clang-format off
  general.add_options()
    ("help,h", "print this manual and exit")
    ("output,o", po::value(&s.output)->value_name("FILE"),
       "output mesh (.off, .obj, .ply or .stl); default: INPUT_denoised.off next to INPUT")
    ("fixed", po::bool_switch(&s.fixed),
       "the paper's fixed parameters (k = 30, v = 2, r = 4d, sigma = 0.4) instead of the automatic mode, which "
       "selects sigma, r and k from the residuals of four candidate settings")
    ("noise-level", po::value(&s.noise_level)->value_name("X"),
       "noise level (standard deviation relative to the mean edge length) used by the automatic mode and the "
       "stopping rule instead of the estimate")
    ("stop-when-converged", po::value(&s.stop_when_converged)->value_name("yes|no"),
       "stopping rule on or off (default: on in the automatic mode without --iterations, off otherwise)")
    ("iterations,k", po::value(&s.iterations)->value_name("K"),
       "k_iter: normal filtering passes (0: no change); default: automatic (chosen by the selection, or at most "
       "the library's limit with the stopping rule), 30 with --fixed")
    ("vertex-iterations,v", po::value(&s.vertex_iterations)->value_name("V")->default_value(s.vertex_iterations),
       "v_iter: vertex update steps (eq. 10) after each pass")
    ("sigma-spatial", po::value(&s.sigma_spatial)->value_name("S"),
       "sigma_s: width of the kernel on d^s, the sum of normal changes along the path; the paper uses 0.1 to 0.8; "
       "default: from the noise level, 0.4 with --fixed")
    ("sigma-range", po::value(&s.sigma_range)->value_name("S"),
       "sigma_r: width of the kernel on d^r, the sum of normal differences to n_i along the path; default: from "
       "the noise level, 0.4 with --fixed")
    ("radius,r", po::value(&s.radius)->value_name("R"),
       "neighbourhood radius in the mesh's length unit (overrides --relative-radius)")
    ("relative-radius", po::value(&s.relative_radius)->value_name("R"),
       "neighbourhood radius as a multiple of d, the mean distance between centroids of edge-adjacent faces (the "
       "paper uses 2 to 6); default: automatic, 4 with --fixed")
    ("spatial-exponent", po::value(&s.spatial_exponent)->value_name("N")->default_value(s.spatial_exponent, "1"),
       "exponent n of d^s (eq. 9; 1 is the L1 form of the paper)")
    ("range-exponent", po::value(&s.range_exponent)->value_name("M")->default_value(s.range_exponent, "1"),
       "exponent m of d^r (eq. 9)")
    ("paths", po::value(&s.paths)->value_name("STRATEGY")->default_value(s.paths),
       "square (section 4), geodesic (exact geodesics, section 3.2), direct (path i-j: bilateral filter) or graph "
       "(shortest paths in the face graph)")
    ("geodesic-rings", po::value(&s.patch_rings)->value_name("N")->default_value(s.patch_rings),
       "with --paths geodesic: rings of faces added around each neighbourhood patch")
    ("selection-sample", po::value(&s.selection_sample)->value_name("N")->default_value(s.selection_sample),
       "on a mesh of more than 3 N faces the automatic selection chooses its setting on a sample of about N faces "
       "(five patches), which then runs once on the whole mesh; 0: always on the whole mesh")
    ("long-run-test", po::bool_switch(&s.long_run_test),
       "for scans: when every candidate of the automatic selection stops within 3 iterations, keep a long run "
       "(sigma 0.8, 6 d, 64 iterations) if its first iteration made at least half of its change, as noise correlated "
       "between vertices does")
    ("step-length", po::bool_switch(&s.step_length), "multiply the terms of eq. 9 by the step lengths (eq. 4)")
    ("self-weight", po::bool_switch(&s.self_weight), "include face i's own normal in its average")
    ("vertex-update", po::value(&s.vertex_update)->value_name("UPDATE")->default_value(s.vertex_update),
       "paper (eq. 10) or least-squares (each vertex step solves for the positions that fit the filtered normals "
       "over the whole mesh)")
    ("no-fold-guard", po::bool_switch(&s.no_fold_guard),
       "apply eq. 10 exactly, as the paper does, without the safeguard against folded triangles")
    ("relax", po::value(&s.relax)->value_name("yes|no"),
       "relax the result along the surface after the last iteration (default: yes when the automatic selection "
       "runs, that is without --fixed, --iterations, the sigmas, the radius, --noise-level or "
       "--stop-when-converged no; no otherwise); also for --method SRML07, ZFAT11 and ZDZ15 (default no)")
    ("threads", po::value(&s.threads)->value_name("1|all")->default_value(s.threads),
       "1: sequential; all: parallel with TBB when available (the result is the same)")
    ("noise", po::value(&s.noise)->value_name("SIGMA_E"),
       "first add seeded Gaussian noise of standard deviation SIGMA_E times the mean edge length, along the vertex "
       "normals unless --noise-kind says otherwise")
    ("noise-kind", po::value(&s.noise_kind)->value_name("KIND")->default_value(s.noise_kind),
       "with --noise: normal (along the vertex normals), isotropic (in random directions, SIGMA_E the RMS length "
       "of the moves) or depth-scan (along the rays from a virtual camera, growing with depth, with ripples and "
       "outliers)")
    ("impulsive", po::value(&s.impulsive)->value_name("FRACTION"),
       "with --noise and --noise-kind normal: impulsive noise, only this fraction of the vertices moves")
    ("seed", po::value(&s.seed)->value_name("SEED")->default_value(s.seed), "seed of the noise (reproducible)")
    ("noisy-output", po::value(&s.noisy_output)->value_name("FILE"), "with --noise: also write the noisy mesh")
    ("reference", po::value(&s.reference)->value_name("FILE"),
       "noise-free mesh with the same faces: print E_n and E_v of the input and of the result")
    ("progress", po::bool_switch(&s.progress),
       "draw the progress bar on standard error even when it is not a terminal")
    ("quiet,q", po::bool_switch(&s.quiet), "print only E_n/E_v (with --reference) and errors; no progress bar");
  // clang-format on
  return general;
}

// A progress bar on stderr, redrawn in place with '\r' after each iteration:
// `[#####.....] 12/100 iterations 0.8 s`. Drawn only if `enabled` (stderr is
// a terminal, or --progress); finish() ends the line.
class Progress_bar
{
public:
  explicit Progress_bar(bool enabled) : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}
  void operator()(std::size_t done, std::size_t total)
  {
    if(!enabled_ || total == 0)
      return;
    const int width = 30;
    const int filled = int(double(width) * double(std::min(done, total)) / double(total));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string bar(std::size_t(filled), '#');
    bar.append(std::size_t(width - filled), '.');
    std::fprintf(stderr, "\r[%s] %zu/%zu iterations %.1f s", bar.c_str(), done, total, seconds);
    std::fflush(stderr);
    drawn_ = true;
  }
  void finish()
  {
    if(drawn_)
      std::fprintf(stderr, "\n");
    drawn_ = false;
  }

private:
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

// --method and --report (kept apart from the intrinsic filter's Settings)
struct Method_settings
{
  std::string method = "intrinsic", report;
  int debug_empty_mesh = -1; // hidden: the report's mesh of this number loses its vertices (tests the checker)
};

void add_method_options(po::options_description& options, po::options_description& hidden, Method_settings& m)
{
  // clang-format off
  options.add_options()
    ("method", po::value(&m.method)->value_name("NAME")->default_value(m.method),
       "intrinsic (this package's filter), or a classic method with its defaults: FDC03, JDD03, SRML07, ZFAT11, "
       "HS13 or ZDZ15")
    ("report", po::value(&m.report)->value_name("FILE.html"),
       "write a self-contained comparison page (meshes, linked cameras, heat map, E_n/E_v/seconds) and FILE.csv");
  hidden.add_options()("debug-empty-report-mesh", po::value(&m.debug_empty_mesh));
  // clang-format on
}

// A usage error for --method / --report, or an empty string.
std::string check_method_options(const Method_settings& m, const po::variables_map& vm)
{
  if(m.method != "intrinsic" && !denoising_support::find_classic_method<CGAL::Sequential_tag, Mesh>(m.method))
    return "--method must be intrinsic, FDC03, JDD03, SRML07, ZFAT11, HS13 or ZDZ15, not '" + m.method + "'";
  if(m.method != "intrinsic")
  {
    for(const char* name :
        {"iterations", "vertex-iterations", "sigma-spatial", "sigma-range", "radius", "relative-radius",
         "spatial-exponent", "range-exponent", "paths", "geodesic-rings", "step-length", "self-weight", "no-fold-guard",
         "vertex-update", "fixed", "noise-level", "stop-when-converged", "long-run-test"})
      if(vm.count(name) && !vm[name].defaulted())
        return std::string("--") + name + " applies to --method intrinsic only";
    if(vm.count("relax") &&
       !denoising_support::find_classic_method<CGAL::Sequential_tag, Mesh>(m.method)->filters_normals)
      return "--relax applies to --method intrinsic, SRML07, ZFAT11 and ZDZ15 only";
  }
  if(vm.count("report") && denoising_support::extension(m.report) != "html")
    return "--report needs a .html file name, not '" + m.report + "'";
  return std::string();
}

// Runs a classic method with its defaults (and, with `relax`, the
// relaxation along the surface); on failure `mesh` may be changed and a
// one-line message is returned.
template <typename ConcurrencyTag>
std::string run_classic(Mesh& mesh, const std::string& method, bool relax)
{
  try
  {
    denoising_support::find_classic_method<ConcurrencyTag, Mesh>(method)->run(mesh, relax);
  }
  catch(const std::exception& e)
  {
    return e.what();
  }
  return std::string();
}

// The comparison page of this run: input, result and (if given) reference.
std::string write_cli_report(const Method_settings& m, const std::string& input_name, bool noisy, const Mesh& input,
                             const Mesh& denoised, const Mesh* reference, double seconds)
{
  namespace R = denoising_support;
  R::Report report;
  report.title = input_name + ": " + m.method;
  report.entries.push_back(R::make_entry(noisy ? "noisy input" : "input", input, reference));
  report.entries.push_back(R::make_entry(m.method + " result", denoised, reference));
  report.entries.back().seconds = seconds;
  if(reference != nullptr)
  {
    try
    {
      report.entries[0].En = PMP::face_normal_error(input, *reference);
      report.entries[0].Ev = PMP::vertex_position_error(input, *reference);
      report.entries[1].En = PMP::face_normal_error(denoised, *reference);
      report.entries[1].Ev = PMP::vertex_position_error(denoised, *reference);
    }
    catch(const std::exception& e)
    {
      return std::string("cannot compare with the reference: ") + e.what();
    }
    report.entries.push_back(R::make_entry("reference", *reference, reference));
    report.entries.back().En = 0.;
    report.entries.back().Ev = 0.;
  }
  report.debug_empty_entry = m.debug_empty_mesh;
  return R::write_report(m.report, report);
}

// The options of intrinsic_denoising() from the command line: those that the
// automatic mode would otherwise choose (k, the sigmas, the radius, the noise
// level, the stopping rule, the relaxation) only when given, the others always
// (their command-line defaults are the library's).
PMP::internal::Denoising::Intrinsic_options intrinsic_options(const Settings& s, const po::variables_map& vm)
{
  namespace S = denoising_support;
  PMP::internal::Denoising::Intrinsic_options o;
  o.automatic_parameters = !s.fixed;
  if(vm.count("iterations"))
    o.number_of_iterations = static_cast<unsigned int>(s.iterations);
  if(vm.count("sigma-spatial"))
    o.filter.sigma_spatial = s.sigma_spatial;
  if(vm.count("sigma-range"))
    o.filter.sigma_range = s.sigma_range;
  if(vm.count("radius"))
    o.filter.neighbor_radius = s.radius;
  else if(vm.count("relative-radius"))
    o.filter.relative_neighbor_radius = s.relative_radius;
  if(vm.count("noise-level"))
    o.noise_level = s.noise_level;
  if(vm.count("stop-when-converged"))
    o.stop_when_converged = s.stop_when_converged == "yes";
  if(vm.count("relax"))
    o.relax_along_surface = s.relax == "yes";
  o.vertex_iterations = static_cast<unsigned int>(s.vertex_iterations);
  o.filter.spatial_exponent = s.spatial_exponent;
  o.filter.range_exponent = s.range_exponent;
  o.filter.path_strategy = S::find_name(S::path_strategy_names, s.paths, false)->value;
  o.filter.use_step_length = s.step_length;
  o.filter.geodesic_patch_rings = static_cast<unsigned int>(s.patch_rings);
  o.filter.include_self_weight = s.self_weight;
  o.prevent_folds = !s.no_fold_guard;
  o.vertex_update = S::find_name(S::vertex_update_names, s.vertex_update, false)->value;
  o.selection_sample_faces = static_cast<std::size_t>(s.selection_sample);
  o.long_run_test = s.long_run_test;
  return o;
}

bool positive_finite(double x) { return std::isfinite(x) && x > 0.; }

// One run of the tool: its options, meshes and results.
struct Cli_run
{
  Settings s;
  Method_settings method;
  po::variables_map vm;
  bool talk = true;
  Mesh input, reference, denoised;
  PMP::Intrinsic_denoising_report report;
  double seconds = 0.;
};

const int go_on = -1; // what the steps below return when the run goes on

// Parses the command line into `r`; the exit code of a usage error or of
// --help, or go_on.
int parse_command_line(int argc, char** argv, Cli_run& r)
{
  Settings& s = r.s;
  po::options_description options = make_options(s);
  po::options_description hidden;
  hidden.add_options()("input", po::value(&s.input));
  add_method_options(options, hidden, r.method);
  po::options_description all;
  all.add(options).add(hidden);
  po::positional_options_description positional;
  positional.add("input", 1);
  try
  {
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), r.vm);
    po::notify(r.vm);
  }
  catch(const po::error& e)
  {
    return fail(exit_usage, e.what());
  }
  if(r.vm.count("help"))
  {
    std::cout << help_head << "OPTIONS\n" << options << help_tail;
    return exit_ok;
  }
  return go_on;
}

// The checks of the options' values (the first failing one's exit code, or
// go_on); sets the default output path.
int check_usage(Cli_run& r)
{
  Settings& s = r.s;
  const po::variables_map& vm = r.vm;
  const Method_settings& method = r.method;
  if(s.input.empty())
    return fail(exit_usage, "no input file");
  const long long max_count = 1000000;
  if(s.iterations < 0 || s.iterations > max_count || s.vertex_iterations < 0 || s.vertex_iterations > max_count ||
     s.patch_rings < 0 || s.patch_rings > max_count)
    return fail(exit_usage, "--iterations, --vertex-iterations and --geodesic-rings must lie in [0, 1000000]");
  if(s.selection_sample < 0 || s.selection_sample > 4294967295LL)
    return fail(exit_usage, "--selection-sample must lie in [0, 4294967295]");
  if(s.seed < 0 || s.seed > 4294967295LL)
    return fail(exit_usage, "--seed must lie in [0, 4294967295]");
  if(!denoising_support::find_name(denoising_support::path_strategy_names, s.paths, false))
    return fail(exit_usage, "--paths must be square, direct, graph or geodesic, not '" + s.paths + "'");
  if(!denoising_support::find_name(denoising_support::vertex_update_names, s.vertex_update, false))
    return fail(exit_usage, "--vertex-update must be paper or least-squares, not '" + s.vertex_update + "'");
  if(vm.count("relax") && s.relax != "yes" && s.relax != "no")
    return fail(exit_usage, "--relax must be yes or no, not '" + s.relax + "'");
  if(s.threads != "1" && s.threads != "all")
    return fail(exit_usage, "--threads must be 1 or all, not '" + s.threads + "'");
  if(!positive_finite(s.sigma_spatial) || !positive_finite(s.sigma_range) || !positive_finite(s.spatial_exponent) ||
     !positive_finite(s.range_exponent) || !positive_finite(s.relative_radius))
    return fail(exit_usage, "sigmas, exponents and radii must be positive and finite");
  if(vm.count("radius") && !positive_finite(s.radius))
    return fail(exit_usage, "--radius must be positive and finite");
  if(vm.count("noise-level") && !(std::isfinite(s.noise_level) && s.noise_level >= 0.))
    return fail(exit_usage, "--noise-level must be non-negative and finite");
  if(vm.count("stop-when-converged") && s.stop_when_converged != "yes" && s.stop_when_converged != "no")
    return fail(exit_usage, "--stop-when-converged must be yes or no, not '" + s.stop_when_converged + "'");
  if(vm.count("noise") && !(std::isfinite(s.noise) && s.noise >= 0.))
    return fail(exit_usage, "--noise must be non-negative and finite");
  if(vm.count("impulsive") && !(s.impulsive >= 0. && s.impulsive <= 1.))
    return fail(exit_usage, "--impulsive must lie in [0, 1]");
  if((vm.count("impulsive") || vm.count("noisy-output")) && !vm.count("noise"))
    return fail(exit_usage, "--impulsive and --noisy-output need --noise");
  if(s.noise_kind != "normal" && s.noise_kind != "isotropic" && s.noise_kind != "depth-scan")
    return fail(exit_usage, "--noise-kind must be normal, isotropic or depth-scan, not '" + s.noise_kind + "'");
  if(!vm["noise-kind"].defaulted() && !vm.count("noise"))
    return fail(exit_usage, "--noise-kind needs --noise");
  if(vm.count("impulsive") && s.noise_kind != "normal")
    return fail(exit_usage, "--impulsive needs --noise-kind normal");
  {
    const std::string usage = check_method_options(method, vm);
    if(!usage.empty())
      return fail(exit_usage, usage);
  }
  if(!method.report.empty())
  {
    const std::string missing = denoising_support::check_report_files();
    if(!missing.empty())
      return fail(exit_input, missing);
  }
  if(s.output.empty())
    s.output = denoising_support::output_path(s.input);
  {
    const std::string ext = denoising_support::extension(s.output);
    if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
      return fail(exit_usage, "unknown output format '" + ext + "' (OFF, OBJ, PLY and STL are written)");
  }
  {
    std::error_code ec;
    if(std::filesystem::exists(s.output, ec) && std::filesystem::equivalent(s.output, s.input, ec))
      return fail(exit_input, "refusing to overwrite the input '" + s.input + "'");
  }
  r.talk = !s.quiet;
  return go_on;
}

// Reads the input and the reference (same faces), with their warnings.
int read_inputs(Cli_run& r)
{
  const Settings& s = r.s;
  const bool talk = r.talk;
  Mesh &input = r.input, &reference = r.reference;
  std::vector<std::string> warnings;
  const auto warn = [&warnings](const std::string& file) {
    for(const std::string& w : warnings)
      std::cerr << "denoise: warning: '" << file << "': " << w << "\n";
    warnings.clear();
  };
  std::string problem = denoising_support::read_mesh_file(s.input, input, &warnings);
  if(!problem.empty())
    return fail(exit_input, problem);
  warn(s.input);
  if(!s.reference.empty())
  {
    problem = denoising_support::read_mesh_file(s.reference, reference, &warnings);
    if(!problem.empty())
      return fail(exit_input, "reference " + problem);
    warn(s.reference);
    if(num_faces(reference) != num_faces(input))
      return fail(exit_input, "the reference has " + std::to_string(num_faces(reference)) + " faces, the input " +
                                  std::to_string(num_faces(input)));
  }
  if(talk)
    std::cout << s.input << ": " << num_vertices(input) << " vertices, " << num_faces(input) << " faces\n";
  return go_on;
}

// Adds the noise asked for to the input, and writes the noisy mesh if asked.
int add_noise(Cli_run& r)
{
  const Settings& s = r.s;
  const po::variables_map& vm = r.vm;
  const bool talk = r.talk;
  Mesh& input = r.input;
  std::string problem;
  if(vm.count("noise"))
  {
    try
    {
      const auto seeded = CGAL::parameters::random_seed(static_cast<unsigned int>(s.seed));
      if(vm.count("impulsive"))
        PMP::add_impulsive_noise(input, s.impulsive, s.noise, seeded);
      else if(s.noise_kind == "isotropic")
        PMP::add_isotropic_gaussian_noise(input, s.noise, seeded);
      else if(s.noise_kind == "depth-scan")
        PMP::add_depth_scan_noise(input, s.noise, seeded);
      else
        PMP::add_gaussian_noise(input, s.noise, seeded);
    }
    catch(const std::exception& e)
    {
      return fail(exit_input, e.what());
    }
    if(talk)
    {
      std::cout << (vm.count("impulsive")          ? "impulsive"
                    : s.noise_kind == "isotropic"  ? "isotropic Gaussian"
                    : s.noise_kind == "depth-scan" ? "depth-scan"
                                                   : "Gaussian")
                << " noise: sigma_E = " << s.noise;
      if(vm.count("impulsive"))
        std::cout << ", fraction " << s.impulsive;
      std::cout << ", seed " << s.seed << "\n";
    }
    if(!s.noisy_output.empty())
    {
      problem = denoising_support::write_mesh(s.noisy_output, input, s.input);
      if(!problem.empty())
        return fail(exit_input, problem);
    }
  }
  return go_on;
}

// Denoises the input into r.denoised (the intrinsic filter or a classic
// method) and prints what was done.
int run_denoising(Cli_run& r)
{
  const Settings& s = r.s;
  const po::variables_map& vm = r.vm;
  const Method_settings& method = r.method;
  const bool talk = r.talk;
  Mesh& denoised = r.denoised;
  PMP::Intrinsic_denoising_report& report = r.report;
  std::string problem;
  Progress_bar bar(talk && (s.progress || ::isatty(STDERR_FILENO)));
  auto progress = [&bar](std::size_t done, std::size_t total) { bar(done, total); };
  denoised = r.input;
  const bool relax_classic = vm.count("relax") && s.relax == "yes"; // with a classic method: off by default
  const auto start = std::chrono::steady_clock::now();
  if(method.method != "intrinsic")
  {
    problem = s.threads == "1" ? run_classic<CGAL::Sequential_tag>(denoised, method.method, relax_classic)
                               : run_classic<CGAL::Parallel_if_available_tag>(denoised, method.method, relax_classic);
  }
  else
  {
#ifdef CGAL_LINKED_WITH_TBB
    std::unique_ptr<tbb::global_control> one_thread;
    if(s.threads == "1")
      one_thread = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, 1);
#endif
    // One concurrency tag only; --threads 1 limits TBB to one thread instead.
    problem = denoising_support::denoise_with_options<CGAL::Parallel_if_available_tag>(
        denoised, intrinsic_options(s, vm), CGAL::parameters::progress_callback(progress), &report);
    bar.finish();
  }
  if(!problem.empty())
    return fail(exit_input, problem);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(talk && method.method != "intrinsic")
    std::cout << "denoised in " << seconds << " s: " << method.method << " with its defaults"
              << (relax_classic ? ", relaxed along the surface" : "") << ", threads " << s.threads << "\n";
  else if(talk)
  {
    std::cout << "denoised in " << seconds << " s: " << s.paths << " paths, n = " << s.spatial_exponent
              << ", m = " << s.range_exponent << (s.step_length ? ", step lengths" : "")
              << (s.no_fold_guard ? ", no fold guard" : "")
              << (s.vertex_update == "paper" ? "" : ", least-squares vertex update") << ", threads " << s.threads
              << "\n";
    std::cout << denoising_support::describe(report);
  }
  r.seconds = seconds;
  return go_on;
}

// Prints E_n and E_v of the input and the result against the reference.
int print_errors(const Cli_run& r)
{
  const Settings& s = r.s;
  const Mesh &input = r.input, &reference = r.reference, &denoised = r.denoised;
  if(!s.reference.empty())
  {
    try
    {
      const double en_in = PMP::face_normal_error(input, reference),
                   en_out = PMP::face_normal_error(denoised, reference);
      const double ev_in = PMP::vertex_position_error(input, reference),
                   ev_out = PMP::vertex_position_error(denoised, reference);
      std::cout << "E_n (degrees): input " << en_in << ", denoised " << en_out << "\n";
      std::cout << "E_v: input " << ev_in << ", denoised " << ev_out << "\n";
    }
    catch(const std::exception& e)
    {
      return fail(exit_input, std::string("cannot compare with the reference: ") + e.what());
    }
  }
  return go_on;
}

// Writes the result and, if asked, the comparison page.
int write_outputs(const Cli_run& r)
{
  const Settings& s = r.s;
  const Method_settings& method = r.method;
  const po::variables_map& vm = r.vm;
  const bool talk = r.talk;
  const Mesh &input = r.input, &reference = r.reference, &denoised = r.denoised;
  const double seconds = r.seconds;
  std::string problem = denoising_support::write_mesh(s.output, denoised, s.input);
  if(!problem.empty())
    return fail(exit_input, problem);
  if(talk)
    std::cout << "output: " << s.output << "\n";
  if(!method.report.empty())
  {
    problem = write_cli_report(method, s.input, vm.count("noise") > 0, input, denoised,
                               s.reference.empty() ? nullptr : &reference, seconds);
    if(!problem.empty())
      return fail(exit_input, problem);
    if(talk)
      std::cout << "report: " << method.report << " (table: " << denoising_support::table_path(method.report) << ")\n";
  }
  return exit_ok;
}

} // namespace

int main(int argc, char** argv)
{
  Cli_run r;
  int code = parse_command_line(argc, argv, r);
  if(code == go_on)
    code = check_usage(r);
  if(code == go_on)
    code = read_inputs(r);
  if(code == go_on)
    code = add_noise(r);
  if(code == go_on)
    code = run_denoising(r);
  if(code == go_on)
    code = print_errors(r);
  if(code == go_on)
    code = write_outputs(r);
  return code;
}
