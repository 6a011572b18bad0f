// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// [HS13] He, Schaefer: "Mesh denoising via L0 minimization", ACM TOG 32(4)
// (SIGGRAPH 2013). A classic method of the paper's Table 1: the vertex
// positions minimise their distance to the input plus the L0 norm of an
// edge-based Laplacian, by alternating optimisation; the linear systems are
// solved with Eigen through CGAL's solver traits.

#ifndef CGAL_POLYGON_MESH_PROCESSING_L0_DENOISING_H
#define CGAL_POLYGON_MESH_PROCESSING_L0_DENOISING_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic/l0_minimization.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/tags.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
  \ingroup PMP_denoising_grp

  \brief denoises `tmesh` by L0 minimisation of an edge-based Laplacian, He and
  Schaefer (2013) [HS13].

  The positions \f$p\f$ minimise
  \f[ \|p - p^*\|^2 + \alpha\, \|R(p)\|^2 + \lambda\, \|D(p)\|_0 \f]
  with \f$p^*\f$ the input, \f$D(e)\f$ for every interior edge \f$e = (p_1,
  p_3)\f$ with opposite vertices \f$p_2, p_4\f$ the edge operator
  \f$(S_{134} h_2 + S_{123} h_4) / (S_{123} + S_{134})\f$ (\f$h_k\f$: the part
  of \f$p_k - p_1\f$ orthogonal to the edge; \f$S\f$: triangle areas; zero
  iff the two triangles are coplanar), and \f$R(e) = p_1 - p_2 + p_3 - p_4\f$
  a regulariser against flipped triangles. As in the paper, an auxiliary
  \f$\delta \approx D(p)\f$ is introduced with a penalty \f$\beta\|D(p) -
  \delta\|^2\f$ and the two are optimised in turn: \f$\delta_e = D_e(p)\f$ if
  \f$\|D_e(p)\|^2 \ge \lambda/\beta\f$, else 0; then \f$p\f$ solves the
  sparse linear system \f$(I + \beta D^\top D + \alpha R^\top R)\, p = p^* +
  \beta D^\top\delta\f$ (by default Eigen's `SimplicialLDLT` through
  `CGAL::Eigen_solver_traits`; see `sparse_linear_solver`). \f$\beta\f$ grows from \f$10^{-3}\f$ by a
  factor \f$\sqrt 2\f$ up to \f$10^3\f$ and \f$\alpha\f$ is halved at every
  step. The coefficients of \f$D\f$ are recomputed from the current positions
  at every step. The paper's defaults are \f$\lambda = 0.02\,\bar l^2
  \bar\gamma\f$ and \f$\alpha_0 = 0.1\,\bar\gamma\f$, with \f$\bar l\f$ the mean
  edge length and \f$\bar\gamma\f$ the mean dihedral angle of the input;
  here \f$\bar\gamma\f$ is in radians and the default factor of
  \f$\lambda\f$ is \f$0.02 \cdot 180/\pi\f$, i.e. the paper's value with
  \f$\bar\gamma\f$ in degrees (with radians, 0.02 barely smooths: measured
  E_n 28.0 -> 24.7 degrees on fandisk at \f$\sigma_E = 0.3\f$).

  Boundary and non-manifold edges have no operator. The mesh is read once and
  written once, at the end: if an exception is thrown, `tmesh` is left
  unchanged.

  \tparam ConcurrencyTag unused (the solver is sequential); for the family's
          signature
  \tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to denoise; its vertex points are overwritten with the result
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{l0_weight}
      \cgalParamDescription{the factor \f$c\f$ of \f$\lambda = c\,\bar l^2\bar\gamma\f$, \f$\bar\gamma\f$ in radians
                            (larger: fewer, sharper features, flatter result)}
      \cgalParamType{double}
      \cgalParamDefault{`0.02 * 180 / pi` (about 1.15)}
    \cgalParamNEnd
    \cgalParamNBegin{regularization_weight}
      \cgalParamDescription{the factor \f$a\f$ of \f$\alpha_0 = a\,\bar\gamma\f$}
      \cgalParamType{double}
      \cgalParamDefault{`0.1`}
    \cgalParamNEnd
    \cgalParamNBegin{sparse_linear_solver}
      \cgalParamDescription{the solver of the sparse symmetric system of each step, factorised once per step and
                            solved for the three coordinates}
      \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d`}
      \cgalParamDefault{`CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::%EigenType>>`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_constrained_map, vertex_point_map, vertex_index_map, face_index_map, geom_traits}
      \cgalParamDescription{as for `intrinsic_denoising()` (a constrained vertex keeps its input position in every
                            solve)}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `tmesh` is a triangle mesh with finite coordinates; the weights are
       positive and finite. Otherwise `std::invalid_argument` is thrown; if the
       sparse factorisation fails, `std::runtime_error`. An empty mesh is left
       as it is.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
void l0_denoising(TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>> Default_solver;
  typedef typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t, NamedParameters,
                                                       Default_solver>::type Solver;
  static const char* fname = "l0_denoising()";
  if(faces(tmesh).empty())
    return;
  const double lambda_factor =
      choose_parameter(get_parameter(np, internal_np::l0_weight), 0.02 * 180. / 3.14159265358979323846);
  const double alpha_factor = choose_parameter(get_parameter(np, internal_np::regularization_weight), 0.1);
  D::require_positive(lambda_factor, fname, "l0_weight");
  D::require_positive(alpha_factor, fname, "regularization_weight");

  D::Classic_setup<TriangleMesh, NamedParameters> setup(tmesh, np, fname);
  D::L0_minimization<Solver> minimization(
      setup.mesh, setup.fixed, choose_parameter<Default_solver>(get_parameter(np, internal_np::sparse_linear_solver)),
      fname);
  if(minimization.run(lambda_factor, alpha_factor))
    setup.write_points(tmesh);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
