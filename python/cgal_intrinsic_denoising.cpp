// Python bindings (pybind11) of the package: intrinsic_denoising() with every
// named parameter as a keyword, the six classic methods, the noise models,
// the error metrics E_n (eq. 12) and E_v (eq. 11), on NumPy arrays, and the
// `denoise` tool's bounded mesh readers and atomic writer.
//
// A mesh is a pair (V, F): V an (n, 3) array of coordinates (any real dtype,
// read as float64), F an (m, 3) array of vertex indices (any integer dtype).
// It becomes a CGAL::Surface_mesh whose vertex i is row i of V, through the
// same polygon-soup path as the `denoise` tool's readers (a soup that is not a
// manifold surface is repaired by orient_polygon_soup(), which appends
// duplicated vertices after the n given ones). Results are returned as a new
// (n, 3) float64 array: row i is the position of vertex i (a vertex the repair
// duplicated keeps the position of its first copy; the report says how many
// were duplicated). The computations run with the GIL released and with
// CGAL::Parallel_if_available_tag; the results do not depend on the thread
// count. Errors of the library (std::invalid_argument) become ValueError with
// the library's message.

#include <denoising_support/mesh_file.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/bilateral_mesh_denoising.h>
#include <CGAL/Polygon_mesh_processing/bilateral_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/fast_feature_preserving_denoising.h>
#include <CGAL/Polygon_mesh_processing/guided_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/Polygon_mesh_processing/l0_denoising.h>
#include <CGAL/Polygon_mesh_processing/non_iterative_denoising.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

namespace py = pybind11;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef denoising_support::Mesh Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
typedef CGAL::Parallel_if_available_tag Tag;

