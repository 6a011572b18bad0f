// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The generalized intrinsic filter of section 3.1 of "Mesh denoising via
// generalized intrinsic filter on 2D manifold", on any per-face or per-vertex
// signal, with the bilateral, geodesic and propagation filters as presets.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTRINSIC_FILTER_H
#define CGAL_POLYGON_MESH_PROCESSING_INTRINSIC_FILTER_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/general_filter.h>

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
  const D::Filter_options options = D::read_filter_options(np);
  const D::Intrinsic_kernel kernel = D::filter_kernel(options, fname);
  const unsigned int iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1u);
  const bool unit_length = choose_parameter(get_parameter(np, internal_np::unit_length_result), false);
  const Intrinsic_path_strategy strategy = options.path_strategy.value_or(
      on_faces ? Intrinsic_path_strategy::SQUARE_PATTERN : Intrinsic_path_strategy::SHORTEST_GRAPH_PATH);
  const bool step_length = options.use_step_length;

  const D::Flat_mesh m = maps.flat(tmesh, fname);
  D::Face_data fd;
  D::compute_face_data<ConcurrencyTag>(m, m.points, fd);

  auto run = [&](const auto& keys, std::size_t count, const auto& index, const std::vector<D::Vec3>& positions,
                 const std::vector<D::Vec3>& normals, const std::vector<double>& measure, const auto& adjacency,
                 double unit) {
    const double radius = D::filter_radius(options, fname, unit, D::Intrinsic_defaults::relative_radius);
    // on faces, the search that visits the faces around a vertex once (same lists)
    D::Csr neighbors;
    if constexpr(on_faces)
      neighbors = D::geometric_neighborhoods<ConcurrencyTag>(m, positions, radius);
    else
      neighbors = D::geometric_neighborhoods<ConcurrencyTag>(positions, adjacency, radius);
    const D::Path_forest paths =
        D::make_paths<ConcurrencyTag>(options, strategy, step_length, unit, positions, adjacency, neighbors,
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
