// Bounded readers of OBJ, PLY (ASCII and binary) and STL (ASCII and binary)
// data for the command-line program (mesh_file.h). Each reads the
// whole input (its size is known), parses it into a polygon soup and reports
// failure as a one-line message naming the line, element or facet at fault:
// every count is bounded by the data's size before anything is allocated from
// it, coordinates must be finite and indices in range.

#ifndef DENOISING_SUPPORT_MESH_READERS_H
#define DENOISING_SUPPORT_MESH_READERS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <istream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace denoising_support {

// Points and faces (indices into the points) as read.
struct Soup
{
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
};

namespace readers {

// The first face of `soup` that refers to a vertex it does not have, and that
// reference (`face`, `index`); false if every reference is in range.
inline bool first_index_out_of_range(const Soup& soup, std::size_t& face, std::size_t& index)
{
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
    for(std::size_t i : soup.polygons[f])
      if(i >= soup.points.size())
      {
        face = f;
        index = i;
        return true;
      }
  return false;
}

// At most `limit` bytes of `in`; `truncated` tells whether there were more.
inline std::string read_all(std::istream& in, std::size_t limit, bool& truncated)
{
  std::string data(limit, '\0');
  in.read(&data[0], std::streamsize(limit));
  data.resize(std::size_t(in.gcount()));
  truncated = in.peek() != std::char_traits<char>::eof();
  return data;
}

// Splits `line` at white space.
inline std::vector<std::string> words(const std::string& line)
{
  std::vector<std::string> w;
  std::size_t i = 0;
  while(i < line.size())
  {
    while(i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
      ++i;
    const std::size_t b = i;
    while(i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
      ++i;
    if(i > b)
      w.push_back(line.substr(b, i - b));
  }
  return w;
}

// The whole word as a number ("nan" and "inf" parse; callers check finiteness).
inline bool to_double(const std::string& word, double& x)
{
  if(word.empty())
    return false;
  char* end = nullptr;
  errno = 0;
  x = std::strtod(word.c_str(), &end);
  return end == word.c_str() + word.size() && errno != ERANGE;
}

inline bool to_integer(const std::string& word, long long& x)
{
  if(word.empty())
    return false;
  char* end = nullptr;
  errno = 0;
  x = std::strtoll(word.c_str(), &end, 10);
  return end == word.c_str() + word.size() && errno != ERANGE;
}

// Calls line(number from 1, text without the end of line) for every line.
template <typename Fn>
bool for_each_line(const std::string& data, const Fn& line)
{
  std::size_t number = 0, b = 0;
  while(b < data.size())
  {
    std::size_t e = data.find('\n', b);
    if(e == std::string::npos)
      e = data.size();
    std::string text = data.substr(b, e - b);
    if(!text.empty() && text.back() == '\r')
      text.pop_back();
    if(!line(++number, text))
      return false;
    b = e + 1;
  }
  return true;
}

inline bool finite(double x, double y, double z) { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }

} // namespace readers

// ---- OBJ --------------------------------------------------------------------

// Vertices ("v x y z [w]") and faces ("f a b c ...", each reference "i",
// "i/t", "i//n" or "i/t/n", negative: counted back from the last vertex read);
// every other statement (normals, texture coordinates, groups, materials,
// lines, points) is ignored.
inline std::string read_obj_soup(std::istream& in, std::size_t byte_count, Soup& soup)
{
  namespace R = readers;
  bool more = false;
  const std::string data = R::read_all(in, byte_count, more);
  std::string problem;
  std::vector<std::size_t> face_line;
  const auto at = [](std::size_t line) { return "line " + std::to_string(line) + ": "; };
  R::for_each_line(data, [&](std::size_t number, std::string text) {
    text = text.substr(0, text.find('#'));
    const std::vector<std::string> w = R::words(text);
    if(w.empty())
      return true;
    if(w[0] == "v")
    {
      double c[3];
      if(w.size() < 4 || !R::to_double(w[1], c[0]) || !R::to_double(w[2], c[1]) || !R::to_double(w[3], c[2]))
        problem = at(number) + "a vertex needs three numbers";
      else if(!R::finite(c[0], c[1], c[2]))
        problem = at(number) + "a NaN or infinite coordinate";
      else
        soup.points.emplace_back(c[0], c[1], c[2]);
    }
    else if(w[0] == "f")
    {
      if(w.size() < 4)
      {
        problem = at(number) + "a face needs at least three vertices";
        return false;
      }
      std::vector<std::size_t> polygon;
      for(std::size_t k = 1; k < w.size() && problem.empty(); ++k)
      {
        long long i = 0;
        if(!R::to_integer(w[k].substr(0, w[k].find('/')), i) || i == 0)
          problem = at(number) + "malformed vertex reference '" + w[k] + "'";
        else if(i < 0 && (long long)soup.points.size() + i < 0)
          problem = at(number) + "vertex reference " + std::to_string(i) + " before the first vertex";
        else if(i > (long long)byte_count)
          problem = at(number) + "vertex index " + std::to_string(i) + " out of range";
        else
          polygon.push_back(i < 0 ? std::size_t((long long)soup.points.size() + i) : std::size_t(i - 1));
      }
      soup.polygons.push_back(std::move(polygon));
      face_line.push_back(number);
    }
    return problem.empty();
  });
  if(!problem.empty())
    return problem;
  if(more)
    return "more data than the file size";
  std::size_t f = 0, i = 0;
  if(R::first_index_out_of_range(soup, f, i))
    return at(face_line[f]) + "vertex index " + std::to_string(i + 1) + " out of range (" +
           std::to_string(soup.points.size()) + " vertices)";
  return std::string();
}

// ---- STL --------------------------------------------------------------------

namespace readers {

// Welds the corners of STL triangles: equal coordinates, one vertex. A
// triangle with two equal corners is dropped (counted in `degenerate`).
struct Stl_welder
{
  Soup& soup;
  std::map<std::array<double, 3>, std::size_t> index;
  std::size_t degenerate = 0;

  void add(const std::array<std::array<double, 3>, 3>& corners)
  {
    std::vector<std::size_t> polygon;
    for(const auto& c : corners)
    {
      auto it = index.find(c);
      if(it == index.end())
      {
        it = index.emplace(c, soup.points.size()).first;
        soup.points.emplace_back(c[0], c[1], c[2]);
      }
      polygon.push_back(it->second);
    }
    if(polygon[0] == polygon[1] || polygon[1] == polygon[2] || polygon[0] == polygon[2])
      ++degenerate;
    else
      soup.polygons.push_back(std::move(polygon));
  }
};

inline std::uint32_t read_u32_le(const unsigned char* p)
{
  return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24);
}

inline float read_f32_le(const unsigned char* p)
{
  const std::uint32_t u = read_u32_le(p);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

} // namespace readers

// Binary STL when the size is exactly 84 + 50 n bytes for the n of its
// header, ASCII otherwise ("solid", then "vertex x y z" lines, three a
// "facet ... endfacet"). Corners are welded by equal coordinates; triangles
// with two equal corners are dropped, their number added to `dropped`.
inline std::string read_stl_soup(std::istream& in, std::size_t byte_count, Soup& soup, std::size_t& dropped)
{
  namespace R = readers;
  bool more = false;
  const std::string data = R::read_all(in, byte_count, more);
  if(more)
    return "more data than the file size";
  R::Stl_welder welder{soup, {}, 0};
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  if(data.size() >= 84 && (data.size() - 84) % 50 == 0 && R::read_u32_le(bytes + 80) == (data.size() - 84) / 50)
  {
    const std::size_t n = (data.size() - 84) / 50;
    for(std::size_t t = 0; t < n; ++t)
    {
      const unsigned char* r = bytes + 84 + 50 * t + 12; // after the normal
      std::array<std::array<double, 3>, 3> corners;
      for(int c = 0; c < 3; ++c)
        for(int k = 0; k < 3; ++k)
          corners[c][k] = double(R::read_f32_le(r + 12 * c + 4 * k));
      for(const auto& c : corners)
        if(!R::finite(c[0], c[1], c[2]))
          return "triangle " + std::to_string(t) + " has a NaN or infinite coordinate";
      welder.add(corners);
    }
  }
  else
  {
    const std::size_t first = data.find_first_not_of(" \t\r\n");
    if(first == std::string::npos || data.compare(first, 5, "solid") != 0)
      return "not an STL file (neither 'solid' nor a binary size of 84 + 50 n bytes)";
    std::string problem;
    std::array<std::array<double, 3>, 3> corners;
    std::size_t in_facet = 0, facet = 0;
    bool open = false;
    R::for_each_line(data, [&](std::size_t number, const std::string& text) {
      const std::vector<std::string> w = R::words(text);
      const std::string at = "line " + std::to_string(number) + ": ";
      if(w.empty())
        return true;
      if(w[0] == "facet")
      {
        if(open)
          problem = at + "facet inside a facet";
        open = true;
        in_facet = 0;
      }
      else if(w[0] == "vertex")
      {
        double c[3];
        if(!open || in_facet >= 3)
          problem = at + "vertex outside a facet, or a fourth vertex";
        else if(w.size() != 4 || !R::to_double(w[1], c[0]) || !R::to_double(w[2], c[1]) || !R::to_double(w[3], c[2]))
          problem = at + "a vertex needs three numbers";
        else if(!R::finite(c[0], c[1], c[2]))
          problem = at + "a NaN or infinite coordinate";
        else
          corners[in_facet++] = {c[0], c[1], c[2]};
      }
      else if(w[0] == "endfacet")
      {
        if(!open || in_facet != 3)
          problem = at + "facet " + std::to_string(facet) + " has " + std::to_string(in_facet) + " vertices, not 3";
        else
          welder.add(corners);
        open = false;
        ++facet;
      }
      return problem.empty();
    });
    if(!problem.empty())
      return problem;
    if(open)
      return "truncated: facet " + std::to_string(facet) + " has no 'endfacet'";
  }
  dropped = welder.degenerate;
  return std::string();
}

// ---- PLY --------------------------------------------------------------------

namespace readers {

enum class Ply_type
{
  INT8,
  UINT8,
  INT16,
  UINT16,
  INT32,
  UINT32,
  FLOAT32,
  FLOAT64,
  NONE
};

inline Ply_type ply_type(const std::string& name)
{
  static const std::pair<const char*, Ply_type> names[] = {
      {"char", Ply_type::INT8},      {"int8", Ply_type::INT8},       {"uchar", Ply_type::UINT8},
      {"uint8", Ply_type::UINT8},    {"short", Ply_type::INT16},     {"int16", Ply_type::INT16},
      {"ushort", Ply_type::UINT16},  {"uint16", Ply_type::UINT16},   {"int", Ply_type::INT32},
      {"int32", Ply_type::INT32},    {"uint", Ply_type::UINT32},     {"uint32", Ply_type::UINT32},
      {"float", Ply_type::FLOAT32},  {"float32", Ply_type::FLOAT32}, {"double", Ply_type::FLOAT64},
      {"float64", Ply_type::FLOAT64}};
  for(const auto& n : names)
    if(name == n.first)
      return n.second;
  return Ply_type::NONE;
}

inline std::size_t ply_size(Ply_type t)
{
  switch(t)
  {
  case Ply_type::INT8:
  case Ply_type::UINT8:
    return 1;
  case Ply_type::INT16:
  case Ply_type::UINT16:
    return 2;
  case Ply_type::INT32:
  case Ply_type::UINT32:
  case Ply_type::FLOAT32:
    return 4;
  case Ply_type::FLOAT64:
    return 8;
  default:
    return 0;
  }
}

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::NONE;       // of the value, or of a list's entries
  Ply_type count_type = Ply_type::NONE; // of a list's count; NONE: a scalar
};

struct Ply_element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties;
};

// Reads values one after the other from the body of a PLY file, in ASCII
// (white-space separated words) or binary (either byte order); `fail` tells
// why a read failed.
struct Ply_body
{
  const std::string& data;
  std::size_t pos;
  int format; // 0 ASCII, 1 binary little endian, 2 binary big endian
  std::string fail;

