// The mesh-file entry of the command-line program, shared with the fuzz
// harness (fuzz/Polygon_mesh_processing/fuzz_mesh_file.cpp) and the tests: read a mesh from bytes or
// a file, validate it, denoise it, write the result atomically. Every function
// reports failure as a one-line message instead of crashing.

#ifndef DENOISING_SUPPORT_MESH_FILE_H
#define DENOISING_SUPPORT_MESH_FILE_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include <denoising_support/mesh_readers.h>
#include <denoising_support/option_names.h>

#include <CGAL/IO/OFF/File_scanner_OFF.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

namespace denoising_support {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

// Lower-case extension of `path` without the dot ("" if none).
inline std::string extension(const std::string& path)
{
  const std::string name = std::filesystem::path(path).filename().string();
  const std::size_t dot = name.find_last_of('.');
  std::string ext = dot == std::string::npos ? std::string() : name.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Checks what the denoiser needs: a non-empty triangle mesh with finite
// coordinates and valid connectivity. Returns "" or a one-line message.
inline std::string validate(const Mesh& mesh)
{
  if(num_faces(mesh) == 0)
    return "the mesh has no face";
  if(!mesh.is_valid(false))
    return "the mesh has an invalid connectivity";
  if(!CGAL::is_triangle_mesh(mesh))
    return "the mesh has a face that is not a triangle (triangulate it first)";
  for(auto v : vertices(mesh))
  {
    const K::Point_3& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return "the mesh has a NaN or infinite coordinate";
  }
  return std::string();
}

// Whether `polygons` (vertex indices under `vertex_count`, at least 3 per
// polygon, none twice in a polygon) is a consistently oriented manifold
// surface, the test of CGAL's is_polygon_soup_a_polygon_mesh() on such
// polygons, in time and memory linear in the soup: no directed edge appears
// twice (an edge has at most two polygons, oriented oppositely), and the
// polygons around each vertex form one fan, open or closed. The directed
// edges are grouped by their first vertex (a counting sort); around vertex
// u, the outgoing edge (u, v) of a polygon is followed by the outgoing edge
// (u, w) of the polygon across (w, u), w the vertex before u in the first
// polygon. These links form chains and cycles (no edge is followed twice, as
// (w, u) is in one polygon only); a chain starts at an edge (u, v) with no
// opposite (v, u), and one fan is one chain or one cycle through all of
// u's outgoing edges.
inline bool is_oriented_manifold_soup(const std::vector<std::vector<std::size_t>>& polygons, std::size_t vertex_count)
{
  if(vertex_count >= (std::size_t(1) << 31))
    return CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
  struct Outgoing // the directed edge (u, to) of a polygon, grouped under u
  {
    std::uint32_t to, before; // before: the vertex before u in the polygon
  };
  std::vector<std::size_t> offset(vertex_count + 1, 0);
  for(const auto& polygon : polygons)
    for(std::size_t u : polygon)
      ++offset[u + 1];
  for(std::size_t v = 0; v < vertex_count; ++v)
    offset[v + 1] += offset[v];
  std::vector<Outgoing> edges(offset[vertex_count]);
  {
    std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
    for(const auto& polygon : polygons)
    {
      const std::size_t n = polygon.size();
      for(std::size_t j = 0; j < n; ++j)
        edges[fill[polygon[j]]++] = {std::uint32_t(polygon[(j + 1) % n]), std::uint32_t(polygon[(j + n - 1) % n])};
    }
  }
  // each vertex's outgoing edges sorted by their end (a handful each), no end twice
  for(std::size_t u = 0; u < vertex_count; ++u)
  {
    const auto b = edges.begin() + std::ptrdiff_t(offset[u]), e = edges.begin() + std::ptrdiff_t(offset[u + 1]);
    std::sort(b, e, [](const Outgoing& x, const Outgoing& y) { return x.to < y.to; });
    for(auto it = b; it != e && it + 1 != e; ++it)
      if(it->to == (it + 1)->to)
        return false;
  }
  // the index of the directed edge (u, to), or none
  constexpr std::size_t none = std::size_t(-1);
  auto find = [&](std::size_t u, std::uint32_t to) -> std::size_t {
    const auto b = edges.begin() + std::ptrdiff_t(offset[u]), e = edges.begin() + std::ptrdiff_t(offset[u + 1]);
    const auto it = std::lower_bound(b, e, to, [](const Outgoing& x, std::uint32_t t) { return x.to < t; });
    return it != e && it->to == to ? std::size_t(it - edges.begin()) : none;
  };
  std::vector<std::size_t> link;
  for(std::size_t u = 0; u < vertex_count; ++u)
  {
    const std::size_t begin = offset[u], end = offset[u + 1];
    if(begin == end)
      continue;
    link.assign(end - begin, none);
    std::size_t starts = 0, start = begin;
    for(std::size_t i = begin; i < end; ++i)
    {
      link[i - begin] = find(u, edges[i].before);
      if(find(edges[i].to, std::uint32_t(u)) == none)
      {
        ++starts;
        start = i;
      }
    }
    if(starts > 1)
      return false;
    std::size_t visited = 0;
    for(std::size_t i = start; i != none && visited <= end - begin; i = link[i - begin])
    {
      ++visited;
      if(starts == 0 && link[i - begin] == start)
        break;
    }
    if(visited != end - begin)
      return false;
  }
  return true;
}

// Builds `mesh` (empty) from a soup that passed is_oriented_manifold_soup(),
// with the same vertex, edge, halfedge and face indices and the same links
// as CGAL's polygon_soup_to_polygon_mesh() gives, faces added one by one
// with Euler::add_face(), but in one pass over the polygons with a table of
// directed edges instead of a search around each vertex per edge: the
// vertices in soup order; the edges in the order the polygons first use
// them, halfedge 2e running as in that polygon; each face's halfedge the
// one from its last corner to its first; on a border the border halfedges
// linked around it, and each vertex's halfedge its incoming border halfedge
// if it has one, else its incoming halfedge in the last face around it
// (where add_face() leaves it when that face closes the vertex's fan).
inline void build_oriented_manifold_mesh(const std::vector<K::Point_3>& points,
                                         const std::vector<std::vector<std::size_t>>& polygons, Mesh& mesh)
{
  typedef Mesh::Vertex_index V;
  typedef Mesh::Halfedge_index H;
  const std::size_t nv = points.size();
  constexpr std::uint32_t none = std::uint32_t(-1);
  // each vertex's outgoing directed edges: their end, then their halfedge once made
  std::vector<std::size_t> offset(nv + 1, 0);
  std::size_t corners = 0;
  for(const auto& polygon : polygons)
  {
    corners += polygon.size();
    for(std::size_t u : polygon)
      ++offset[u + 1];
  }
  for(std::size_t v = 0; v < nv; ++v)
    offset[v + 1] += offset[v];
  std::vector<std::uint32_t> end(corners), made(corners, none);
  {
    std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
    for(const auto& polygon : polygons)
      for(std::size_t j = 0, n = polygon.size(); j < n; ++j)
        end[fill[polygon[j]]++] = std::uint32_t(polygon[(j + 1) % n]);
  }
  const auto find = [&](std::size_t u, std::size_t v) -> std::size_t {
    for(std::size_t i = offset[u]; i < offset[u + 1]; ++i)
      if(end[i] == v)
        return i;
    return std::size_t(-1);
  };
  // at most one edge per corner: reserving more than is used touches no memory
  mesh.reserve(Mesh::size_type(nv), Mesh::size_type(corners), Mesh::size_type(polygons.size()));
  for(const K::Point_3& p : points)
    mesh.add_vertex(p);
  std::vector<std::uint32_t> incoming(nv, none);
  std::vector<H> h;
  for(const auto& polygon : polygons)
  {
    const std::size_t n = polygon.size();
    h.resize(n);
    for(std::size_t j = 0; j < n; ++j)
    {
      const std::size_t u = polygon[j], v = polygon[(j + 1) % n];
      const std::size_t back = find(v, u);
      h[j] = back != std::size_t(-1) && made[back] != none
                 ? mesh.opposite(H(made[back]))
                 : mesh.add_edge(V(Mesh::size_type(u)), V(Mesh::size_type(v)));
      made[find(u, v)] = std::uint32_t(h[j]);
    }
    const Mesh::Face_index f = mesh.add_face();
    mesh.set_halfedge(f, h[n - 1]);
    for(std::size_t j = 0; j < n; ++j)
    {
      mesh.set_face(h[j], f);
      mesh.set_next(h[j], h[(j + 1) % n]);
      incoming[polygon[(j + 1) % n]] = std::uint32_t(h[j]);
    }
  }
  // the border: one outgoing and one incoming border halfedge per border vertex
  std::vector<std::uint32_t> outgoing_border(nv, none);
  for(H b : halfedges(mesh))
    if(mesh.is_border(b))
      outgoing_border[std::size_t(mesh.source(b))] = std::uint32_t(b);
  for(H b : halfedges(mesh))
    if(mesh.is_border(b))
    {
      mesh.set_next(b, H(outgoing_border[std::size_t(mesh.target(b))]));
      incoming[std::size_t(mesh.target(b))] = std::uint32_t(b);
    }
  for(std::size_t v = 0; v < nv; ++v)
    if(incoming[v] != none)
      mesh.set_halfedge(V(Mesh::size_type(v)), H(incoming[v]));
}

// The mesh of a polygon soup read from a file: a face may not use a vertex
// twice; a soup that is not a manifold surface is repaired by
// orient_polygon_soup() (vertices are duplicated on non-manifold edges and
// vertices; the faces stay). Returns "" or a one-line message.
inline std::string soup_to_mesh(Soup& soup, Mesh& mesh)
{
  for(std::size_t i = 0; i < soup.polygons.size(); ++i)
  {
    const std::vector<std::size_t>& polygon = soup.polygons[i];
    for(std::size_t j = 0; j < polygon.size(); ++j)
      for(std::size_t k = j + 1; k < polygon.size(); ++k)
        if(polygon[j] == polygon[k])
          return "face " + std::to_string(i) + " uses a vertex twice";
  }
  namespace PMP = CGAL::Polygon_mesh_processing;
  for(std::size_t i = 0; i < soup.polygons.size(); ++i)
    if(soup.polygons[i].size() < 3)
      return "face " + std::to_string(i) + " has fewer than 3 vertices";
  if(!is_oriented_manifold_soup(soup.polygons, soup.points.size()))
  {
    PMP::orient_polygon_soup(soup.points, soup.polygons);
    if(!is_oriented_manifold_soup(soup.polygons, soup.points.size()))
      return "the faces do not form a surface, even after orient_polygon_soup()";
  }
  std::size_t corners = 0;
  for(const auto& polygon : soup.polygons)
    corners += polygon.size();
  if(mesh.num_vertices() == 0 && mesh.num_edges() == 0 && mesh.num_faces() == 0 && corners < (std::size_t(1) << 31))
    build_oriented_manifold_mesh(soup.points, soup.polygons, mesh);
  else // appended to a mesh, or too big for 32-bit halfedge indices
    PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  return std::string();
}

namespace off_text {

// The text after the OFF header, read line by line as CGAL's OFF scanner
// reads it (skip white space and '#' comment lines, take the rest of the
// line, drop what follows a '#', read its numbers up to the first that is
// not one), from a buffer: the stream's per-line strings and string streams
// cost about 8 s for a million faces.
class Lines
{
public:
  explicit Lines(std::string text) : text_(std::move(text)) {}

  // The next line as CGAL's skip_comment_OFF() then std::getline() give it;
  // false at the end of the text.
  bool next(std::string_view& line)
  {
    const std::size_t n = text_.size();
    for(;;)
    {
      while(pos_ < n && std::isspace(static_cast<unsigned char>(text_[pos_])))
        ++pos_;
      if(pos_ < n && text_[pos_] == '#')
      {
        const std::size_t eol = text_.find('\n', pos_);
        pos_ = eol == std::string::npos ? n : eol + 1;
        continue;
      }
      break;
    }
    if(pos_ >= n)
      return false;
    const std::size_t eol = std::min(text_.find('\n', pos_), n);
    line = std::string_view(text_).substr(pos_, eol - pos_);
    pos_ = eol < n ? eol + 1 : n;
    const std::size_t hash = line.find('#');
    if(hash != std::string_view::npos)
      line = line.substr(0, hash);
    return true;
  }

  // The lines left that hold something but a comment.
  std::size_t remaining_lines()
  {
    std::size_t count = 0;
    std::string_view line;
    while(next(line))
      count += line.find_first_not_of(" \t\r\v\f") != std::string_view::npos;
    return count;
  }

private:
  std::string text_;
  std::size_t pos_ = 0;
};

// The numbers of `line` up to the first word that is not one, into
// `entries`, as `std::istringstream >> CGAL::IO::iformat(double)` reads
// them. Plain decimal words go through std::from_chars; a line with any
// other word (a sign '+', "inf", an exponent out of range, ...) is read by
// the string stream itself, so that both agree on every line.
inline void numbers(std::string_view line, std::vector<double>& entries)
{
  entries.clear();
  const char* p = line.data();
  const char* const end = p + line.size();
  auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  for(;;)
  {
    while(p < end && space(*p))
      ++p;
    if(p == end)
      return;
    const char c = *p;
    auto digit = [](char x) { return x >= '0' && x <= '9'; };
    // from_chars would also read "-inf" and "-nan", which the stream does not
    const bool plain = digit(c) || c == '.' || (c == '-' && p + 1 < end && (digit(p[1]) || p[1] == '.'));
    double d = 0.;
    const auto r = plain ? std::from_chars(p, end, d) : std::from_chars_result{p, std::errc::invalid_argument};
    if(plain && r.ec == std::errc() && (r.ptr == end || space(*r.ptr)))
    {
      entries.push_back(d);
      p = r.ptr;
      continue;
    }
    // anything else: the stream decides, for the whole line
    entries.clear();
    std::istringstream words{std::string(line)};
    while(words >> CGAL::IO::iformat(d))
      entries.push_back(d);
    return;
  }
}

// The polygon of face `i` from the numbers of its line (its size, then its
// vertex indices, each under `nv`; what follows is ignored), into
// `polygon`. Returns "" or a one-line message.
inline std::string face(const std::vector<double>& entries, std::size_t nv, std::size_t i,
                        std::vector<std::size_t>& polygon)
{
  auto is_index = [](double x, std::size_t bound) { return x >= 0. && x < double(bound) && x == std::floor(x); };
  if(entries.empty() || !is_index(entries[0], nv + 1) || entries[0] < 3. ||
     entries.size() < 1 + static_cast<std::size_t>(entries[0]))
    return "malformed face " + std::to_string(i);
  polygon.resize(static_cast<std::size_t>(entries[0]));
  for(std::size_t j = 0; j < polygon.size(); ++j)
  {
    if(!is_index(entries[j + 1], nv))
      return "face " + std::to_string(i) + " has a vertex index out of range";
    polygon[j] = static_cast<std::size_t>(entries[j + 1]);
  }
  return std::string();
}

// The warning for `extra` lines after the `nf` faces of the header.
inline std::string extra_lines_warning(std::size_t extra, std::size_t nf)
{
  return std::to_string(extra) + " line" + (extra > 1 ? "s" : "") + " after the " + std::to_string(nf) +
         " faces the OFF header announces, ignored";
}

} // namespace off_text

// The vertices and faces of a plain text OFF file ("OFF", three coordinates
// a vertex) after its header, with the checks of read_off(), then
// soup_to_mesh().
inline std::string read_plain_off_body(std::istream& in, std::size_t nv, std::size_t nf, Mesh& mesh,
                                       std::vector<std::string>* warnings)
{
  // the rest of the data in one read where the stream can say its size
  std::string text;
  const std::streampos here = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streampos last = in.tellg();
  if(here != std::streampos(-1) && last != std::streampos(-1) && last >= here)
  {
    in.seekg(here);
    text.resize(std::size_t(last - here));
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in.gcount()));
  }
  else
  {
    in.clear();
    std::ostringstream rest;
    rest << in.rdbuf();
    text = std::move(rest).str();
  }
  off_text::Lines lines{std::move(text)};
  std::string_view line;
  std::vector<double> entries;
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  points.reserve(nv);
  polygons.reserve(nf);
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(!lines.next(line))
      return "truncated or malformed vertex " + std::to_string(i);
    off_text::numbers(line, entries);
    if(entries.size() < 3)
      return "truncated or malformed vertex " + std::to_string(i);
    const double x = entries[0], y = entries[1], z = entries[2];
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      return "vertex " + std::to_string(i) + " has a NaN or infinite coordinate";
    points.emplace_back(x, y, z);
  }
  for(std::size_t i = 0; i < nf; ++i)
  {
    if(!lines.next(line))
      return "truncated face " + std::to_string(i);
    off_text::numbers(line, entries);
    std::vector<std::size_t> polygon;
    if(std::string problem = off_text::face(entries, nv, i, polygon); !problem.empty())
      return problem;
    polygons.push_back(std::move(polygon));
  }
  if(warnings)
    if(const std::size_t extra = lines.remaining_lines(); extra > 0)
      warnings->push_back(off_text::extra_lines_warning(extra, nf));
  Soup soup{std::move(points), std::move(polygons)};
  return soup_to_mesh(soup, mesh);
}

