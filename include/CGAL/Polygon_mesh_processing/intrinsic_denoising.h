// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Mesh denoising via the intrinsic filter (Algorithm 1 of "Mesh denoising via
// generalized intrinsic filter on 2D manifold"): face normals filtered with
// weights integrated along paths (eqs. 8-9), then vertices updated (eq. 10).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTRINSIC_DENOISING_H
#define CGAL_POLYGON_MESH_PROCESSING_INTRINSIC_DENOISING_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/intrinsic_denoiser.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/weights/normal_filter_pass.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising_report.h>

#include <CGAL/tags.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
  \ingroup PMP_denoising_grp

  \brief one pass of the intrinsic filter (eq. 8 of the paper) on the face
  normals of `tmesh`; writes the filtered normals to `filtered_normals` and
  leaves the mesh unchanged.

  For each face \f$i\f$ with unit normal \f$n_i\f$ and neighbourhood
  \f$N_i\f$ (the faces connected to \f$i\f$ through vertices whose centroid is
  within `neighbor_radius` of \f$c_i\f$; where the faces are so much smaller
  than on average that more than 16 times the faces a disc of that radius
  holds at the mean face area (and more than 256) would be taken in, the
  squared radius is halved until they are not: see the manual's section on
  robustness),
  \f[ \bar n_i = \frac{1}{W_i}\sum_{j\in N_i} A_j\, g(d^s_{ij};\sigma_s)\, g(d^r_{ij};\sigma_r)\, n_j, \qquad
      g(x;\sigma) = e^{-x^2/2\sigma^2}, \f]
  with, along the path \f$L = (i = x_0, x_1, \dots, x_k = j)\f$ (eq. 9),
  \f$ d^s = (\sum_x \|n_{x+1} - n_x\|^n)^{1/n}\f$ and
  \f$ d^r = (\sum_{x\in L} \|n_x - n_i\|^m)^{1/m}\f$, and \f$W_i\f$ the norm of
  the sum, so that \f$\bar n_i\f$ is a unit vector. The paths are those of
  `path_strategy`, built on the mesh as given.

  The neighbourhood and paths are rebuilt at every call; `intrinsic_denoising()`
  builds them once for all its iterations.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Parallel_if_available_tag`; the result does not depend on it.
  \tparam TriangleMesh a model of `FaceListGraph`
  \tparam FaceNormalMap a model of `WritablePropertyMap` with face descriptors
          as keys and `GeomTraits::Vector_3` as values
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh whose face normals are filtered; it is not modified
  \param filtered_normals the property map receiving the filtered normal of every face
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{sigma_spatial}
      \cgalParamDescription{\f$\sigma_s\f$, the width of the kernel on \f$d^s\f$ (sum of normal changes along the path)}
      \cgalParamType{double}
      \cgalParamDefault{`0.4`}
    \cgalParamNEnd
    \cgalParamNBegin{sigma_range}
      \cgalParamDescription{\f$\sigma_r\f$, the width of the kernel on \f$d^r\f$ (sum of normal differences to \f$n_i\f$ along the path)}
      \cgalParamType{double}
      \cgalParamDefault{`0.4`}
    \cgalParamNEnd
    \cgalParamNBegin{spatial_exponent}
      \cgalParamDescription{the exponent \f$n\f$ of \f$d^s\f$ (1: L1, the paper's choice)}
      \cgalParamType{double}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{range_exponent}
      \cgalParamDescription{the exponent \f$m\f$ of \f$d^r\f$}
      \cgalParamType{double}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{neighbor_radius}
      \cgalParamDescription{the radius \f$r\f$ of the geometric neighbourhood, in the mesh's length unit (smaller where the faces are far smaller than on average, see above)}
      \cgalParamType{double}
      \cgalParamDefault{`relative_neighbor_radius` times \f$d\f$}
    \cgalParamNEnd
    \cgalParamNBegin{relative_neighbor_radius}
      \cgalParamDescription{the radius as a multiple of \f$d\f$, the mean distance between the centroids of edge-adjacent faces (the paper uses 2 to 6); ignored if `neighbor_radius` is given}
      \cgalParamType{double}
      \cgalParamDefault{`4`}
    \cgalParamNEnd
    \cgalParamNBegin{path_strategy}
      \cgalParamDescription{how paths are chosen}
      \cgalParamType{`CGAL::Polygon_mesh_processing::Intrinsic_path_strategy`}
      \cgalParamDefault{`Intrinsic_path_strategy::SQUARE_PATTERN`}
    \cgalParamNEnd
    \cgalParamNBegin{use_step_length}
      \cgalParamDescription{if `true`, each term of both sums of eq. 9 is multiplied by its step length \f$\|q_{x+1} - q_x\|\f$ (eq. 4), in units of \f$d\f$ (the mean distance between the centroids of edge-adjacent faces): the distance between the centroids of consecutive path faces, or, with `GEODESIC` paths, the length along the geodesic between the middles of its parts in consecutive faces (\f$c_i\f$ and \f$c_j\f$ at the ends); eq. 8-9 set it to 1}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{geodesic_patch_rings}
      \cgalParamDescription{with `Intrinsic_path_strategy::GEODESIC`: the geodesics from \f$c_i\f$ are
        computed on a copy of face \f$i\f$, its neighbourhood and this number of rings of faces (sharing a
        vertex) around it, of which only the faces closer to \f$c_i\f$ than the farthest neighbour centroid
        are kept (faces of zero area are left out). With 0, a geodesic stays inside the neighbourhood; a ring
        lets it pass through faces whose centroid lies just outside the radius (on the benchmark meshes this
        changes \f$E_n\f$ by less than 0.001 degree and costs about a third more path time). A neighbour no
        geodesic reaches inside that patch, or whose computed geodesic is not a plausible path (see the
        manual), gets the direct path
        \f$\{i, j\}\f$. A geodesic through a vertex crosses only the faces its segments cross, not the
        faces it touches at the vertex.}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{include_self_weight}
      \cgalParamDescription{if `true`, \f$A_i n_i\f$ is added to the sum; eq. 8 read literally leaves it out}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with vertex descriptors as keys and `GeomTraits::Point_3` as values}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDescription{a property map associating to each vertex an index from 0 to `num_vertices(tmesh) - 1`}
      \cgalParamType{a model of `ReadablePropertyMap` with vertex descriptors as keys and `std::size_t` as values}
      \cgalParamDefault{an automatically indexed internal map}
    \cgalParamNEnd
    \cgalParamNBegin{face_index_map}
      \cgalParamDescription{a property map associating to each face an index from 0 to `num_faces(tmesh) - 1`}
      \cgalParamType{a model of `ReadablePropertyMap` with face descriptors as keys and `std::size_t` as values}
      \cgalParamDefault{an automatically indexed internal map}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of a geometric traits class}
      \cgalParamType{a model of `Kernel`}
      \cgalParamDefault{a \cgal Kernel deduced from the point type}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  A face with zero area has a zero normal: it has no weight in the sums and no
  NaN is produced. A face whose weighted sum vanishes keeps its normal.

  \pre `tmesh` is a triangle mesh with finite coordinates; the numeric
       parameters are positive and finite. Otherwise `std::invalid_argument` is
       thrown and nothing is written.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename FaceNormalMap,
          typename NamedParameters = parameters::Default_named_parameters>
void intrinsic_filter_face_normals(const TriangleMesh& tmesh, FaceNormalMap filtered_normals,
                                   const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  static const char* fname = "intrinsic_filter_face_normals()";
  if(faces(tmesh).empty())
    return;
  const D::Mesh_maps<TriangleMesh, NamedParameters> maps(tmesh, np);
  const D::Intrinsic_setup s = D::make_intrinsic_setup<ConcurrencyTag>(tmesh, D::read_filter_options(np), maps, fname);
  std::vector<D::Vec3> out;
  D::intrinsic_filter_pass<ConcurrencyTag>(s.paths, s.input_faces.normals, s.input_faces.areas, s.kernel, out);
  maps.write_face_vectors(tmesh, s.mesh.in_input_order(out), filtered_normals);
}

/*!
  \ingroup PMP_denoising_grp

  \brief denoises `tmesh` with the intrinsic filter, keeping sharp edges and
  corners: Algorithm 1 of "Mesh denoising via generalized intrinsic filter on
  2D manifold".

  Neighbourhoods and paths are computed once on the input mesh (section 4);
  then, `number_of_iterations` times: the face normals of the current mesh are
  filtered by one pass of eq. 8 (see `intrinsic_filter_face_normals()` for the
  weights), and the vertices follow the filtered normals by
  `vertex_iterations` steps of eq. 10 (see `update_vertices_from_face_normals()`).

  The mesh is read once and written once, at the end: if an exception is
  thrown, `tmesh` and the property maps are left unchanged.

  <b>Automatic mode (the default): selection from the residual.</b> When
  \f$\sigma_s\f$, \f$\sigma_r\f$, the radius, `number_of_iterations` and
  `noise_level` are all left to it, four candidate settings run on the
  input, from a kernel that keeps sharp edges to one that is almost a
  Gaussian smoothing of the normals: \f$\sigma_s = \sigma_r\f$ = 0.5 and
  0.8 on \f$r = 3d\f$ (sharing their paths), 0.8 on \f$r = 6d\f$ and 1.4
  on \f$r = 2d\f$, each with \f$v_{iter}\f$ as given (default 2). Every
  decision is read from the input and the candidates' results, with no noise
  model and no ground truth:
  - <em>When a candidate stops.</em> After each iteration the correlation
    of the residual (input minus result) across the mesh's edges is measured:
    the sum over edges of \f$r_u \cdot r_v\f$ over the sum of
    \f$(|r_u|^2 + |r_v|^2)/2\f$. Removing noise that is independent from
    vertex to vertex leaves it slightly negative; removing shape (flattened
    curvature, rounded edges) makes it rise, as a smooth residual agrees
    across edges. A candidate keeps the iterate before the first whose
    correlation reaches \f$-0.05\f$ (at most 40 iterations). A noise-free
    mesh is usually kept as it is; a coarse irregular one may not be (the
    user manual gives the cases).
  - <em>Which candidate is kept.</em> If the flattest result has at least
    30% of its interior edges under 1 degree (piecewise flat: noise leaves
    no edge that flat, a curved surface few), only the candidates within
    0.05 of that share are compared; otherwise all are. They are compared
    where each has removed the same amount, half the smallest residual RMS
    at which a candidate stopped: the one with the lowest residual
    correlation there removed the most noise and the least shape, and is
    kept.
  - <em>Sparse noise.</em> The normal components of the kept result's
    residual are compared with 3 robust standard deviations (1.4826 times
    their median absolute value); if some lie beyond, and the residual at
    the others is smooth (correlation across
    edges of at least 0.1: shape removed from exact vertices, where noise
    removed gives 0 or less), the noise is taken for impulsive: the input is
    denoised again with the kept kernel, radius and number of iterations,
    only the flagged vertices moving (`outlier_vertices` in the report).
  - <em>Self-check.</em> Otherwise the kept result is taken for the
    noise-free surface and given the noise it removed (the normal components
    of its residual, shuffled over the vertices with a fixed seed); the kept
    kernel runs on that copy for as many iterations as the candidate did,
    and on (up to 60 iterations) while the copy keeps coming closer to the
    result. If the copy
    came closer after fewer iterations, or after more (by more than 2%),
    the input is denoised again with the largest smaller count whose angle
    is within 2% of the smallest, or else with the count of the smallest
    angle (`self_check_errors` and the stop reason `SELF_CHECK` in the
    report); a longer run goes on from the candidate's result. The kept kernel also runs on the copy with the
    candidates' other radii (2, 3 and 6 \f$d\f$, those whose paths are still
    held), walked outwards from the candidate's and in each direction only
    while each brings the copy closer than the best so far; if one brings
    the copy more than 2% closer than the candidate's radius, the input is
    denoised again with it (`self_check_radii` and
    `self_check_smallest_errors` in the report).
  The report lists every candidate with its iterations, residual RMS,
  correlation, flat share and score, and the one kept; its `noise_level` is
  the kept candidate's residual RMS relative to the mean edge length. The
  user manual gives the distribution of the result against a per-input grid
  search, the fixed mode and the classic methods on the development corpus
  (`corpus_benchmark`: the triangle meshes of CGAL's data set with 1,000 to
  60,000 faces, with Gaussian, impulsive and simulated depth-scan noise), and
  where the selection fails.

  <b>Automatic mode with some parameters given.</b> If some of those are
  given, the others are derived from the noise level, estimated from the
  mesh alone (at each vertex a quadric height field is fitted by least
  squares to the vertex and its two rings, in the frame of the vertex normal;
  the residual's standard deviation, at the lower quartile over the vertices
  and divided by 0.85, relative to the mean edge length) unless given:
  \f$\sigma_s = \sigma_r = 0.2 + \hat\sigma\f$ (clamped to [0.2, 1.4]),
  \f$r = (2 + 10\hat\sigma)\,d\f$ (clamped to \f$[3d, 4d]\f$),
  \f$v_{iter} = 2\f$, at most 100 iterations; and unless
  `number_of_iterations` is given, a stopping rule ends the iterations once
  the RMS vertex displacement from the input reaches 0.95 times the noise
  level, or once the filtered normals change by less than 0.005 degree on
  average from one iteration to the next (neither test before 20 iterations,
  unless the noise level is below 0.02: a noise-free mesh stops after one
  iteration). Explicit parameters always win; a given `number_of_iterations`
  is run exactly (the stopping rule is then off unless
  `stop_when_converged(true)`).

  <b>Fixed mode</b> (`automatic_parameters(false)`): the values of the
  paper's figure 2, `number_of_iterations` 30, `vertex_iterations` 2,
  `relative_neighbor_radius` 4, and \f$\sigma_s = \sigma_r = 0.4\f$ (chosen
  by measurement on noisy fandisk), with no stopping rule.

  \return what was done: the parameter values used, the noise level, the
  iterations run and why they stopped (`Intrinsic_denoising_report`).

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Parallel_if_available_tag`; the result does not depend on it.
  \tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to denoise; its vertex points are overwritten with the result
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{automatic_parameters}
      \cgalParamDescription{if `true`, the automatic selection chooses the setting and the number of iterations, or,
                            with some of them given, the others are derived from the noise level and the stopping
                            rule is on (see above); if `false`, the fixed defaults of the paper's figure 2}
      \cgalParamType{bool}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{noise_level}
      \cgalParamDescription{the noise level to use instead of its estimate: the standard deviation of the noise along
                            the normals, relative to the mean edge length (0: no noise)}
      \cgalParamType{double, non-negative}
      \cgalParamDefault{estimated from the mesh}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{\f$k_{iter}\f$, the number of normal filtering passes; with the stopping rule, the
                            largest number}
      \cgalParamType{unsigned int}
      \cgalParamDefault{automatic mode: at most `100`, ended by the stopping rule; fixed mode: `30`}
    \cgalParamNEnd
    \cgalParamNBegin{stop_when_converged}
      \cgalParamDescription{whether the stopping rule may end the iterations before `number_of_iterations`}
      \cgalParamType{bool}
      \cgalParamDefault{`true` in the automatic mode unless `number_of_iterations` is given, `false` otherwise}
    \cgalParamNEnd
    \cgalParamNBegin{selection_sample_faces}
      \cgalParamDescription{on a mesh of more than three times this many faces, the automatic selection (candidates,
                            sparse-noise test, self-check, second pass) runs on a sample of about this many faces, in
                            five patches grown from seed faces drawn with a fixed seed, and the setting it
                            chooses (kernel, radius, number of iterations) then runs once on the whole mesh; with
                            sparse noise the selection runs again on the whole mesh. `0`: always on the whole mesh.
                            The report gives the sample's size (`selection_sample_faces`)}
      \cgalParamType{std::size_t}
      \cgalParamDefault{`100000`}
    \cgalParamNEnd
    \cgalParamNBegin{long_run_test}
      \cgalParamDescription{for scans: when every candidate of the automatic selection stops within 3 iterations
                            (which both little noise and noise correlated between vertices, as a depth scan's, give),
                            run \f$\sigma\f$ 0.8 on 6 \f$d\f$ for 64 iterations from the input and keep that run if
                            its first iteration made at least half of its turn of the face normals (noise is used up
                            early, shape is eroded steadily); otherwise, or with `false`, the mode goes on as
                            without it. The report gives the share (`long_run_first_share`) and, if the run is
                            kept, the stop reason `LONG_RUN`. Not the default: on \cgal's data set it also keeps the
                            long run on one lightly noisy irregular mesh, which it smooths too much}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{progress_callback}
      \cgalParamDescription{called after each iteration with the number of iterations done and the largest number
                            (the stopping rule may end the run earlier); during the automatic selection, after each
                            candidate with the number of candidates run and their number (with `CGAL::Parallel_tag`,
                            where the candidates run as concurrent tasks, these calls come together once all have
                            run); always from the calling thread}
      \cgalParamType{a callable with signature `void(std::size_t, std::size_t)`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_iterations}
      \cgalParamDescription{\f$v_{iter}\f$, the vertex update steps after each pass}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`2`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_update}
      \cgalParamDescription{how the vertices follow the filtered normals after each pass:
                            `Vertex_update::PAPER` is eq. 10; `Vertex_update::LEAST_SQUARES` makes each of the
                            \f$v_{iter}\f$ steps a global one that solves for the positions fitting the filtered
                            normals over the whole mesh, with a weak pull to the positions before the step (see
                            `update_vertices_from_face_normals()` and the manual for when it helps). The fold
                            safeguard restricts both.}
      \cgalParamType{`CGAL::Polygon_mesh_processing::Vertex_update`}
      \cgalParamDefault{`Vertex_update::PAPER`}
    \cgalParamNEnd
    \cgalParamNBegin{relax_along_surface}
      \cgalParamDescription{if `true`, after the last iteration each vertex is moved along the surface only (eq. 10
                            moves it along normals only): 5 steps toward the area-weighted centroid of its faces'
                            centroids, in the directions its faces leave free (none at a corner, along the crease on
                            an edge), at most half as far from the denoised position as the denoising moved it from
                            the input; border and constrained vertices stay, the fold safeguard applies, with sparse
                            noise only the outliers move. The report's `relaxed_vertices` counts the vertices moved.}
      \cgalParamType{bool}
      \cgalParamDefault{`true` when the automatic selection runs (automatic mode, stopping rule on, none of \f$\sigma_s\f$,
                        \f$\sigma_r\f$, the radius, `number_of_iterations` or `noise_level` given), else `false`}
    \cgalParamNEnd
    \cgalParamNBegin{sigma_spatial, sigma_range, spatial_exponent, range_exponent, neighbor_radius, relative_neighbor_radius, path_strategy, use_step_length, geodesic_patch_rings, include_self_weight}
      \cgalParamDescription{as for `intrinsic_filter_face_normals()`, except that in the automatic mode the defaults
                            of \f$\sigma_s\f$, \f$\sigma_r\f$ and the radius are derived from the noise level}
    \cgalParamNEnd
    \cgalParamNBegin{face_normal_map}
      \cgalParamDescription{if given, receives the filtered normals of the last pass}
      \cgalParamType{a model of `WritablePropertyMap` with face descriptors as keys and `GeomTraits::Vector_3` as values}
      \cgalParamDefault{unused}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_constrained_map}
      \cgalParamDescription{a property map telling which vertices never move}
      \cgalParamType{a model of `ReadablePropertyMap` with vertex descriptors as keys and `bool` as values}
      \cgalParamDefault{no vertex is constrained}
    \cgalParamNEnd
    \cgalParamNBegin{prevent_folds}
      \cgalParamDescription{if `true`, each step of the vertex update is restricted so that no face comes to point
                            against its orientation before the step, against its filtered normal (if it agreed with
                            it before), or against its orientation in the input mesh: the vertices of such a face get
                            their move halved, up to 4 times, then stay in place. `false` gives eq. 10 exactly, as in
                            the paper, which "easily generates folded triangles". Faces already folded in the input
                            are not unfolded.}
      \cgalParamType{bool}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map, geom_traits}
      \cgalParamDescription{as for `intrinsic_filter_face_normals()`; the vertex point map must also be writable}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  Messy input: isolated vertices and constrained vertices never move; border
  faces have one-sided neighbourhoods; non-manifold vertices, duplicated
  vertices and several connected components are handled (components never
  share a neighbourhood); zero-area faces get a zero normal and never produce a
  NaN; the result of a mesh scaled by \f$s\f$ is the result scaled by \f$s\f$.

  \pre `tmesh` is a triangle mesh with finite coordinates, and the index maps
       number vertices and faces from 0 to \f$n-1\f$; the numeric parameters are
       positive and finite. Otherwise `std::invalid_argument` is thrown naming
       the problem, and `tmesh` and every property map are left unchanged. An
       empty mesh is left as it is.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Intrinsic_denoising_report intrinsic_denoising(TriangleMesh& tmesh,
                                               const NamedParameters& np = parameters::default_values())
{
  return internal::Denoising::intrinsic_denoising_with_options<ConcurrencyTag>(
      tmesh, internal::Denoising::read_intrinsic_options(np), np);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
