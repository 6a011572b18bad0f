// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The internals of intrinsic_filter(), the generalized filter of section
// 3.1 on any signal: signals as flat arrays of doubles (Signal_traits), the
// built-in choices of phi and psi, and the weighted average of eq. 1.

#ifndef CGAL_PMP_INTERNAL_DENOISING_GENERAL_FILTER_H
#define CGAL_PMP_INTERNAL_DENOISING_GENERAL_FILTER_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/intrinsic_setup.h>

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
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
