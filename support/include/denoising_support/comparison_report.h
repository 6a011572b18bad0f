// A self-contained HTML comparison page of denoising results: every mesh drawn
// with three.js (inlined, so the page needs no network), all cameras linked,
// a per-face normal-error heat map, and the E_n / E_v / seconds table, also
// embedded as JSON and written next to the page as CSV (FILE.csv for
// FILE.html) for checks. Used by the command-line tool (`denoise --report`)
// and by benchmark/Polygon_mesh_processing/table1_benchmark.cpp.
//
// The page is tools/render/report_template.html with tools/render/viewer.js
// and three's module build (tools/render/node_modules, `npm ci` there) pasted
// in; CMake passes their locations as DENOISING_RENDER_DIR and
// DENOISING_THREE_JS.

#ifndef DENOISING_SUPPORT_COMPARISON_REPORT_H
#define DENOISING_SUPPORT_COMPARISON_REPORT_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace denoising_support {

// one mesh of the page and its row of the table
struct Entry
{
  std::string label;
  std::vector<float> positions;                         // x y z per vertex
  std::vector<std::uint32_t> triangles;                 // three vertex numbers per face
  std::vector<float> face_errors;                       // degrees per face; empty: no heat map
  double En = std::numeric_limits<double>::quiet_NaN(); // NaN: empty cell
  double Ev = std::numeric_limits<double>::quiet_NaN();
  double seconds = std::numeric_limits<double>::quiet_NaN();
};

struct Report
{
  std::string title;
  std::array<double, 3> view_dir{{1., 0.6, 1.4}}; // from the centre towards the camera
  std::array<double, 3> view_up{{0., 1., 0.}};
  double heat_max = 15.; // degrees shown as full red
  std::vector<Entry> entries;
  int debug_empty_entry = -1; // testing only: this entry loses its vertices
};

// The vertices and triangles of `mesh`; with `reference` (same faces), the
// angle in degrees between each face normal and the reference's.
template <typename Mesh>
Entry make_entry(const std::string& label, const Mesh& mesh, const Mesh* reference = nullptr)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Entry e;
  e.label = label;
  std::map<vertex_descriptor, std::uint32_t> number;
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(vertex_descriptor v : vertices(mesh))
  {
    number.emplace(v, std::uint32_t(number.size()));
    const auto& p = get(vpm, v);
    e.positions.insert(e.positions.end(), {float(p.x()), float(p.y()), float(p.z())});
  }
  auto normals = [](const Mesh& m) {
    std::vector<std::array<double, 3>> out;
    const auto pm = get(CGAL::vertex_point, m);
    for(auto f : faces(m))
    {
      std::array<std::array<double, 3>, 3> q;
      int k = 0;
      for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
        if(k < 3)
        {
          const auto& p = get(pm, v);
          q[k++] = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
        }
      const double a[3] = {q[1][0] - q[0][0], q[1][1] - q[0][1], q[1][2] - q[0][2]};
      const double b[3] = {q[2][0] - q[0][0], q[2][1] - q[0][1], q[2][2] - q[0][2]};
      out.push_back({{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}});
    }
    return out;
  };
  for(auto f : faces(mesh))
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      e.triangles.push_back(number[v]);
  if(reference != nullptr && num_faces(*reference) == num_faces(mesh))
  {
    const auto na = normals(mesh), nb = normals(*reference);
    for(std::size_t f = 0; f < na.size(); ++f)
    {
      const auto &a = na[f], &b = nb[f];
      const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      const double cross = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      // a face of zero area counts as 0, as in face_normal_error()
      e.face_errors.push_back(
          cross == 0. && dot == 0. ? 0.f : float(std::atan2(cross, dot) * (180. / 3.14159265358979323846)));
    }
  }
  return e;
}