// Reads OFF data of `byte_count` bytes as CGAL's OFF reader does (same
// scanner), but with bounds CGAL's reader lacks: the counts of the header and
// the size of each face must fit in the data (CGAL allocates them before
// reading, so a 20-byte file announcing 2e9 vertices would ask for 48 GB), and
// indices must be in range; then soup_to_mesh(). Lines after the faces the
// header announces are ignored, and counted in `warnings` (text OFF). Returns
// "" or a one-line message.
// The `nv` vertices of OFF data read by `scanner` from `in` (homogeneous
// coordinates divided out, normals, colours and textures skipped), checked.
inline std::string read_off_vertices(CGAL::File_scanner_OFF& scanner, std::istream& in, std::size_t nv,
                                     std::vector<K::Point_3>& points)
{
  for(std::size_t i = 0; i < nv; ++i)
  {
    double x = 0, y = 0, z = 0, w = 1;
    scanner.scan_vertex(x, y, z, w);
    if(scanner.has_normals())
    {
      double nx, ny, nz;
      scanner.scan_normal(nx, ny, nz);
    }
    if(scanner.has_vcolors() || scanner.has_textures())
    {
      // colours are not used; CGAL's scan_color() converts doubles to
      // unsigned char unchecked (undefined behaviour; found by the fuzzer)
      if(scanner.binary())
        return "binary OFF with vertex colours or textures is not supported";
      scanner.skip_to_next_vertex(i);
    }
    if(!in.good())
      return "truncated or malformed vertex " + std::to_string(i);
    if(w != 1.)
    {
      x /= w;
      y /= w;
      z /= w;
    }
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      return "vertex " + std::to_string(i) + " has a NaN or infinite coordinate";
    points.emplace_back(x, y, z);
  }
  return std::string();
}

