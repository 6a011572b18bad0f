// The denoising package's additions to CGAL's named-parameter list, in the
// form CGAL_add_named_parameter(tag_type, tag_value, function_name).
// Included (several times, no guard) by
// <CGAL/STL_Extension/internal/parameters_interface.h> of this package.
// Parameters CGAL already has and whose meaning is the same are reused
// instead (number_of_iterations, neighbor_radius, face_normal_map,
// vertex_is_constrained_map, random_seed, geom_traits, vertex_point_map,
// vertex_index_map, face_index_map).

// one macro call per line, without semicolons
// clang-format off

// sigma_s and sigma_r of the kernels g(d^s; sigma_s) g(d^r; sigma_r), eq. 8
CGAL_add_named_parameter(sigma_spatial_t, sigma_spatial, sigma_spatial)
CGAL_add_named_parameter(sigma_range_t, sigma_range, sigma_range)
// exponents n (for d^s) and m (for d^r) of eq. 9
CGAL_add_named_parameter(spatial_exponent_t, spatial_exponent, spatial_exponent)
CGAL_add_named_parameter(range_exponent_t, range_exponent, range_exponent)
// v_iter of Algorithm 1: iterations of the vertex update (eq. 10) per normal pass
CGAL_add_named_parameter(vertex_iterations_t, vertex_iterations, vertex_iterations)
// neighbourhood radius as a multiple of the mean distance between centroids of
// edge-adjacent faces (used unless neighbor_radius gives it absolutely)
CGAL_add_named_parameter(relative_neighbor_radius_t, relative_neighbor_radius, relative_neighbor_radius)
// whether face i's own normal takes part in its average (weight A_i)
CGAL_add_named_parameter(include_self_weight_t, include_self_weight, include_self_weight)
// how the path from face i to neighbour j is chosen (Intrinsic_path_strategy)
CGAL_add_named_parameter(path_strategy_t, path_strategy, path_strategy)
// eq. 4's step length ||q_{x+1} - q_x|| in the path sums (off: eq. 8-9)
CGAL_add_named_parameter(use_step_length_t, use_step_length, use_step_length)
// the signals phi (for d^s) and psi (for d^r) of the general filter, section 3.1
CGAL_add_named_parameter(spatial_signal_t, spatial_signal, spatial_signal)
CGAL_add_named_parameter(range_signal_t, range_signal, range_signal)
// whether the general filter scales each result to unit length (normals)
CGAL_add_named_parameter(unit_length_result_t, unit_length_result, unit_length_result)
// GEODESIC paths: rings of faces added around the neighbourhood patch
CGAL_add_named_parameter(geodesic_patch_rings_t, geodesic_patch_rings, geodesic_patch_rings)
// whether the vertex update (eq. 10) is restricted so that no face folds
// (default true; false reproduces the paper's update exactly)
CGAL_add_named_parameter(prevent_folds_t, prevent_folds, prevent_folds)
// how the vertices follow the filtered normals (Vertex_update)
CGAL_add_named_parameter(vertex_update_t, vertex_update, vertex_update)
// whether the result is relaxed along the surface after the last iteration
// (default: when the automatic selection runs)
CGAL_add_named_parameter(relax_along_surface_t, relax_along_surface, relax_along_surface)
// classic methods
// T of Sun et al. 2007: faces whose normals make n_i . n_j <= T get no weight
CGAL_add_named_parameter(normal_threshold_t, normal_threshold, normal_threshold)
// normal filtering over the faces sharing a vertex (true) or an edge (false) with face i
CGAL_add_named_parameter(use_vertex_neighborhood_t, use_vertex_neighborhood, use_vertex_neighborhood)
// He and Schaefer 2013: lambda = l0_weight * (mean edge length)^2 * (mean dihedral angle)
CGAL_add_named_parameter(l0_weight_t, l0_weight, l0_weight)
// He and Schaefer 2013: initial alpha = regularization_weight * (mean dihedral angle)
CGAL_add_named_parameter(regularization_weight_t, regularization_weight, regularization_weight)
// automatic mode of intrinsic_denoising()
// whether the parameters not given are derived from the mesh (default true)
CGAL_add_named_parameter(automatic_parameters_t, automatic_parameters, automatic_parameters)
// the noise level in units of the mean edge length, instead of its estimate
CGAL_add_named_parameter(noise_level_t, noise_level, noise_level)
// whether the iterations stop by the no-ground-truth rule (default: unless
// number_of_iterations is given or automatic_parameters is false)
CGAL_add_named_parameter(stop_when_converged_t, stop_when_converged, stop_when_converged)
// the automatic selection's sample size on big meshes (0: the whole mesh)
CGAL_add_named_parameter(selection_sample_faces_t, selection_sample_faces, selection_sample_faces)
// whether the automatic selection may keep a long run when every candidate
// stops at once (the long-run test; default false)
CGAL_add_named_parameter(long_run_test_t, long_run_test, long_run_test)
// a callable (iterations done, maximum iterations) called after each iteration
CGAL_add_named_parameter(progress_callback_t, progress_callback, progress_callback)