namespace internal {

inline std::string base64(const void* data, std::size_t bytes)
{
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const unsigned char* s = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((bytes + 2) / 3 * 4);
  for(std::size_t i = 0; i < bytes; i += 3)
  {
    const unsigned v = (unsigned(s[i]) << 16) | (i + 1 < bytes ? unsigned(s[i + 1]) << 8 : 0u) |
                       (i + 2 < bytes ? unsigned(s[i + 2]) : 0u);
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes ? digits[v & 63] : '=';
  }
  return out;
}

// per-face errors for the heat map, in hundredths of a degree (Uint16,
// little-endian, base64): half the size of floats, finer than any colour step
inline std::string centidegrees(const std::vector<float>& degrees)
{
  std::vector<unsigned char> bytes;
  bytes.reserve(2 * degrees.size());
  for(float d : degrees)
  {
    const double c = std::isfinite(d) ? std::min(65535., std::max(0., std::round(double(d) * 100.))) : 65535.;
    const unsigned v = unsigned(c);
    bytes.push_back(static_cast<unsigned char>(v & 255));
    bytes.push_back(static_cast<unsigned char>(v >> 8));
  }
  return base64(bytes.data(), bytes.size());
}

// a JSON string (labels and titles are plain text)
inline std::string quote(const std::string& s)
{
  std::string out = "\"";
  for(char c : s)
  {
    if(c == '"' || c == '\\')
      out += '\\';
    if(c == '<') // never "</script>" inside the page's JSON
    {
      out += "\\u003c";
      continue;
    }
    if(static_cast<unsigned char>(c) < 0x20)
      continue;
    out += c;
  }
  return out + "\"";
}

// round-trip precision; null for "no value"
inline std::string number(double x)
{
  if(!std::isfinite(x))
    return "null";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", x);
  return buf;
}

inline bool read_file(const std::string& path, std::string& out)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

} // namespace internal

// FILE.csv for FILE.html
inline std::string table_path(const std::string& html_path)
{
  const std::size_t dot = html_path.rfind('.');
  const std::size_t slash = html_path.find_last_of("/\\");
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? html_path.substr(0, dot) : html_path) + ".csv";
}

// The page's parts: an empty string if they can be read, else a one-line error.
inline std::string check_report_files()
{
#if defined(DENOISING_RENDER_DIR) && defined(DENOISING_THREE_JS)
  const std::string render_dir = DENOISING_RENDER_DIR, three_path = DENOISING_THREE_JS;
  for(const std::string& f : {render_dir + "/report_template.html", render_dir + "/viewer.js"})
    if(!std::ifstream(f))
      return "report: cannot read the page part " + f;
  if(!std::ifstream(three_path))
    return "report: three.js build file " + three_path + " is missing: run `npm ci` in tools/render";
  return std::string();
#else
  return "report: this program was built without the page's scripts (DENOISING_RENDER_DIR / DENOISING_THREE_JS)";
#endif
}