// The `nf` faces of OFF data read by `scanner` from `in`, their indices
// checked against `nv` vertices.
inline std::string read_off_faces(CGAL::File_scanner_OFF& scanner, std::istream& in, std::size_t nv, std::size_t nf,
                                  std::vector<std::vector<std::size_t>>& polygons)
{
  for(std::size_t i = 0; i < nf; ++i)
  {
    std::vector<std::size_t> polygon;
    if(scanner.binary())
    {
      // 32-bit integers: no conversion issue
      std::size_t no = std::size_t(-1);
      scanner.scan_facet(no, i);
      if((!in.eof() && !in.good()) || no < 3 || no > nv)
        return "truncated or malformed face " + std::to_string(i);
      polygon.resize(no);
      for(std::size_t j = 0; j < no; ++j)
      {
        std::size_t id = nv;
        scanner.scan_facet_vertex_index(id, j + 1, i);
        if(!in || id >= nv)
          return "face " + std::to_string(i) + " has a vertex index out of range";
        polygon[j] = id;
      }
      scanner.skip_to_next_facet(i);
    }
    else
    {
      // Text: parsed here, because CGAL's scanner converts the numbers of the
      // line, read as doubles, to size_t unchecked (undefined behaviour for a
      // negative or huge value; found by the fuzzer).
      CGAL::skip_comment_OFF(in);
      std::string line;
      if(!std::getline(in, line))
        return "truncated face " + std::to_string(i);
      std::vector<double> entries;
      off_text::numbers(std::string_view(line).substr(0, line.find('#')), entries);
      if(std::string problem = off_text::face(entries, nv, i, polygon); !problem.empty())
        return problem;
    }
    polygons.push_back(std::move(polygon));
  }
  return std::string();
}

