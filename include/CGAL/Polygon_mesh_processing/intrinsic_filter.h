// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The generalized intrinsic filter of section 3.1 of "Mesh denoising via
// generalized intrinsic filter on 2D manifold", on any per-face or per-vertex
// signal, with the bilateral, geodesic and propagation filters as presets.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTRINSIC_FILTER_H
#define CGAL_POLYGON_MESH_PROCESSING_INTRINSIC_FILTER_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/intrinsic_setup.h>

#include <CGAL/tags.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Conversion of a signal value to and from `dimension` doubles. Supported:
// arithmetic types (integral results are rounded), std::array of them, and 3D
// types with x(), y(), z() and a constructor from three coordinates (CGAL's
// Point_3 and Vector_3).
template <typename T, typename = void>
struct Signal_traits
{
  static_assert(sizeof(T) == 0, "unsupported signal value type: use an arithmetic type, a std::array of one, "
                                "or a type with x(), y(), z() such as CGAL's Point_3 and Vector_3");
};

template <typename T>
T signal_scalar(double x)
{
  if constexpr(std::is_integral<T>::value)
    return static_cast<T>(std::llround(x));
  else
    return static_cast<T>(x);
}

template <typename T>
struct Signal_traits<T, std::enable_if_t<std::is_arithmetic<T>::value>>
{
  static constexpr std::size_t dimension = 1;
  static void get(const T& v, double* out) { out[0] = static_cast<double>(v); }
  static T make(const double* in) { return signal_scalar<T>(in[0]); }
};

template <typename T, std::size_t N>
struct Signal_traits<std::array<T, N>, std::enable_if_t<std::is_arithmetic<T>::value>>
{
  static constexpr std::size_t dimension = N;
  static void get(const std::array<T, N>& v, double* out)
  {
    for(std::size_t k = 0; k < N; ++k)
      out[k] = static_cast<double>(v[k]);
  }
  static std::array<T, N> make(const double* in)
  {
    std::array<T, N> v;
    for(std::size_t k = 0; k < N; ++k)
      v[k] = signal_scalar<T>(in[k]);
    return v;
  }
};

template <typename T>
struct Signal_traits<T, std::void_t<decltype(std::declval<const T&>().x()), decltype(std::declval<const T&>().y()),
                                    decltype(std::declval<const T&>().z())>>
{
  static constexpr std::size_t dimension = 3;
  static void get(const T& v, double* out)
  {
    out[0] = CGAL::to_double(v.x());
    out[1] = CGAL::to_double(v.y());
    out[2] = CGAL::to_double(v.z());
  }
  static T make(const double* in) { return T(in[0], in[1], in[2]); }
};

// A signal as `dimension` doubles per item (face or vertex index). Dimension
// 0 is the constant signal: every distance is 0.
struct Flat_signal
{
  std::size_t dimension = 0;
  std::vector<double> values;

  double* at(std::size_t i) { return values.data() + i * dimension; }
  const double* at(std::size_t i) const { return values.data() + i * dimension; }
  double squared_distance(std::uint32_t a, std::uint32_t b) const
  {
    const double *x = at(a), *y = at(b);
    double s = 0.;
    for(std::size_t k = 0; k < dimension; ++k)
      s += (x[k] - y[k]) * (x[k] - y[k]);
    return s;
  }
};

inline Flat_signal flat_signal(const std::vector<Vec3>& v)
{
  Flat_signal s;
  s.dimension = 3;
  s.values.resize(3 * v.size());
  for(std::size_t i = 0; i < v.size(); ++i)
    for(std::size_t k = 0; k < 3; ++k)
      s.values[3 * i + k] = v[i][k];
  return s;
}

// Reads a property map over `keys` (indexed by `index`) into a flat signal;
// throws std::invalid_argument on a NaN or infinite value.
template <typename Keys, typename IndexMap, typename SignalMap>
Flat_signal read_signal(const Keys& keys, std::size_t count, const IndexMap& index, const SignalMap& map,
                        const char* fname, const char* what)
{
  typedef typename boost::property_traits<SignalMap>::value_type Value;
  typedef Signal_traits<typename std::decay<Value>::type> Traits;
  Flat_signal s;
  s.dimension = Traits::dimension;
  s.values.resize(count * s.dimension);
  for(auto key : keys)
  {
    double* out = s.at(get(index, key));
    Traits::get(get(map, key), out);
    for(std::size_t k = 0; k < s.dimension; ++k)
      if(!std::isfinite(out[k]))
        throw std::invalid_argument(std::string(fname) + ": the " + what + " has a NaN or infinite value.");
  }
  return s;
}