  bool next(Ply_type t, double& x) { return format == 0 ? next_ascii(x) : next_binary(t, x); }

  // The next word of an ASCII body as a number.
  bool next_ascii(double& x)
  {
    while(pos < data.size() && std::isspace(static_cast<unsigned char>(data[pos])))
      ++pos;
    const std::size_t b = pos;
    while(pos < data.size() && !std::isspace(static_cast<unsigned char>(data[pos])))
      ++pos;
    if(b == pos)
      return (fail = "truncated"), false;
    if(!to_double(data.substr(b, pos - b), x))
      return (fail = "not a number: '" + data.substr(b, (std::min)(pos - b, std::size_t(20))) + "'"), false;
    return true;
  }

  // The next value of type `t` of a binary body, in its byte order.
  bool next_binary(Ply_type t, double& x)
  {
    const std::size_t n = ply_size(t);
    if(data.size() - pos < n)
      return (fail = "truncated"), false;
    unsigned char b[8];
    std::memcpy(b, data.data() + pos, n);
    pos += n;
    const bool little = format == 1;
    const std::uint16_t one = 1;
    unsigned char host_little;
    std::memcpy(&host_little, &one, 1);
    if(bool(host_little) != little)
      for(std::size_t i = 0; i < n / 2; ++i)
        std::swap(b[i], b[n - 1 - i]);
    switch(t)
    {
    case Ply_type::INT8:
      return (x = value_as<std::int8_t>(b)), true;
    case Ply_type::UINT8:
      return (x = value_as<std::uint8_t>(b)), true;
    case Ply_type::INT16:
      return (x = value_as<std::int16_t>(b)), true;
    case Ply_type::UINT16:
      return (x = value_as<std::uint16_t>(b)), true;
    case Ply_type::INT32:
      return (x = value_as<std::int32_t>(b)), true;
    case Ply_type::UINT32:
      return (x = value_as<std::uint32_t>(b)), true;
    case Ply_type::FLOAT32:
      return (x = value_as<float>(b)), true;
    case Ply_type::FLOAT64:
      return (x = value_as<double>(b)), true;
    default:
      return (fail = "unknown type"), false;
    }
  }