namespace {

// A mesh built from (V, F), with the number of rows of V.
struct Input
{
  Mesh mesh;
  std::size_t rows = 0;
  std::size_t duplicated_vertices = 0;
};

std::string shape_text(const py::array& a)
{
  std::string s = "(";
  for(py::ssize_t i = 0; i < a.ndim(); ++i)
    s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// V as a C-contiguous float64 array of shape (n, 3), or ValueError.
py::array_t<double, py::array::c_style> read_vertices(const py::handle& object, const char* name)
{
  py::array a = py::array::ensure(object);
  if(!a)
    throw py::type_error(std::string(name) + " must be an array of shape (n, 3) of numbers");
  const char kind = a.dtype().kind();
  if(kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + " must hold real numbers (dtype kind '" + std::string(1, kind) + "')");
  if(a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(std::string(name) + " must have shape (n, 3), not " + shape_text(a));
  auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  const double* p = v.data();
  for(py::ssize_t i = 0; i < v.shape(0); ++i)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(p[3 * i + c]))
        throw py::value_error(std::string(name) + ": row " + std::to_string(i) + " has a NaN or infinite coordinate");
  return v;
}

// F as int64 indices of shape (m, 3), each in [0, rows), or ValueError.
py::array_t<std::int64_t, py::array::c_style> read_faces(const py::handle& object, std::size_t rows, const char* name)
{
  py::array a = py::array::ensure(object);
  if(!a)
    throw py::type_error(std::string(name) + " must be an array of shape (m, 3) of vertex indices");
  const char kind = a.dtype().kind();
  if(kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + " must hold integers (dtype kind '" + std::string(1, kind) + "')");
  if(a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(std::string(name) + " must have shape (m, 3), not " + shape_text(a) +
                          " (triangles only: triangulate the mesh first)");
  if(kind == 'u' && a.itemsize() == 8)
  {
    // uint64 values above INT64_MAX would wrap: check them as unsigned first
    auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for(py::ssize_t i = 0; i < u.size(); ++i)
      if(u.data()[i] >= rows)
        throw py::value_error(std::string(name) + ": row " + std::to_string(i / 3) + " has the index " +
                              std::to_string(u.data()[i]) + ", out of range [0, " + std::to_string(rows) + ")");
  }
  auto f = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  const std::int64_t* p = f.data();
  for(py::ssize_t i = 0; i < f.size(); ++i)
    if(p[i] < 0 || static_cast<std::uint64_t>(p[i]) >= rows)
      throw py::value_error(std::string(name) + ": row " + std::to_string(i / 3) + " has the index " +
                            std::to_string(p[i]) + ", out of range [0, " + std::to_string(rows) + ")");
  return f;
}

std::unique_ptr<Input> make_input(const py::handle& V, const py::handle& F, const char* vname = "V",
                                  const char* fname = "F")
{
  const auto v = read_vertices(V, vname);
  const std::size_t rows = static_cast<std::size_t>(v.shape(0));
  const auto f = read_faces(F, rows, fname);
  denoising_support::Soup soup;
  soup.points.reserve(rows);
  for(std::size_t i = 0; i < rows; ++i)
    soup.points.emplace_back(v.data()[3 * i], v.data()[3 * i + 1], v.data()[3 * i + 2]);
  soup.polygons.resize(static_cast<std::size_t>(f.shape(0)));
  for(std::size_t i = 0; i < soup.polygons.size(); ++i)
    soup.polygons[i] = {static_cast<std::size_t>(f.data()[3 * i]), static_cast<std::size_t>(f.data()[3 * i + 1]),
                        static_cast<std::size_t>(f.data()[3 * i + 2])};
  auto input = std::make_unique<Input>();
  input->rows = rows;
  const std::string problem = denoising_support::soup_to_mesh(soup, input->mesh);
  if(!problem.empty())
    throw py::value_error(std::string(fname) + ": " + problem);
  input->duplicated_vertices = num_vertices(input->mesh) - rows;
  return input;
}

// Row i: the point of vertex i (vertex i of the mesh is row i of V).
py::array_t<double> positions(const Input& input)
{
  py::array_t<double> out({static_cast<py::ssize_t>(input.rows), py::ssize_t(3)});
  double* p = out.mutable_data();
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(input.mesh))
  {
    if(i == input.rows)
      break;
    const auto& q = input.mesh.point(v);
    p[3 * i] = q.x();
    p[3 * i + 1] = q.y();
    p[3 * i + 2] = q.z();
    ++i;
  }
  return out;
}

// The vertex_is_constrained_map of `constrained` (None: no vertex), a
// boolean array with one entry per row of V (vertices that the soup repair
// appended are not constrained).
Mesh::Property_map<vertex_descriptor, bool> constrained_map(Input& input, const py::object& constrained)
{
  auto map = input.mesh.add_property_map<vertex_descriptor, bool>("v:py_constrained", false).first;
  if(constrained.is_none())
    return map;
  py::array a = py::array::ensure(constrained);
  if(!a || a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != input.rows)
    throw py::value_error("constrained must be a one-dimensional array with one entry per row of V (" +
                          std::to_string(input.rows) + ")");
  auto b = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(a);
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(input.mesh))
  {
    if(i == input.rows)
      break;
    map[v] = b.data()[i++];
  }
  return map;
}

PMP::Vertex_update read_vertex_update(const std::string& name)
{
  if(const auto* e = denoising_support::find_name(denoising_support::vertex_update_names, name, true))
    return e->value;
  throw py::value_error("vertex_update must be 'paper' or 'least_squares', not '" + name + "'");
}

PMP::Intrinsic_path_strategy read_paths(const std::string& name)
{
  if(const auto* e = denoising_support::find_name(denoising_support::path_strategy_names, name, true))
    return e->value;
  throw py::value_error("path_strategy must be 'square_pattern', 'geodesic', 'direct' or 'shortest_graph_path', not '" +
                        name + "'");
}

// Limits TBB to `threads` threads while alive (0: all).
struct Thread_limit
{
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> control;
#endif
  explicit Thread_limit(long long threads)
  {
    if(threads < 0)
      throw py::value_error("threads must be 0 (all) or positive, not " + std::to_string(threads));
#ifdef CGAL_LINKED_WITH_TBB
    if(threads > 0)
      control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      static_cast<std::size_t>(threads));
#endif
  }
};

// Runs `work` with the GIL released; a std::invalid_argument becomes
// ValueError with its message.
template <typename Work>
void run_released(Work&& work)
{
  std::exception_ptr failure;
  {
    py::gil_scoped_release release;
    try
    {
      work();
    }
    catch(...)
    {
      failure = std::current_exception();
    }
  }
  if(failure)
    std::rethrow_exception(failure);
}

// ---------------------------------------------------------------------------
// intrinsic_denoising()

// The arguments of intrinsic_denoising() as Python gives them.
unsigned int to_unsigned(long long x, const char* name)
{
  if(x < 0 || x > static_cast<long long>(std::numeric_limits<unsigned int>::max()))
    throw py::value_error(std::string("intrinsic_denoising(): ") + name +
                          " must be a non-negative integer below 2^32, not " + std::to_string(x));
  return static_cast<unsigned int>(x);
}