// Counts the non-empty lines left in `in` after the `nf` faces of text OFF
// data, and says so in `warnings` if there are any.
inline void warn_of_extra_off_lines(std::istream& in, std::size_t nf, std::vector<std::string>& warnings)
{
  // more face lines than the header announces: read as the header says, but said
  std::size_t extra = 0;
  std::string line;
  while(std::getline(in, line))
  {
    line = line.substr(0, line.find('#'));
    if(line.find_first_not_of(" \t\r") != std::string::npos)
      ++extra;
  }
  if(extra > 0)
    warnings.push_back(off_text::extra_lines_warning(extra, nf));
}

inline std::string read_off(std::istream& in, std::size_t byte_count, Mesh& mesh,
                            std::vector<std::string>* warnings = nullptr)
{
  CGAL::File_scanner_OFF scanner(in, false);
  if(in.fail())
    return "not an OFF file (bad or missing header)";
  const std::size_t nv = scanner.size_of_vertices(), nf = scanner.size_of_facets();
  if(nv > byte_count || nf > byte_count)
    return "the OFF header announces " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
           " faces, more than " + std::to_string(byte_count) + " bytes can hold";
  if(!scanner.binary() && !scanner.has_normals() && !scanner.has_colors() && !scanner.has_textures() &&
     !scanner.is_homogeneous() && scanner.dimension() == 3)
    return read_plain_off_body(in, nv, nf, mesh, warnings);
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  points.reserve(nv);
  polygons.reserve(nf);
  if(std::string problem = read_off_vertices(scanner, in, nv, points); !problem.empty())
    return problem;
  if(std::string problem = read_off_faces(scanner, in, nv, nf, polygons); !problem.empty())
    return problem;
  if(!in && !in.eof())
    return "malformed OFF data";
  if(!scanner.binary() && warnings)
    warn_of_extra_off_lines(in, nf, *warnings);
  Soup soup{std::move(points), std::move(polygons)};
  return soup_to_mesh(soup, mesh);
}