  // The value of type T whose bytes (host order) start at `b`.
  template <typename T>
  static double value_as(const unsigned char* b)
  {
    T v;
    std::memcpy(&v, b, sizeof(T));
    return double(v);
  }
};

// The header of the PLY text `data` up to `end` (where end_header starts),
// whose body starts at `body`: the format (0 ASCII, 1 little-endian, 2
// big-endian) and the elements with their properties. A problem, or empty.
inline std::string read_ply_header(const std::string& data, std::size_t end, std::size_t body, int& format,
                                   std::vector<Ply_element>& elements)
{
  std::string problem;
  for_each_line(data.substr(0, end), [&](std::size_t number, const std::string& text) {
    const std::vector<std::string> w = words(text);
    const std::string at = "header line " + std::to_string(number) + ": ";
    if(w.empty() || w[0] == "comment" || w[0] == "obj_info" || w[0] == "ply")
      return true;
    if(w[0] == "format")
    {
      if(w.size() < 2 || (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
        problem = at + "unknown format";
      else
        format = w[1] == "ascii" ? 0 : w[1] == "binary_little_endian" ? 1 : 2;
    }
    else if(w[0] == "element")
    {
      long long count = -1;
      if(w.size() != 3 || !to_integer(w[2], count) || count < 0)
        problem = at + "malformed element";
      else if((unsigned long long)count > data.size() - body)
        problem = at + "element " + w[1] + " announces " + w[2] + " items, more than the " +
                  std::to_string(data.size() - body) + " bytes of data can hold";
      else
        elements.push_back({w[1], std::size_t(count), {}});
    }
    else if(w[0] == "property")
    {
      Ply_property p;
      if(elements.empty())
        problem = at + "property before any element";
      else if(w.size() == 3 && (p.type = ply_type(w[1])) != Ply_type::NONE)
        p.name = w[2];
      else if(w.size() == 5 && w[1] == "list" && (p.count_type = ply_type(w[2])) != Ply_type::NONE &&
              (p.type = ply_type(w[3])) != Ply_type::NONE)
        p.name = w[4];
      else
        problem = at + "malformed property";
      if(problem.empty())
        elements.back().properties.push_back(p);
    }
    else
      problem = at + "unknown keyword '" + w[0] + "'";
    return problem.empty();
  });
  if(!problem.empty())
    return problem;
  if(format < 0)
    return "the PLY header has no format line";
  return std::string();
}

// The items of element `e` from `reader` (the body of `data`, a file of
// `byte_count` bytes): vertices and faces go to `soup`, other elements are
// skipped. A problem, or empty.
inline std::string read_ply_element(Ply_body& reader, const Ply_element& e, const std::string& data,
                                    std::size_t byte_count, Soup& soup)
{
  const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
  int xyz[3] = {-1, -1, -1};
  int indices = -1;
  for(std::size_t k = 0; k < e.properties.size(); ++k)
  {
    const Ply_property& p = e.properties[k];
    for(int c = 0; c < 3; ++c)
      if(is_vertex && p.count_type == Ply_type::NONE && p.name == std::string(1, char('x' + c)))
        xyz[c] = int(k);
    if(is_face && p.count_type != Ply_type::NONE && (p.name == "vertex_indices" || p.name == "vertex_index"))
      indices = int(k);
  }
  if(is_vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
    return "the vertex element has no x, y and z";
  if(is_face && indices < 0)
    return "the face element has no vertex_indices list";
  for(std::size_t i = 0; i < e.count; ++i)
  {
    double c[3] = {0., 0., 0.};
    std::vector<std::size_t> polygon;
    const std::string item = e.name + " " + std::to_string(i);
    for(std::size_t k = 0; k < e.properties.size(); ++k)
    {
      const Ply_property& p = e.properties[k];
      double x = 0.;
      if(p.count_type == Ply_type::NONE)
      {
        if(!reader.next(p.type, x))
          return item + ": " + reader.fail;
        for(int d = 0; d < 3; ++d)
          if(int(k) == xyz[d])
            c[d] = x;
        continue;
      }
      double count = 0.;
      if(!reader.next(p.count_type, count))
        return item + ": " + reader.fail;
      // each entry takes at least one byte: a count beyond the data left is malformed
      if(!(count >= 0.) || count != std::floor(count) || count > double(data.size() - reader.pos))
        return item + ": malformed list size";
      for(std::size_t j = 0; j < std::size_t(count); ++j)
      {
        if(!reader.next(p.type, x))
          return item + ": " + reader.fail;
        if(int(k) == indices)
        {
          if(!(x >= 0.) || x != std::floor(x) || x >= double(byte_count))
            return item + ": vertex index " + std::to_string(x) + " out of range";
          polygon.push_back(std::size_t(x));
        }
      }
    }
    if(is_vertex)
    {
      if(!finite(c[0], c[1], c[2]))
        return item + ": a NaN or infinite coordinate";
      soup.points.emplace_back(c[0], c[1], c[2]);
    }
    if(is_face)
    {
      if(polygon.size() < 3)
        return item + ": fewer than three vertices";
      soup.polygons.push_back(std::move(polygon));
    }
  }
  return std::string();
}

} // namespace readers

// The elements "vertex" (properties x, y, z; others skipped) and "face" (a
// list property vertex_indices or vertex_index; others skipped); other
// elements are read and skipped. ASCII and binary, either byte order.
inline std::string read_ply_soup(std::istream& in, std::size_t byte_count, Soup& soup)
{
  namespace R = readers;
  bool more = false;
  const std::string data = R::read_all(in, byte_count, more);
  if(more)
    return "more data than the file size";
  if(data.compare(0, 3, "ply") != 0)
    return "not a PLY file (no 'ply' magic)";
  std::size_t end = data.find("end_header");
  if(end == std::string::npos)
    return "the PLY header has no 'end_header'";
  std::size_t body = data.find('\n', end);
  if(body == std::string::npos)
    return "the PLY header has no end of line after 'end_header'";
  ++body;
  int format = -1;
  std::vector<R::Ply_element> elements;
  std::string problem = R::read_ply_header(data, end, body, format, elements);
  if(!problem.empty())
    return problem;
  R::Ply_body reader{data, body, format, std::string()};
  for(const R::Ply_element& e : elements)
  {
    problem = R::read_ply_element(reader, e, data, byte_count, soup);
    if(!problem.empty())
      return problem;
  }
  std::size_t f = 0, i = 0;
  if(R::first_index_out_of_range(soup, f, i))
    return "face " + std::to_string(f) + ": vertex index " + std::to_string(i) + " out of range (" +
           std::to_string(soup.points.size()) + " vertices)";
  return std::string();
}

} // namespace denoising_support

#endif