py::dict report_dict(const PMP::Intrinsic_denoising_report& r)
{
  py::dict d;
  d["automatic_parameters"] = r.automatic_parameters;
  d["noise_level"] = r.noise_level;
  d["noise_level_estimated"] = r.noise_level_estimated;
  d["mean_edge_length"] = r.mean_edge_length;
  d["sigma_spatial"] = r.sigma_spatial;
  d["sigma_range"] = r.sigma_range;
  d["neighbor_radius"] = r.neighbor_radius;
  d["relative_neighbor_radius"] = r.relative_neighbor_radius;
  d["vertex_iterations"] = r.vertex_iterations;
  d["vertex_update"] = denoising_support::name_of(denoising_support::vertex_update_names, r.vertex_update).python;
  d["maximum_iterations"] = r.maximum_iterations;
  d["iterations"] = r.iterations;
  d["stop_reason"] = denoising_support::name_of(denoising_support::stop_reason_names, r.stop_reason).python;
  d["displacement"] = r.displacement;
  py::list candidates;
  for(const PMP::Intrinsic_candidate_report& c : r.candidates)
  {
    py::dict e;
    e["sigma"] = c.sigma;
    e["relative_neighbor_radius"] = c.relative_neighbor_radius;
    e["iterations"] = c.iterations;
    e["stopped_by_correlation"] = c.stopped_by_correlation;
    e["residual_rms"] = c.residual_rms;
    e["residual_correlation"] = c.residual_correlation;
    e["flat_share"] = c.flat_share;
    e["score"] = c.score;
    candidates.append(e);
  }
  d["candidates"] = candidates;
  d["chosen_candidate"] = r.chosen_candidate;
  d["selection_sample_faces"] = r.selection_sample_faces;
  d["selection_sample_patches"] = r.selection_sample_patches;
  d["inlier_residual_correlation"] = r.inlier_residual_correlation;
  d["outlier_vertices"] = r.outlier_vertices;
  d["change_angle"] = r.change_angle;
  d["second_pass_angle"] = r.second_pass_angle;
  d["relaxed_vertices"] = r.relaxed_vertices;
  d["self_check_errors"] = r.self_check_errors;
  d["self_check_radii"] = r.self_check_radii;
  d["self_check_smallest_errors"] = r.self_check_smallest_errors;
  d["residual_hop_correlations"] = r.residual_hop_correlations;
  d["residual_correlation_length"] = r.residual_correlation_length;
  d["residual_axis_share"] = r.residual_axis_share;
  d["long_run_first_share"] = r.long_run_first_share;
  return d;
}