// Reads a mesh in `format` ("off", "obj", "ply" or "stl") of `byte_count`
// bytes from `in`, then validates it. Returns "" on success, a one-line
// message otherwise (and leaves `mesh` empty). What was read but not used
// (OFF lines after the announced faces, STL triangles with two equal corners)
// is described in `warnings`, if given.
inline std::string read_mesh(std::istream& in, const std::string& format, std::size_t byte_count, Mesh& mesh,
                             std::vector<std::string>* warnings = nullptr)
{
  mesh.clear();
  std::string problem;
  try
  {
    if(format == "off")
      problem = read_off(in, byte_count, mesh, warnings);
    else if(format == "obj" || format == "ply" || format == "stl")
    {
      Soup soup;
      std::size_t dropped = 0;
      problem = format == "obj"   ? read_obj_soup(in, byte_count, soup)
                : format == "ply" ? read_ply_soup(in, byte_count, soup)
                                  : read_stl_soup(in, byte_count, soup, dropped);
      if(problem.empty())
        problem = soup_to_mesh(soup, mesh);
      if(problem.empty() && dropped > 0 && warnings)
        warnings->push_back(std::to_string(dropped) + " STL triangle" + (dropped > 1 ? "s" : "") +
                            " with two equal corners dropped");
    }
    else
      problem = "unknown file format '" + format + "' (OFF, OBJ, PLY and STL are read)";
  }
  catch(const std::exception& e) // CGAL's failed assertions, std::bad_alloc
  {
    problem = std::string("malformed ") + format + " data (" + e.what() + ")";
  }
  if(problem.empty())
    problem = validate(mesh);
  if(!problem.empty())
  {
    mesh.clear();
    // keep the message on one line
    for(char& c : problem)
      if(c == '\n' || c == '\r')
        c = ' ';
  }
  return problem;
}