// The built-in choices for phi and psi; `input` stands for the signal being
// filtered and is returned as a null pointer (it changes with the iterations).
template <typename Param, typename Keys, typename IndexMap>
const Flat_signal* resolve_signal(const Param& param, Flat_signal& storage, const Keys& keys, std::size_t count,
                                  const IndexMap& index, const std::vector<Vec3>& positions,
                                  const std::vector<Vec3>& normals, const char* fname, const char* what)
{
  if constexpr(std::is_same<Param, Intrinsic_signal>::value)
  {
    switch(param)
    {
    case Intrinsic_signal::INPUT:
      return nullptr;
    case Intrinsic_signal::POSITION:
      storage = flat_signal(positions);
      break;
    case Intrinsic_signal::NORMAL:
      storage = flat_signal(normals);
      break;
    case Intrinsic_signal::CONSTANT:
      storage = Flat_signal();
      break;
    default:
      throw std::invalid_argument(std::string(fname) + ": unknown signal for " + what + ".");
    }
  }
  else
    storage = read_signal(keys, count, index, param, fname, what);
  return &storage;
}

// The weighted average of eq. 1 (or eq. 8 with unit-length results) of
// `input` on the path trees `paths`, with measure `measure` (areas).
template <typename ConcurrencyTag>
void intrinsic_average_pass(const Path_forest& paths, const Intrinsic_kernel& kernel, const Flat_signal& phi,
                            const Flat_signal& psi, const std::vector<double>& measure, const Flat_signal& input,
                            bool unit_length, Flat_signal& out)
{
  const std::size_t dim = input.dimension;
  out.dimension = dim;
  out.values.resize(input.values.size());
  intrinsic_weights_pass<ConcurrencyTag>(
      paths, kernel, [&phi](std::uint32_t a, std::uint32_t b) { return phi.squared_distance(a, b); },
      [&psi](std::uint32_t a, std::uint32_t b) { return psi.squared_distance(a, b); },
      [&](std::size_t i, std::uint32_t b, std::uint32_t e, const double* w) {
        double* o = out.at(i);
        for(std::size_t d = 0; d < dim; ++d)
          o[d] = 0.;
        double total = 0.;
        auto add = [&](std::size_t j, double weight) {
          const double* x = input.at(j);
          for(std::size_t d = 0; d < dim; ++d)
            o[d] += weight * x[d];
          total += weight;
        };
        if(kernel.include_self)
          add(i, measure[i]);
        for(std::uint32_t k = b; k < e; ++k)
          if(paths.is_weighted(k))
            add(paths.face[k], measure[paths.face[k]] * w[k - b]);
        double scale = 0.;
        if(unit_length)
        {
          double len2 = 0.;
          for(std::size_t d = 0; d < dim; ++d)
            len2 += o[d] * o[d];
          scale = len2 > 0. ? 1. / std::sqrt(len2) : 0.;
        }
        else
          scale = total > 0. ? 1. / total : 0.;
        if(scale > 0. && std::isfinite(scale))
          for(std::size_t d = 0; d < dim; ++d)
            o[d] *= scale;
        else // nothing to average with: keep the value
          for(std::size_t d = 0; d < dim; ++d)
            o[d] = input.at(i)[d];
      });
}

} // namespace Denoising
} // namespace internal