py::tuple denoise(const py::handle& V, const py::handle& F, const py::object& constrained, const py::object& progress,
                  long long threads, const PMP::internal::Denoising::Intrinsic_options& options)
{
  if(!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be callable as progress(done, total)");

  std::unique_ptr<Input> input = make_input(V, F);
  auto constrained_vertices = constrained_map(*input, constrained);
  auto normals = input->mesh.add_property_map<face_descriptor, denoising_support::K::Vector_3>("f:py_normal").first;
  const Thread_limit limit(threads);

  // Called from the calling thread after each iteration: Ctrl-C and the
  // user's callback run there, with the GIL; a Python error ends the run.
  auto callback = [&progress](std::size_t done, std::size_t total) {
    py::gil_scoped_acquire acquire;
    if(PyErr_CheckSignals() != 0)
      throw py::error_already_set();
    if(!progress.is_none())
      progress(done, total);
  };
  const auto np = CGAL::parameters::progress_callback(callback)
                      .vertex_is_constrained_map(constrained_vertices)
                      .face_normal_map(normals);
  PMP::Intrinsic_denoising_report result;
  run_released(
      [&] { result = PMP::internal::Denoising::intrinsic_denoising_with_options<Tag>(input->mesh, options, np); });

  py::dict report = report_dict(result);
  py::array_t<double> filtered({static_cast<py::ssize_t>(num_faces(input->mesh)), py::ssize_t(3)});
  double* n = filtered.mutable_data();
  std::size_t i = 0;
  for(face_descriptor f : faces(input->mesh))
  {
    n[3 * i] = normals[f].x();
    n[3 * i + 1] = normals[f].y();
    n[3 * i + 2] = normals[f].z();
    ++i;
  }
  report["face_normals"] = filtered;
  report["duplicated_vertices"] = input->duplicated_vertices;
  return py::make_tuple(positions(*input), report);
}

// ---------------------------------------------------------------------------
// the classic methods, the noise models and the metrics

// Runs `method(mesh, constrained map)` on a copy of (V, F) and returns the
// new positions.
template <typename Method>
py::array_t<double> run_on_copy(const py::handle& V, const py::handle& F, const py::object& constrained,
                                long long threads, Method&& method)
{
  std::unique_ptr<Input> input = make_input(V, F);
  auto map = constrained_map(*input, constrained);
  const Thread_limit limit(threads);
  run_released([&] { method(input->mesh, map); });
  return positions(*input);
}

template <typename Map>
auto classic_np(const Map& map, long long iterations, const char* fname)
{
  if(iterations < 0 || iterations > static_cast<long long>(std::numeric_limits<unsigned int>::max()))
    throw py::value_error(std::string(fname) + ": number_of_iterations must be a non-negative integer below 2^32");
  return CGAL::parameters::vertex_is_constrained_map(map).number_of_iterations(static_cast<unsigned int>(iterations));
}

unsigned int vertex_steps(long long v, const char* fname)
{
  if(v < 0 || v > static_cast<long long>(std::numeric_limits<unsigned int>::max()))
    throw py::value_error(std::string(fname) + ": vertex_iterations must be a non-negative integer below 2^32");
  return static_cast<unsigned int>(v);
}

// The parameters the two normal filters ZFAT11 and ZDZ15 share.
template <typename Map>
auto normal_filter_np(const Map& map, long long iterations, double sigma_spatial, double sigma_range,
                      long long vertex_iterations, PMP::Vertex_update update, bool relax, const char* fname)
{
  return classic_np(map, iterations, fname)
      .sigma_spatial(sigma_spatial)
      .sigma_range(sigma_range)
      .vertex_iterations(vertex_steps(vertex_iterations, fname))
      .vertex_update(update)
      .relax_along_surface(relax);
}

// One of the noise models on a copy of (V, F): `noise(mesh, np)` with the
// seed and the constrained vertices as named parameters.
template <typename Noise>
py::array_t<double> add_noise(const py::handle& V, const py::handle& F, long long seed, const py::object& constrained,
                              Noise&& noise)
{
  if(seed < 0 || seed > static_cast<long long>(std::numeric_limits<unsigned int>::max()))
    throw py::value_error("seed must be a non-negative integer below 2^32, not " + std::to_string(seed));
  const unsigned int s = static_cast<unsigned int>(seed);
  return run_on_copy(V, F, constrained, 0, [&](Mesh& mesh, const auto& map) {
    noise(mesh, CGAL::parameters::random_seed(s).vertex_is_constrained_map(map));
  });
}

// `metric(mesh, reference)` of (V, F) against (V_reference, F_reference or F).
template <typename Metric>
double compare(const py::handle& V, const py::handle& F, const py::handle& V_reference, const py::object& F_reference,
               Metric&& metric)
{
  std::unique_ptr<Input> a = make_input(V, F);
  std::unique_ptr<Input> b =
      make_input(V_reference, F_reference.is_none() ? F : F_reference, "V_reference", "F_reference");
  double e = 0.;
  run_released([&] { e = metric(a->mesh, b->mesh); });
  return e;
}

// (V, F) of a mesh: vertices and faces in index order.
py::tuple arrays_of(const Mesh& mesh)
{
  py::array_t<double> V({static_cast<py::ssize_t>(num_vertices(mesh)), py::ssize_t(3)});
  py::array_t<std::int64_t> F({static_cast<py::ssize_t>(num_faces(mesh)), py::ssize_t(3)});
  double* p = V.mutable_data();
  std::int64_t* q = F.mutable_data();
  for(vertex_descriptor v : vertices(mesh))
  {
    const auto& x = mesh.point(v);
    *p++ = x.x();
    *p++ = x.y();
    *p++ = x.z();
  }
  for(face_descriptor f : faces(mesh))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      *q++ = static_cast<std::int64_t>(target(h, mesh).idx());
  return py::make_tuple(V, F);
}

// The module's functions for intrinsic_denoising() as `denoise`.
void define_intrinsic(py::module_& m)
{
  m.def(
      "denoise",
      [](const py::handle& V, const py::handle& F, bool automatic_parameters, std::optional<double> noise_level,
         std::optional<long long> number_of_iterations, std::optional<bool> stop_when_converged,
         long long vertex_iterations, const std::string& vertex_update, std::optional<double> sigma_spatial,
         std::optional<double> sigma_range, double spatial_exponent, double range_exponent,
         std::optional<double> neighbor_radius, std::optional<double> relative_neighbor_radius,
         const std::string& path_strategy, bool use_step_length, long long geodesic_patch_rings,
         bool include_self_weight, bool prevent_folds, std::optional<bool> relax_along_surface,
         long long selection_sample_faces, bool long_run_test, const py::object& constrained,
         const py::object& progress, long long threads) {
        // argument checks that need no mesh (the library checks the values)
        PMP::internal::Denoising::Intrinsic_options o;
        o.automatic_parameters = automatic_parameters;
        if(number_of_iterations)
          o.number_of_iterations = to_unsigned(*number_of_iterations, "number_of_iterations");
        o.vertex_iterations = to_unsigned(vertex_iterations, "vertex_iterations");
        o.filter.geodesic_patch_rings = to_unsigned(geodesic_patch_rings, "geodesic_patch_rings");
        o.selection_sample_faces = to_unsigned(selection_sample_faces, "selection_sample_faces");
        o.long_run_test = long_run_test;
        o.vertex_update = read_vertex_update(vertex_update);
        o.filter.path_strategy = read_paths(path_strategy);
        if(neighbor_radius && relative_neighbor_radius)
          throw py::value_error("intrinsic_denoising(): give neighbor_radius or relative_neighbor_radius, not both");
        o.noise_level = noise_level;
        o.stop_when_converged = stop_when_converged;
        o.filter.sigma_spatial = sigma_spatial;
        o.filter.sigma_range = sigma_range;
        o.filter.spatial_exponent = spatial_exponent;
        o.filter.range_exponent = range_exponent;
        o.filter.neighbor_radius = neighbor_radius;
        o.filter.relative_neighbor_radius = relative_neighbor_radius;
        o.filter.use_step_length = use_step_length;
        o.filter.include_self_weight = include_self_weight;
        o.prevent_folds = prevent_folds;
        o.relax_along_surface = relax_along_surface;
        return denoise(V, F, constrained, progress, threads, o);
      },
      py::arg("V"), py::arg("F"), py::kw_only(), py::arg("automatic_parameters") = true,
      py::arg("noise_level") = py::none(), py::arg("number_of_iterations") = py::none(),
      py::arg("stop_when_converged") = py::none(), py::arg("vertex_iterations") = 2, py::arg("vertex_update") = "paper",
      py::arg("sigma_spatial") = py::none(), py::arg("sigma_range") = py::none(), py::arg("spatial_exponent") = 1.,
      py::arg("range_exponent") = 1., py::arg("neighbor_radius") = py::none(),
      py::arg("relative_neighbor_radius") = py::none(), py::arg("path_strategy") = "square_pattern",
      py::arg("use_step_length") = false, py::arg("geodesic_patch_rings") = 0, py::arg("include_self_weight") = false,
      py::arg("prevent_folds") = true, py::arg("relax_along_surface") = py::none(),
      py::arg("selection_sample_faces") =
          static_cast<long long>(PMP::Intrinsic_denoising_report::default_selection_sample_faces),
      py::arg("long_run_test") = false, py::arg("constrained") = py::none(), py::arg("progress") = py::none(),
      py::arg("threads") = 0,
      R"(Denoises the triangle mesh (V, F) with intrinsic_denoising() (Algorithm 1 of "Mesh denoising via
generalized intrinsic filter on 2D manifold") and returns (V_out, report).

V_out: new (n, 3) float64 array, row i the denoised position of vertex i.
report: dict of what was done (the fields of Intrinsic_denoising_report: parameters used, noise level,
iterations, stop_reason, the candidates of the automatic selection), plus 'face_normals' (the filtered
normals of the last pass, (m, 3)) and 'duplicated_vertices' (vertices the soup repair added).

Keywords are the named parameters of intrinsic_denoising(), with its defaults; None means "not given"
(the automatic mode chooses it). vertex_update: 'paper' (eq. 10) or 'least_squares'. path_strategy:
'square_pattern', 'geodesic', 'direct' or 'shortest_graph_path'. stop_when_converged: default on in the
automatic mode unless number_of_iterations is given. relax_along_surface: default on when the automatic
selection runs (none of the sigmas, radii, number_of_iterations or noise_level given, stopping rule on);
report['relaxed_vertices'] counts the vertices it moved. selection_sample_faces: on a mesh of more than
three times this many faces the automatic selection chooses its setting on a sample of about this many
faces (report['selection_sample_faces']), which then runs once on the whole mesh; 0: never. long_run_test
(for scans): when every candidate stops within 3 iterations, keep a run of 64 iterations of sigma 0.8 on 6 d
if its first iteration made at least half of its change (report['long_run_first_share'], stop_reason
'long_run').
constrained: boolean array, one entry per vertex, True for vertices that never move. progress: callable progress(done, total) after each iteration.
threads: 0 for all, or a limit (the result does not depend on it). Ctrl-C interrupts after the
current iteration. Bad input raises ValueError or TypeError naming the problem.)");
}

// The module's functions for the classic methods that move vertices directly or by one normal pass: FDC03, JDD03, SRML07.
void define_classic_smoothing(py::module_& m)
{
  m.def(
      "bilateral_mesh_denoising",
      [](const py::handle& V, const py::handle& F, double sigma_spatial, std::optional<double> sigma_range,
         long long number_of_iterations, const py::object& constrained, long long threads) {
        const char* fname = "bilateral_mesh_denoising()";
        return run_on_copy(V, F, constrained, threads, [&](Mesh& mesh, const auto& map) {
          const auto np = classic_np(map, number_of_iterations, fname).sigma_spatial(sigma_spatial);
          if(sigma_range)
            PMP::bilateral_mesh_denoising<Tag>(mesh, np.sigma_range(*sigma_range));
          else
            PMP::bilateral_mesh_denoising<Tag>(mesh, np);
        });
      },
      py::arg("V"), py::arg("F"), py::kw_only(), py::arg("sigma_spatial") = 1., py::arg("sigma_range") = py::none(),
      py::arg("number_of_iterations") = 5, py::arg("constrained") = py::none(), py::arg("threads") = 0,
      "FDC03, the bilateral mesh filter of Fleishman et al. 2003 (bilateral_mesh_denoising()); sigma_range None: "
      "per vertex, adaptive. Returns the new V.");

  m.def(
      "non_iterative_denoising",
      [](const py::handle& V, const py::handle& F, double sigma_spatial, double sigma_range,
         long long number_of_iterations, const py::object& constrained, long long threads) {
        const char* fname = "non_iterative_denoising()";
        return run_on_copy(V, F, constrained, threads, [&](Mesh& mesh, const auto& map) {
          PMP::non_iterative_denoising<Tag>(
              mesh, classic_np(map, number_of_iterations, fname).sigma_spatial(sigma_spatial).sigma_range(sigma_range));
        });
      },
      py::arg("V"), py::arg("F"), py::kw_only(), py::arg("sigma_spatial") = 2., py::arg("sigma_range") = 0.5,
      py::arg("number_of_iterations") = 1, py::arg("constrained") = py::none(), py::arg("threads") = 0,
      "JDD03, the robust non-iterative smoothing of Jones et al. 2003 (non_iterative_denoising()). Returns the new V.");

  m.def(
      "fast_feature_preserving_denoising",
      [](const py::handle& V, const py::handle& F, double normal_threshold, bool use_vertex_neighborhood,
         long long number_of_iterations, long long vertex_iterations, const std::string& vertex_update,
         bool relax_along_surface, const py::object& constrained, long long threads) {
        const char* fname = "fast_feature_preserving_denoising()";
        const PMP::Vertex_update update = read_vertex_update(vertex_update);
        return run_on_copy(V, F, constrained, threads, [&](Mesh& mesh, const auto& map) {
          PMP::fast_feature_preserving_denoising<Tag>(mesh,
                                                      classic_np(map, number_of_iterations, fname)
                                                          .normal_threshold(normal_threshold)
                                                          .use_vertex_neighborhood(use_vertex_neighborhood)
                                                          .vertex_iterations(vertex_steps(vertex_iterations, fname))
                                                          .vertex_update(update)
                                                          .relax_along_surface(relax_along_surface));
        });
      },
      py::arg("V"), py::arg("F"), py::kw_only(), py::arg("normal_threshold") = 0.5,
      py::arg("use_vertex_neighborhood") = true, py::arg("number_of_iterations") = 20,
      py::arg("vertex_iterations") = 10, py::arg("vertex_update") = "paper", py::arg("relax_along_surface") = false,
      py::arg("constrained") = py::none(), py::arg("threads") = 0,
      "SRML07, the fast and effective feature-preserving denoising of Sun et al. 2007 "
      "(fast_feature_preserving_denoising()); relax_along_surface: relax the result along the surface as "
      "denoise() does. Returns the new V.");
}

// The module's functions for the classic normal filters and the global L0 method: ZFAT11, HS13, ZDZ15.
void define_classic_normal_filters(py::module_& m)
{
  m.def(
      "bilateral_normal_denoising",
      [](const py::handle& V, const py::handle& F, double sigma_spatial, double sigma_range,
         long long number_of_iterations, long long vertex_iterations, const std::string& vertex_update,
         std::optional<double> neighbor_radius, std::optional<double> relative_neighbor_radius,
         bool relax_along_surface, const py::object& constrained, long long threads) {
        const char* fname = "bilateral_normal_denoising()";
        const PMP::Vertex_update update = read_vertex_update(vertex_update);
        if(neighbor_radius && relative_neighbor_radius)
          throw py::value_error("bilateral_normal_denoising(): give neighbor_radius or relative_neighbor_radius, "
                                "not both");
        return run_on_copy(V, F, constrained, threads, [&](Mesh& mesh, const auto& map) {
          const auto np = normal_filter_np(map, number_of_iterations, sigma_spatial, sigma_range, vertex_iterations,
                                           update, relax_along_surface, fname);
          if(neighbor_radius)
            PMP::bilateral_normal_denoising<Tag>(mesh, np.neighbor_radius(*neighbor_radius));
          else if(relative_neighbor_radius)
            PMP::bilateral_normal_denoising<Tag>(mesh, np.relative_neighbor_radius(*relative_neighbor_radius));
          else
            PMP::bilateral_normal_denoising<Tag>(mesh, np);
        });
      },
      py::arg("V"), py::arg("F"), py::kw_only(), py::arg("sigma_spatial") = 1., py::arg("sigma_range") = 0.35,
      py::arg("number_of_iterations") = 20, py::arg("vertex_iterations") = 10, py::arg("vertex_update") = "paper",
      py::arg("neighbor_radius") = py::none(), py::arg("relative_neighbor_radius") = py::none(),
      py::arg("relax_along_surface") = false, py::arg("constrained") = py::none(), py::arg("threads") = 0,
      "ZFAT11, the bilateral normal filter of Zheng et al. 2011 (bilateral_normal_denoising()); without a radius the "
      "neighbours are the faces sharing a vertex; relax_along_surface: relax the result along the surface as "
      "denoise() does. Returns the new V.");

  m.def(
      "l0_denoising",
      [](const py::handle& V, const py::handle& F, double l0_weight, double regularization_weight,
         const py::object& constrained, long long threads) {
        return run_on_copy(V, F, constrained, threads, [&](Mesh& mesh, const auto& map) {
          PMP::l0_denoising<Tag>(
              mesh, CGAL::parameters::vertex_is_constrained_map(map).l0_weight(l0_weight).regularization_weight(
                        regularization_weight));
        });
      },
      py::arg("V"), py::arg("F"), py::kw_only(), py::arg("l0_weight") = 0.02 * 180. / 3.14159265358979323846,
      py::arg("regularization_weight") = 0.1, py::arg("constrained") = py::none(), py::arg("threads") = 0,
      "HS13, L0 minimisation of He and Schaefer 2013 (l0_denoising()). Returns the new V.");

  m.def(
      "guided_normal_denoising",
      [](const py::handle& V, const py::handle& F, double sigma_spatial, double sigma_range,
         std::optional<double> neighbor_radius, double relative_neighbor_radius, long long number_of_iterations,
         long long vertex_iterations, const std::string& vertex_update, bool relax_along_surface,
         const py::object& constrained, long long threads) {
        const char* fname = "guided_normal_denoising()";
        const PMP::Vertex_update update = read_vertex_update(vertex_update);
        return run_on_copy(V, F, constrained, threads, [&](Mesh& mesh, const auto& map) {
          const auto np = normal_filter_np(map, number_of_iterations, sigma_spatial, sigma_range, vertex_iterations,
                                           update, relax_along_surface, fname);
          if(neighbor_radius)
            PMP::guided_normal_denoising<Tag>(mesh, np.neighbor_radius(*neighbor_radius));
          else
            PMP::guided_normal_denoising<Tag>(mesh, np.relative_neighbor_radius(relative_neighbor_radius));
        });
      },
      py::arg("V"), py::arg("F"), py::kw_only(), py::arg("sigma_spatial") = 1., py::arg("sigma_range") = 0.35,
      py::arg("neighbor_radius") = py::none(), py::arg("relative_neighbor_radius") = 2.,
      py::arg("number_of_iterations") = 20, py::arg("vertex_iterations") = 10, py::arg("vertex_update") = "paper",
      py::arg("relax_along_surface") = false, py::arg("constrained") = py::none(), py::arg("threads") = 0,
      "ZDZ15, guided mesh normal filtering of Zhang et al. 2015 (guided_normal_denoising()); neighbor_radius, if "
      "given, replaces relative_neighbor_radius; relax_along_surface: relax the result along the surface as "
      "denoise() does. Returns the new V.");
}

// The module's functions for the seeded noise models.
void define_noise_models(py::module_& m)
{
  m.def(
      "add_gaussian_noise",
      [](const py::handle& V, const py::handle& F, double sigma, long long seed, const py::object& constrained) {
        return add_noise(V, F, seed, constrained,
                         [sigma](Mesh& mesh, const auto& np) { PMP::add_gaussian_noise(mesh, sigma, np); });
      },
      py::arg("V"), py::arg("F"), py::arg("sigma"), py::kw_only(), py::arg("seed") = 0,
      py::arg("constrained") = py::none(),
      "Gaussian noise along the vertex normals, standard deviation sigma times the mean edge length (the paper's "
      "sigma_E), seeded (add_gaussian_noise()). Returns the new V.");
  m.def(
      "add_isotropic_gaussian_noise",
      [](const py::handle& V, const py::handle& F, double sigma, long long seed, const py::object& constrained) {
        return add_noise(V, F, seed, constrained,
                         [sigma](Mesh& mesh, const auto& np) { PMP::add_isotropic_gaussian_noise(mesh, sigma, np); });
      },
      py::arg("V"), py::arg("F"), py::arg("sigma"), py::kw_only(), py::arg("seed") = 0,
      py::arg("constrained") = py::none(),
      "Gaussian noise in random directions: three independent coordinates, the RMS length of the moves sigma times "
      "the mean edge length, seeded (add_isotropic_gaussian_noise()). Returns the new V.");
  m.def(
      "add_impulsive_noise",
      [](const py::handle& V, const py::handle& F, double fraction, double sigma, long long seed,
         const py::object& constrained) {
        return add_noise(V, F, seed, constrained, [fraction, sigma](Mesh& mesh, const auto& np) {
          PMP::add_impulsive_noise(mesh, fraction, sigma, np);
        });
      },
      py::arg("V"), py::arg("F"), py::arg("fraction"), py::arg("sigma"), py::kw_only(), py::arg("seed") = 0,
      py::arg("constrained") = py::none(),
      "Impulsive noise: each vertex with probability fraction moves along its normal by a Gaussian amount of "
      "standard deviation sigma times the mean edge length (add_impulsive_noise()). Returns the new V.");
  m.def(
      "add_depth_scan_noise",
      [](const py::handle& V, const py::handle& F, double sigma, long long seed, const py::object& constrained) {
        return add_noise(V, F, seed, constrained,
                         [sigma](Mesh& mesh, const auto& np) { PMP::add_depth_scan_noise(mesh, sigma, np); });
      },
      py::arg("V"), py::arg("F"), py::arg("sigma"), py::kw_only(), py::arg("seed") = 0,
      py::arg("constrained") = py::none(),
      "Simulated depth-scan noise: along camera rays, growing with depth, with a low-frequency term and outliers "
      "(add_depth_scan_noise()). Returns the new V.");
}

// The module's functions for the error metrics E_n and E_v.
void define_metrics(py::module_& m)
{
  m.def(
      "face_normal_error",
      [](const py::handle& V, const py::handle& F, const py::handle& V_reference, const py::object& F_reference) {
        return compare(V, F, V_reference, F_reference,
                       [](const Mesh& a, const Mesh& b) { return PMP::face_normal_error(a, b); });
      },
      py::arg("V"), py::arg("F"), py::arg("V_reference"), py::arg("F_reference") = py::none(),
      "E_n (eq. 12): the mean angle in degrees between the face normals of (V, F) and of the reference, face by "
      "face (F_reference default: F).");
  m.def(
      "vertex_position_error",
      [](const py::handle& V, const py::handle& F, const py::handle& V_reference, const py::object& F_reference) {
        return compare(V, F, V_reference, F_reference,
                       [](const Mesh& a, const Mesh& b) { return PMP::vertex_position_error(a, b); });
      },
      py::arg("V"), py::arg("F"), py::arg("V_reference"), py::arg("F_reference") = py::none(),
      "E_v (eq. 11): the area-weighted distance from the vertices of (V, F) to the reference surface "
      "(F_reference default: F).");
}

// The module's functions for the mesh files of the `denoise` tool.
void define_file_io(py::module_& m)
{
  m.def(
      "read_mesh",
      [](const std::string& path) {
        Mesh mesh;
        std::vector<std::string> warnings;
        std::string problem;
        {
          py::gil_scoped_release release;
          problem = denoising_support::read_mesh_file(path, mesh, &warnings);
        }
        if(problem.rfind("cannot open", 0) == 0)
        {
          PyErr_SetString(PyExc_OSError, problem.c_str());
          throw py::error_already_set();
        }
        if(!problem.empty())
          throw py::value_error(problem);
        if(mesh.has_garbage())
          mesh.collect_garbage();
        for(const std::string& w : warnings)
          PyErr_WarnEx(PyExc_UserWarning, ("'" + path + "': " + w).c_str(), 1);
        return arrays_of(mesh);
      },
      py::arg("path"),
      "Reads a triangle mesh (OFF, OBJ, PLY or STL, by the extension) with the bounded readers of the `denoise` "
      "tool and returns (V, F). A soup that is not a manifold surface is repaired as the tool does. Raises OSError "
      "if the file cannot be opened, ValueError naming the problem if it is malformed; data read but not used is "
      "reported by a UserWarning.");
  m.def(
      "write_mesh",
      [](const std::string& path, const py::handle& V, const py::handle& F) {
        std::unique_ptr<Input> input = make_input(V, F);
        std::string problem;
        {
          py::gil_scoped_release release;
          problem = denoising_support::write_mesh(path, input->mesh);
        }
        if(problem.rfind("cannot write", 0) == 0)
        {
          PyErr_SetString(PyExc_OSError, problem.c_str());
          throw py::error_already_set();
        }
        if(!problem.empty())
          throw py::value_error(problem);
      },
      py::arg("path"), py::arg("V"), py::arg("F"),
      "Writes (V, F) to path (OFF, OBJ, PLY or STL, by the extension; 17 significant digits) through a temporary "
      "file and a rename, so that path is either unchanged or complete. Raises OSError if it cannot be written.");
}

} // namespace

PYBIND11_MODULE(cgal_intrinsic_denoising, m)
{
  m.doc() = "Feature-preserving mesh denoising with the generalized intrinsic filter (CGAL package): "
            "intrinsic_denoising() on NumPy arrays, the classic methods, the noise models and the error "
            "metrics E_n and E_v. A mesh is V, an (n, 3) array of coordinates, and F, an (m, 3) array of "
            "vertex indices; functions return new arrays and never modify their arguments.";

  define_intrinsic(m);
  define_classic_smoothing(m);
  define_classic_normal_filters(m);
  define_noise_models(m);
  define_metrics(m);
  define_file_io(m);
}