inline std::string read_mesh_file(const std::string& path, Mesh& mesh, std::vector<std::string>* warnings = nullptr)
{
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if(!in || ec)
    return "cannot open '" + path + "'";
  const std::string problem = read_mesh(in, extension(path), std::size_t(size), mesh, warnings);
  return problem.empty() ? problem : "'" + path + "': " + problem;
}

// Denoises `mesh` with the package's defaults (plus `np`); on failure `mesh`
// is unchanged and a one-line message is returned. If `report` is not null,
// it receives what intrinsic_denoising() chose and did.
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::string denoise(Mesh& mesh, const NamedParameters& np = CGAL::parameters::default_values(),
                    CGAL::Polygon_mesh_processing::Intrinsic_denoising_report* report = nullptr)
{
  try
  {
    const CGAL::Polygon_mesh_processing::Intrinsic_denoising_report r =
        CGAL::Polygon_mesh_processing::intrinsic_denoising<ConcurrencyTag>(mesh, np);
    if(report != nullptr)
      *report = r;
  }
  catch(const std::exception& e)
  {
    return e.what();
  }
  return std::string();
}

// The same with the options `options` set at run time (the command-line
// tool's and the Python module's path: one instantiation for every
// combination of options) and the maps and progress callback of `np`.
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::string denoise_with_options(Mesh& mesh,
                                 const CGAL::Polygon_mesh_processing::internal::Denoising::Intrinsic_options& options,
                                 const NamedParameters& np = CGAL::parameters::default_values(),
                                 CGAL::Polygon_mesh_processing::Intrinsic_denoising_report* report = nullptr)
{
  try
  {
    const CGAL::Polygon_mesh_processing::Intrinsic_denoising_report r =
        CGAL::Polygon_mesh_processing::internal::Denoising::intrinsic_denoising_with_options<ConcurrencyTag>(
            mesh, options, np);
    if(report != nullptr)
      *report = r;
  }
  catch(const std::exception& e)
  {
    return e.what();
  }
  return std::string();
}

// Whether every candidate of the automatic selection stopped at once (the
// library's test, which the long-run test reads too).
using CGAL::Polygon_mesh_processing::internal::Denoising::short_selection;

// The automatic selection's lines on the noise it removed: dense or
// sparse, and the residual at the kept candidate's stop.
inline void describe_noise(std::ostream& out, const CGAL::Polygon_mesh_processing::Intrinsic_denoising_report& r)
{
  out << "noise kind: "
      << (r.outlier_vertices > 0
              ? "sparse: only the " + std::to_string(r.outlier_vertices) + " outlier vertices were denoised"
              : std::string("dense: every vertex denoised"))
      << " (residual correlation " << r.inlier_residual_correlation
      << " at the vertices within 3 robust deviations; sparse from 0.1)\n";
  const std::vector<double>& c = r.residual_hop_correlations;
  if(c.size() >= 8)
    out << "residual at the kept candidate's stop: correlation " << c[0] << ", " << c[1] << ", " << c[3] << ", " << c[7]
        << " between vertices 1, 2, 4, 8 edges apart, at least 0.5 over " << r.residual_correlation_length
        << " edges (independent noise removed: about 0 beyond one edge); " << 100. * r.residual_axis_share
        << "% of its energy along one direction (33% if spread evenly)\n";
}