/*!
  \ingroup PMP_denoising_grp

  \brief the generalized intrinsic filter of section 3.1 (eqs. 1-4) on a
  per-face or per-vertex signal \f$J\f$ of `tmesh`:
  \f[ \tilde J_p = \frac{1}{W_p}\sum_{q\in N(p)} A_q\; g(d^s;\sigma_s)\,g(d^r;\sigma_r)\; J_q, \qquad
      W_p = \sum_{q\in N(p)} A_q\, g(d^s;\sigma_s)\,g(d^r;\sigma_r), \f]
  \f[ d^s = \Big(\sum_{x\in L} \|\varphi_{x+1} - \varphi_x\|^n\,\ell_x\Big)^{1/n}, \qquad
      d^r = \Big(\sum_{x\in L} \|\psi_x - \psi_p\|^m\,\ell_x\Big)^{1/m}, \f]
  along the path \f$L\f$ from \f$p\f$ to \f$q\f$ given by `path_strategy`,
  with step lengths \f$\ell_x = \|q_{x+1}-q_x\|\f$ (`use_step_length`) or 1,
  \f$A_q\f$ the area of face \f$q\f$ (a third of the area around vertex
  \f$q\f$), and \f$N(p)\f$ the geometric neighbourhood of radius \f$r\f$.
  The result is written to `filtered` (which may be the same map as `signal`);
  the mesh is not modified.

  The face-normal denoiser `intrinsic_denoising()` runs on the same engine,
  with \f$\varphi = \psi = J\f$ = the face normals. The classic filters are
  presets (see `bilateral_filter_parameters()`,
  `geodesic_filter_parameters()`, `propagation_filter_parameters()`).

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Parallel_if_available_tag`; the result does not depend on it.
  \tparam TriangleMesh a model of `FaceListGraph`
  \tparam SignalMap a model of `ReadablePropertyMap` whose key type is the
          face descriptor (a face signal) or the vertex descriptor (a vertex
          signal) of `TriangleMesh`, and whose value type is an arithmetic
          type, a `std::array` of one, or a 3D type with `x()`, `y()`, `z()`
          (`Point_3`, `Vector_3`, a colour as `std::array<double, 3>`...)
  \tparam FilteredSignalMap a model of `WritablePropertyMap` with the same key
          type and a supported value type of the same dimension
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh that carries the signal; it is not modified
  \param signal the property map giving the value \f$J\f$ of every face or of every vertex
  \param filtered the property map receiving the filtered values \f$\tilde J\f$; it may be `signal` itself
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{spatial_signal}
      \cgalParamDescription{\f$\varphi\f$: an `Intrinsic_signal` (`INPUT`, `POSITION`, `NORMAL`, `CONSTANT`) or a readable property map with the signal's key type and a supported value type}
      \cgalParamDefault{`Intrinsic_signal::INPUT`}
    \cgalParamNEnd
    \cgalParamNBegin{range_signal}
      \cgalParamDescription{\f$\psi\f$, as `spatial_signal`}
      \cgalParamDefault{`Intrinsic_signal::INPUT`}
    \cgalParamNEnd
    \cgalParamNBegin{sigma_spatial, sigma_range}
      \cgalParamDescription{\f$\sigma_s\f$, \f$\sigma_r\f$, in the units of \f$d^s\f$ and \f$d^r\f$}
      \cgalParamType{double}
      \cgalParamDefault{`0.4` each}
    \cgalParamNEnd
    \cgalParamNBegin{spatial_exponent, range_exponent}
      \cgalParamDescription{\f$n\f$ and \f$m\f$}
      \cgalParamType{double}
      \cgalParamDefault{`1` each (L1)}
    \cgalParamNEnd
    \cgalParamNBegin{path_strategy}
      \cgalParamDescription{`Intrinsic_path_strategy`: `SQUARE_PATTERN` or `GEODESIC` (face signals only), `DIRECT` or `SHORTEST_GRAPH_PATH`}
      \cgalParamDefault{`SQUARE_PATTERN` for a face signal, `SHORTEST_GRAPH_PATH` for a vertex signal}
    \cgalParamNEnd
    \cgalParamNBegin{use_step_length}
      \cgalParamDescription{multiply each term of the sums by the distance between the positions (centroids or points) of consecutive path items (eq. 4), in units of the mean distance between adjacent items}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{neighbor_radius, relative_neighbor_radius}
      \cgalParamDescription{the neighbourhood radius, absolute or as a multiple of the mean distance between adjacent items (edge-adjacent face centroids; edge lengths for vertices)}
      \cgalParamDefault{4 times that mean distance}
    \cgalParamNEnd
    \cgalParamNBegin{include_self_weight}
      \cgalParamDescription{whether \f$p\f$ itself takes part in its average (weight \f$A_p\f$)}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{how many times the filter is applied (paths are built once; \f$\varphi\f$ and \f$\psi\f$ set to `INPUT` follow the filtered signal)}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{unit_length_result}
      \cgalParamDescription{if `true`, each result is divided by its length instead of \f$W_p\f$ (for unit vectors such as normals, as in eq. 8)}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map, geom_traits}
      \cgalParamDescription{as for `intrinsic_denoising()`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  An item with nothing to average with keeps its value.

  \pre `tmesh` is a triangle mesh with finite coordinates; the signals have
       finite values; the numeric parameters are positive and finite;
       `SQUARE_PATTERN` is used with a face signal only. Otherwise
       `std::invalid_argument` is thrown and nothing is written. A mesh
       without faces is left as it is and nothing is written.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename SignalMap,
          typename FilteredSignalMap, typename NamedParameters = parameters::Default_named_parameters>
void intrinsic_filter(const TriangleMesh& tmesh, const SignalMap& signal, FilteredSignalMap filtered,
                      const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename boost::property_traits<SignalMap>::key_type Key;
  constexpr bool on_faces = std::is_same<Key, typename GT::face_descriptor>::value;
  static_assert(on_faces || std::is_same<Key, typename GT::vertex_descriptor>::value,
                "the signal's key type must be the mesh's face or vertex descriptor");
  static const char* fname = "intrinsic_filter()";
  if(faces(tmesh).empty())
    return;

  const D::Mesh_maps<TriangleMesh, NamedParameters> maps(tmesh, np);
  const D::Intrinsic_kernel kernel = D::read_kernel(np, fname);
  const unsigned int iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1u);
  const bool unit_length = choose_parameter(get_parameter(np, internal_np::unit_length_result), false);
  const Intrinsic_path_strategy strategy = D::read_strategy(
      np, on_faces ? Intrinsic_path_strategy::SQUARE_PATTERN : Intrinsic_path_strategy::SHORTEST_GRAPH_PATH);
  const bool step_length = D::read_step_length(np);

  const D::Flat_mesh m = maps.flat(tmesh, fname);
  D::Face_data fd;
  D::compute_face_data<ConcurrencyTag>(m, m.points, fd);

  auto run = [&](const auto& keys, std::size_t count, const auto& index, const std::vector<D::Vec3>& positions,
                 const std::vector<D::Vec3>& normals, const std::vector<double>& measure, const auto& adjacency,
                 double unit) {
    const double radius = D::read_radius(np, fname, unit, D::Intrinsic_defaults::relative_radius);
    // on faces, the search that visits the faces around a vertex once (same lists)
    D::Csr neighbors;
    if constexpr(on_faces)
      neighbors = D::geometric_neighborhoods<ConcurrencyTag>(m, positions, radius);
    else
      neighbors = D::geometric_neighborhoods<ConcurrencyTag>(positions, adjacency, radius);
    const D::Path_forest paths =
        D::make_paths<ConcurrencyTag>(np, strategy, step_length, unit, positions, adjacency, neighbors,
                                      on_faces ? &m : nullptr, on_faces ? &fd : nullptr, fname);
    D::Flat_signal current = D::read_signal(keys, count, index, signal, fname, "signal"), next, phi_store, psi_store;
    const D::Flat_signal* phi_fixed =
        D::resolve_signal(choose_parameter(get_parameter(np, internal_np::spatial_signal), Intrinsic_signal::INPUT),
                          phi_store, keys, count, index, positions, normals, fname, "spatial signal");
    const D::Flat_signal* psi_fixed =
        D::resolve_signal(choose_parameter(get_parameter(np, internal_np::range_signal), Intrinsic_signal::INPUT),
                          psi_store, keys, count, index, positions, normals, fname, "range signal");
    for(unsigned int it = 0; it < iterations; ++it)
    {
      D::intrinsic_average_pass<ConcurrencyTag>(paths, kernel, phi_fixed ? *phi_fixed : current,
                                                psi_fixed ? *psi_fixed : current, measure, current, unit_length, next);
      std::swap(current, next);
    }
    typedef typename boost::property_traits<FilteredSignalMap>::value_type Out;
    typedef D::Signal_traits<typename std::decay<Out>::type> Out_traits;
    if(Out_traits::dimension != current.dimension)
      throw std::invalid_argument(std::string(fname) + ": the filtered signal map's values have another dimension "
                                                       "than the signal's.");
    for(auto key : keys)
      put(filtered, key, Out_traits::make(current.at(get(index, key))));
  };

  if constexpr(on_faces)
  {
    run(faces(tmesh), m.number_of_faces(), maps.fim, fd.centroids, fd.normals, fd.areas, D::Face_vertex_adjacency{m},
        D::mean_adjacent_centroid_distance(m, fd));
  }
  else
  {
    const D::Csr edges = D::vertex_adjacency(m);
    const D::Vertex_edge_adjacency adjacency{edges};
    run(vertices(tmesh), m.number_of_vertices(), maps.vim, m.points, D::area_weighted_vertex_normals(m),
        D::vertex_areas(m, fd.areas), adjacency, D::mean_adjacent_distance(m.points, adjacency));
  }
}

/*!
  \ingroup PMP_denoising_grp
  \brief named parameters making `intrinsic_filter()` the bilateral filter
  (Tomasi and Manduchi 1998; the paper's case 1, eq. 5): path \f$L = \{p, q\}\f$,
  \f$\varphi\f$ = position, \f$\psi\f$ = the signal, \f$n = m = 2\f$, so
  \f$d^s = \|p - q\|\f$ and \f$d^r = \|J_p - J_q\|\f$; \f$p\f$ takes part in
  its own average, as in the classic filter. Parameters chained after these
  override them (e.g. `.neighbor_radius(2 * sigma_spatial)` for the window).

  \param sigma_spatial \f$\sigma_s\f$, the width of the kernel on the distance between the positions of \f$p\f$
                       and \f$q\f$ (face centroids or vertex points), in the mesh's length unit
  \param sigma_range \f$\sigma_r\f$, the width of the kernel on \f$\|J_p - J_q\|\f$, in the signal's unit
  \return the named parameters, to pass to `intrinsic_filter()` (more can be chained after them)
*/
inline auto bilateral_filter_parameters(double sigma_spatial, double sigma_range)
{
  return parameters::path_strategy(Intrinsic_path_strategy::DIRECT)
      .spatial_signal(Intrinsic_signal::POSITION)
      .range_signal(Intrinsic_signal::INPUT)
      .spatial_exponent(2.)
      .range_exponent(2.)
      .include_self_weight(true)
      .sigma_spatial(sigma_spatial)
      .sigma_range(sigma_range);
}