namespace internal {

// The page's data (JSON: meshes, face lists, the table) of `report`, and the
// table as CSV in `csv`.
inline std::string report_json(const Report& report, std::string& csv_text)
{
  // the JSON data: identical triangle lists are stored once
  std::vector<const std::vector<std::uint32_t>*> lists;
  std::ostringstream meshes;
  for(std::size_t i = 0; i < report.entries.size(); ++i)
  {
    const Entry& e = report.entries[i];
    std::size_t list = 0;
    while(list < lists.size() && *lists[list] != e.triangles)
      ++list;
    if(list == lists.size())
      lists.push_back(&e.triangles);
    const bool emptied = int(i) == report.debug_empty_entry;
    meshes << (i ? ",\n" : "") << "{\"label\":" << quote(e.label) << ",\"positions\":\""
           << (emptied ? std::string() : base64(e.positions.data(), e.positions.size() * sizeof(float)))
           << "\",\"faces\":" << list << ",\"errors\":"
           << (e.face_errors.empty() ? std::string("null") : "\"" + centidegrees(e.face_errors) + "\"") << "}";
  }
  std::ostringstream data;
  data << "{\"title\":" << quote(report.title) << ",\"heatMax\":" << number(report.heat_max) << ",\"view\":{\"dir\":["
       << report.view_dir[0] << "," << report.view_dir[1] << "," << report.view_dir[2] << "],\"up\":["
       << report.view_up[0] << "," << report.view_up[1] << "," << report.view_up[2] << "]},\n\"faceLists\":[";
  for(std::size_t l = 0; l < lists.size(); ++l)
    data << (l ? ",\n\"" : "\"") << base64(lists[l]->data(), lists[l]->size() * sizeof(std::uint32_t)) << "\"";
  data << "],\n\"meshes\":[" << meshes.str() << "],\n\"table\":[";
  std::ostringstream csv;
  csv << "label,E_n,E_v,seconds\n";
  for(std::size_t i = 0; i < report.entries.size(); ++i)
  {
    const Entry& e = report.entries[i];
    data << (i ? ",\n" : "") << "{\"label\":" << quote(e.label) << ",\"E_n\":" << number(e.En)
         << ",\"E_v\":" << number(e.Ev) << ",\"seconds\":" << number(e.seconds) << "}";
    std::string label = e.label;
    for(char& c : label)
      if(c == ',' || c == '\n')
        c = ' ';
    auto cell = [](double x) { return std::isfinite(x) ? number(x) : std::string(); };
    csv << label << "," << cell(e.En) << "," << cell(e.Ev) << "," << cell(e.seconds) << "\n";
  }
  data << "]}";
  csv_text = csv.str();
  return data.str();
}

} // namespace internal

// Writes the page to `html_path` and the table to table_path(html_path).
// Returns an empty string on success, else a one-line error.
inline std::string write_report(const std::string& html_path, const Report& report)
{
  const std::string missing = check_report_files();
  if(!missing.empty())
    return missing;
#if defined(DENOISING_RENDER_DIR) && defined(DENOISING_THREE_JS)
  const std::string render_dir = DENOISING_RENDER_DIR, three_path = DENOISING_THREE_JS;
#else
  const std::string render_dir, three_path;
#endif
  std::string page, viewer, three;
  if(!internal::read_file(render_dir + "/report_template.html", page) ||
     !internal::read_file(render_dir + "/viewer.js", viewer))
    return "report: cannot read the page template in " + render_dir;
  if(!internal::read_file(three_path, three))
    return "report: three.js build file " + three_path + " is missing: run `npm ci` in tools/render";

  std::string csv;
  const std::string data_text = internal::report_json(report, csv);

  // paste the parts into the template's placeholders, found in the template
  // itself and replaced from the last one back, so pasted text is never searched
  const std::pair<const char*, const std::string*> parts[] = {
      {"@REPORT_DATA@", &data_text}, {"@THREE_MODULE@", &three}, {"@VIEWER_JS@", &viewer}};
  std::vector<std::pair<std::size_t, std::size_t>> at; // (position, part)
  for(std::size_t k = 0; k < 3; ++k)
  {
    const std::size_t pos = page.find(parts[k].first);
    if(pos == std::string::npos)
      return std::string("report: placeholder ") + parts[k].first + " missing in " + render_dir +
             "/report_template.html";
    at.emplace_back(pos, k);
  }
  std::sort(at.rbegin(), at.rend());
  for(const auto& a : at)
    page.replace(a.first, std::string(parts[a.second].first).size(), *parts[a.second].second);

  std::ofstream out(html_path, std::ios::binary);
  out << page;
  if(!out.flush())
    return "report: cannot write " + html_path;
  std::ofstream table(table_path(html_path));
  table << csv;
  if(!table.flush())
    return "report: cannot write " + table_path(html_path);
  return std::string();
}

} // namespace denoising_support

#endif // DENOISING_SUPPORT_COMPARISON_REPORT_H