// The lines on the long-run test and, when every candidate stopped at once
// and no long run was kept, the note on what that means.
inline void describe_long_run(std::ostream& out, const CGAL::Polygon_mesh_processing::Intrinsic_denoising_report& r)
{
  using Reason = CGAL::Polygon_mesh_processing::Intrinsic_stop_reason;
  typedef CGAL::Polygon_mesh_processing::internal::Denoising::Selection_rules Rules;
  if(r.long_run_first_share >= 0.)
    out << "long-run test (every candidate stopped at once): the first of " << Rules::long_run_iterations
        << " iterations of sigma " << Rules::long_run_candidate.sigma << " on "
        << Rules::long_run_candidate.relative_radius << " d made " << r.long_run_first_share
        << " of their turn of the normals (the long run is kept from " << Rules::long_run_first_share << "): "
        << (r.stop_reason == Reason::LONG_RUN ? "kept, the change was used up early, as noise is"
                                              : "not kept, the change went on, as shape erosion does")
        << "\n";
  if(short_selection(r) && r.stop_reason != Reason::LONG_RUN)
  {
    out << "note: every candidate's residual was correlated across edges within " << Rules::short_run_iterations
        << " iterations. Either the mesh has little noise (or a coarse shape the filter would take for noise), or "
           "its noise is itself correlated from vertex to vertex, as the noise of depth scans and of surfaces "
           "reconstructed from them is; "
        << (r.long_run_first_share < 0. ? "the automatic mode cannot tell the two apart"
                                        : "the long-run test read the change as shape")
        << ", so the mesh is left nearly as it is. For a scan, ";
    if(r.long_run_first_share < 0.)
      out << "try --long-run-test (it keeps a long run if its first iteration made most of its change, as noise "
             "does), or ";
    out << "choose the parameters: --fixed (the paper's setting) for light scanner noise, or for the strong, "
           "blotchy noise of a depth camera a wider and longer setting such as -k 60 --relative-radius 6 "
           "--sigma-spatial 0.8 --sigma-range 0.8 (see the manual, real scans).\n";
  }
}

// A few readable lines on what intrinsic_denoising() chose and did.
inline std::string describe(const CGAL::Polygon_mesh_processing::Intrinsic_denoising_report& r)
{
  using Reason = CGAL::Polygon_mesh_processing::Intrinsic_stop_reason;
  std::ostringstream out;
  out << "parameters: " << (r.automatic_parameters ? "automatic" : "fixed") << "\n";
  if(!r.candidates.empty())
  {
    // the automatic selection: every candidate, its stop and its score
    out << "selection: " << r.candidates.size() << " candidates, each stopped before its residual correlation across "
        << "edges reached the threshold; among the flattest results (if piecewise flat), the lowest correlation at a "
        << "common residual RMS wins\n";
    if(r.selection_sample_faces > 0)
      out << "sample: the selection ran on " << r.selection_sample_faces << " faces in " << r.selection_sample_patches
          << " patches of the mesh, its setting then once on the whole mesh\n";
    for(std::size_t c = 0; c < r.candidates.size(); ++c)
    {
      const auto& k = r.candidates[c];
      out << (c == r.chosen_candidate ? "  * " : "    ") << "sigma " << k.sigma << ", r " << k.relative_neighbor_radius
          << " d: " << k.iterations << " iterations" << (k.stopped_by_correlation ? "" : " (limit)")
          << ", residual RMS " << k.residual_rms << ", correlation " << k.residual_correlation << ", flat edges "
          << k.flat_share << ", score " << k.score << "\n";
    }
    describe_noise(out, r);
    if(!r.self_check_errors.empty())
    {
      // the self-check's curve, and the iterations it kept
      out << "self-check on a synthetic noisy copy of the result (angle to the result after k iterations):";
      for(std::size_t k = 0; k < r.self_check_errors.size(); ++k)
        out << (k % 10 == 0 ? "\n   " : "") << " " << k << ": " << r.self_check_errors[k];
      out << "\n";
      // the radii tried on the copy, walked outwards from the candidate's
      out << "smallest angle on the copy with the kept kernel, by radius (walked outwards from the candidate's while "
             "the copy comes closer; another taken if over 2% below the best before it):";
      for(std::size_t i = 0; i < r.self_check_radii.size() && i < r.self_check_smallest_errors.size(); ++i)
        out << (i > 0 ? "," : "") << " " << r.self_check_radii[i] << " d: " << r.self_check_smallest_errors[i];
      out << "\n";
    }
  }
  if(r.second_pass_angle > 0.)
    out << "second pass (the kept kernel again on the result, as many iterations): it turned the normals by "
        << r.second_pass_angle << " degrees, the run had turned the input's by " << r.change_angle << " degrees: "
        << (r.stop_reason == Reason::SECOND_PASS ? "over half, so the run removed mostly shape: the input is kept"
                                                 : "at most half, so the run removed mostly noise: its result is kept")
        << "\n";
  if(r.noise_level_estimated || r.noise_level > 0. || r.automatic_parameters)
    out << "noise level: " << r.noise_level << " x mean edge length ("
        << (!r.candidates.empty()     ? "residual RMS of the kept candidate"
            : r.noise_level_estimated ? "estimated"
                                      : "given")
        << ")\n";
  out << "sigma_s = " << r.sigma_spatial << ", sigma_r = " << r.sigma_range << "\n";
  out << "r = " << r.neighbor_radius << " (" << r.relative_neighbor_radius << " d), v_iter = " << r.vertex_iterations
      << "\n";
  out << "iterations: " << r.iterations << " of at most " << r.maximum_iterations
      << ", stopped: " << name_of(stop_reason_names, r.stop_reason).description;
  if(r.stop_reason != Reason::ITERATION_LIMIT || r.displacement > 0.)
    out << " (RMS displacement " << r.displacement << " x mean edge length)";
  out << "\n";
  if(!r.candidates.empty() || r.relaxed_vertices > 0)
    out << "tangential relaxation: " << r.relaxed_vertices
        << " vertices moved along the surface after the last iteration (each by at most half its denoising "
        << "displacement)\n";
  describe_long_run(out, r);
  return out.str();
}