/*!
  \ingroup PMP_denoising_grp
  \brief named parameters making `intrinsic_filter()` the geodesic filter
  (Grazzini and Soille 2009; the paper's case 2, eq. 6): \f$d^s\f$ sums the
  squared signal changes along the shortest graph path (\f$n = 2\f$,
  \f$\varphi\f$ = the signal) and \f$d^r\f$ is constant, so only \f$d^s\f$
  decides the weights; \f$p\f$ takes part in its own average.

  \param sigma_spatial \f$\sigma_s\f$, the width of the kernel on \f$d^s\f$, the square root of the sum of the
                       squared signal changes between consecutive items of the path, in the signal's unit
  \return the named parameters, to pass to `intrinsic_filter()` (more can be chained after them)
*/
inline auto geodesic_filter_parameters(double sigma_spatial)
{
  return parameters::path_strategy(Intrinsic_path_strategy::SHORTEST_GRAPH_PATH)
      .spatial_signal(Intrinsic_signal::INPUT)
      .range_signal(Intrinsic_signal::CONSTANT)
      .spatial_exponent(2.)
      .range_exponent(2.)
      .include_self_weight(true)
      .sigma_spatial(sigma_spatial);
}

/*!
  \ingroup PMP_denoising_grp
  \brief named parameters making `intrinsic_filter()` the propagation filter
  (Chang and Wang 2015; the paper's case 3, eq. 7): \f$n = m = 2\f$ and
  \f$\varphi = \psi\f$ = the signal along the shortest graph path;
  \f$p\f$ takes part in its own average.

  \param sigma_spatial \f$\sigma_s\f$, the width of the kernel on \f$d^s\f$, the square root of the sum of the
                       squared signal changes between consecutive items of the path, in the signal's unit
  \param sigma_range \f$\sigma_r\f$, the width of the kernel on \f$d^r\f$, the square root of the sum over the
                     path of the squared differences \f$\|J_x - J_p\|^2\f$, in the signal's unit
  \return the named parameters, to pass to `intrinsic_filter()` (more can be chained after them)
*/
inline auto propagation_filter_parameters(double sigma_spatial, double sigma_range)
{
  return parameters::path_strategy(Intrinsic_path_strategy::SHORTEST_GRAPH_PATH)
      .spatial_signal(Intrinsic_signal::INPUT)
      .range_signal(Intrinsic_signal::INPUT)
      .spatial_exponent(2.)
      .range_exponent(2.)
      .include_self_weight(true)
      .sigma_spatial(sigma_spatial)
      .sigma_range(sigma_range);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
