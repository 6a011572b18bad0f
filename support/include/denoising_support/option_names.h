// The names of the package's enumerations as the command-line tool and the
// Python module spell them, in one table each: path strategies, vertex
// updates and the reasons the iterations stopped (with the sentence the
// tool prints for each).

#ifndef DENOISING_SUPPORT_OPTION_NAMES_H
#define DENOISING_SUPPORT_OPTION_NAMES_H

#include <CGAL/Polygon_mesh_processing/denoising_types.h>

#include <cstddef>
#include <string>

namespace denoising_support {

template <typename Enum>
struct Enum_name
{
  Enum value;
  const char* cli;         // the command-line tool's word
  const char* python;      // the Python module's word
  const char* description; // what the tool prints (may be empty)
};

typedef CGAL::Polygon_mesh_processing::Intrinsic_path_strategy Path_strategy;
typedef CGAL::Polygon_mesh_processing::Vertex_update Vertex_update_kind;
typedef CGAL::Polygon_mesh_processing::Intrinsic_stop_reason Stop_reason;

inline constexpr Enum_name<Path_strategy> path_strategy_names[] = {
    {Path_strategy::SQUARE_PATTERN, "square", "square_pattern", "square"},
    {Path_strategy::GEODESIC, "geodesic", "geodesic", "geodesic"},
    {Path_strategy::DIRECT, "direct", "direct", "direct"},
    {Path_strategy::SHORTEST_GRAPH_PATH, "graph", "shortest_graph_path", "graph"}};

inline constexpr Enum_name<Vertex_update_kind> vertex_update_names[] = {
    {Vertex_update_kind::PAPER, "paper", "paper", ""},
    {Vertex_update_kind::LEAST_SQUARES, "least-squares", "least_squares", "least-squares vertex update"}};

inline constexpr Enum_name<Stop_reason> stop_reason_names[] = {
    {Stop_reason::ITERATION_LIMIT, "iteration-limit", "iteration_limit", "iteration limit"},
    {Stop_reason::NOISE_LEVEL_REACHED, "noise-level-reached", "noise_level_reached",
     "displacement reached the noise level"},
    {Stop_reason::CONVERGED, "converged", "converged", "converged"},
    {Stop_reason::RESIDUAL_CORRELATED, "residual-correlated", "residual_correlated",
     "the residual became correlated across edges"},
    {Stop_reason::SELF_CHECK, "self-check", "self_check",
     "the self-check chose the number of iterations or the radius"},
    {Stop_reason::SECOND_PASS, "second-pass", "second_pass",
     "the second pass read the change as shape, not noise: input kept"},
    {Stop_reason::LONG_RUN, "long-run", "long_run",
     "the long-run test: every candidate stopped at once, and a long run's first iteration made most of its change, "
     "as correlated noise does"}};

// The entry of `value` in `table` (the first entry if there is none).
template <typename Enum, std::size_t N>
const Enum_name<Enum>& name_of(const Enum_name<Enum> (&table)[N], Enum value)
{
  for(const Enum_name<Enum>& e : table)
    if(e.value == value)
      return e;
  return table[0];
}

// The entry whose command-line word (`python` false) or Python word is
// `word`, or null.
template <typename Enum, std::size_t N>
const Enum_name<Enum>* find_name(const Enum_name<Enum> (&table)[N], const std::string& word, bool python)
{
  for(const Enum_name<Enum>& e : table)
    if(word == (python ? e.python : e.cli))
      return &e;
  return nullptr;
}

} // namespace denoising_support

#endif