// <input without its extension>_denoised.off, next to the input.
inline std::string output_path(const std::string& input)
{
  std::filesystem::path p(input);
  return (p.parent_path() / (p.stem().string() + "_denoised.off")).string();
}

// `mesh` as OFF text: each coordinate in the shortest decimal form that
// reads back as the same double (std::to_chars), vertices numbered in the
// order of vertices(mesh). Written through one buffer: an ostream's
// per-number formatting costs about a second per million faces.
inline bool write_off_text(std::ostream& out, const Mesh& mesh)
{
  std::size_t max_index = 0;
  for(auto v : vertices(mesh))
    max_index = std::max(max_index, std::size_t(v));
  // number_of_*(): the elements not removed (num_vertices() counts those too)
  std::vector<std::size_t> id(mesh.number_of_vertices() == 0 ? 0 : max_index + 1, 0);
  std::size_t next_id = 0;
  for(auto v : vertices(mesh))
    id[std::size_t(v)] = next_id++;
  std::string buffer;
  buffer.reserve(std::size_t(1) << 20);
  char number[64];
  auto append = [&](auto x) {
    const auto r = std::to_chars(number, number + sizeof(number), x);
    buffer.append(number, r.ptr);
  };
  auto flush = [&](bool force) {
    if(force || buffer.size() >= (std::size_t(1) << 20) - 256)
    {
      out.write(buffer.data(), std::streamsize(buffer.size()));
      buffer.clear();
    }
  };
  buffer += "OFF\n";
  append(std::size_t(mesh.number_of_vertices()));
  buffer += ' ';
  append(std::size_t(mesh.number_of_faces()));
  buffer += " 0\n";
  for(auto v : vertices(mesh))
  {
    const K::Point_3& p = mesh.point(v);
    append(p.x());
    buffer += ' ';
    append(p.y());
    buffer += ' ';
    append(p.z());
    buffer += '\n';
    flush(false);
  }
  for(auto f : faces(mesh))
  {
    append(std::size_t(degree(f, mesh)));
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
    {
      buffer += ' ';
      append(id[std::size_t(v)]);
    }
    buffer += '\n';
    flush(false);
  }
  flush(true);
  return bool(out);
}

// Writes `mesh` (OFF, write_off_text()) to `path` through a temporary file in
// the same directory and a rename: `path` is either left as it was or holds
// the whole mesh. Refuses to write over `protect` (the input file).
inline std::string write_mesh_file(const std::string& path, const Mesh& mesh, const std::string& protect = "")
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if(!protect.empty() && fs::exists(path, ec) && fs::equivalent(path, protect, ec))
    return "refusing to overwrite the input '" + protect + "'";
  const std::string tmp = path + ".tmp" + std::to_string(static_cast<long>(::getpid())) + ".off";
  bool ok = false;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    ok = out && write_off_text(out, mesh);
    out.close();
    ok = ok && !out.fail();
  }
  if(!ok || std::rename(tmp.c_str(), path.c_str()) != 0)
  {
    std::remove(tmp.c_str());
    return "cannot write '" + path + "'";
  }
  return std::string();
}

// Writes `mesh` to `path` in the format of its extension (OFF as
// write_off_text() writes it; OBJ, PLY or STL by CGAL with 17 digits),
// atomically as write_mesh_file() does (temporary file in
// the same directory, then a rename), never over `protect`.
inline std::string write_mesh(const std::string& path, const Mesh& mesh, const std::string& protect = "")
{
  const std::string ext = extension(path);
  if(ext == "off")
    return write_mesh_file(path, mesh, protect);
  if(ext != "obj" && ext != "ply" && ext != "stl")
    return "unknown output format '" + ext + "' (OFF, OBJ, PLY and STL are written)";
  namespace fs = std::filesystem;
  std::error_code ec;
  if(!protect.empty() && fs::exists(path, ec) && fs::equivalent(path, protect, ec))
    return "refusing to overwrite the input '" + protect + "'";
  const std::string tmp = path + ".tmp" + std::to_string(static_cast<long>(::getpid())) + "." + ext;
  bool ok = false;
  try
  {
    ok = CGAL::IO::write_polygon_mesh(tmp, mesh, CGAL::parameters::stream_precision(17).verbose(false));
  }
  catch(const std::exception&)
  {
    ok = false;
  }
  if(!ok || std::rename(tmp.c_str(), path.c_str()) != 0)
  {
    std::remove(tmp.c_str());
    return "cannot write '" + path + "'";
  }
  return std::string();
}

} // namespace denoising_support

#endif
