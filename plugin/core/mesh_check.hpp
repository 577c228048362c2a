// The check of a gmsh MSH 2.2 triangle mesh that edp/lib/mesh.idp runs before FreeFEM's gmshload,
// which aborts or misleads on what is caught here: another format than ASCII MSH 2 (gmsh 4 writes
// MSH 4 unless -format msh22), a file cut off, a triangle on an undefined node, a clockwise
// triangle (FreeFEM's meshes are counter-clockwise: gmshload stops on an assertion), a triangle
// of area below 1e-8 in the mesh's units (gmshload: only "bug : mes < 1e-8 !"), and, when
// min_quality > 0, a nearly degenerate triangle: quality q = 4 sqrt(3) area / (sum of the squared
// edge lengths), 1 for an equilateral triangle, 0 for a degenerate one.
// Returns "" when the mesh passes, else one sentence naming the file and the first fault.
#pragma once
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <algorithm>
#include <array>
#include <map>
#include <unordered_map>
#include <vector>

namespace sma::mesh {

namespace detail {
inline std::string format(const char* fmt, double a = 0, double b = 0, double c = 0, double d = 0,
                          double e = 0, double f = 0) {
  char buf[512];
  std::snprintf(buf, sizeof buf, fmt, a, b, c, d, e, f);
  return buf;
}
}  // namespace detail

inline std::string check_msh(const std::string& path, double min_quality) {
  std::ifstream in(path);
  if (!in) return "mesh " + path + " cannot be read";
  const std::string name = "mesh " + path;
  std::string line, version, binary;
  std::unordered_map<long, std::pair<double, double>> node;
  bool saw_format = false, saw_elements = false, end_elements = false;
  long declared = -1, elements = 0, triangles = 0, missing = 0, clockwise = 0;
  double cw_x = 0, cw_y = 0;
  double total = 0, worst_q = 0, worst_q_area = 0, min_area = 0, min_area_q = 0;
  long worst_q_id = 0, min_area_id = 0;
  // Nodes: the count the section declares and the lines it holds, ids given twice, coordinates
  // that are not finite numbers of a sane size. Triangles: one listed twice (the same three nodes,
  // in any order) corrupts gmshload's mesh (issue 26: a heap corruption).
  long nodes_declared = -1, node_lines = 0, node_twice = 0, node_bad = 0;
  std::string node_bad_text;
  std::map<std::array<long, 3>, long> seen_triangles;
  long triangle_twice = 0, triangle_first = 0;
  // An element line must be "id type ntags tag... nodes" of a 2D type with exactly its fields: a
  // tag count of 2^31 - 1 made gmshload read for ever, a tetrahedron ended in a bare message.
  long element_bad = 0;
  std::string element_bad_text, element_bad_why;
  double worst_x = 0, worst_y = 0, min_x = 0, min_y = 0;
  enum { none, format, nodes, elems } section = none;
  bool first_line = true;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (first_line && line.rfind("\xEF\xBB\xBF", 0) == 0)
      return name + " begins with a byte-order mark (an editor's): gmshload reads plain ASCII MSH 2.2; save it without";
    first_line = false;
    if (line.rfind("$MeshFormat", 0) == 0) { section = format; continue; }
    if (line.rfind("$Nodes", 0) == 0) { section = nodes; continue; }
    if (line.rfind("$Elements", 0) == 0) { section = elems; saw_elements = true; declared = -1; continue; }
    if (line.rfind("$EndElements", 0) == 0) { section = none; end_elements = true; continue; }
    if (line.rfind("$End", 0) == 0) { section = none; continue; }
    std::istringstream words(line);
    if (section == format) {
      words >> version >> binary;
      saw_format = true;
      section = none;
    } else if (section == nodes) {
      if (nodes_declared < 0) {
        if (!(words >> nodes_declared) || nodes_declared < 0) nodes_declared = -2;
        continue;
      }
      ++node_lines;
      long id;
      double x, y, z;
      std::string extra;
      // exactly "id x y z": a line with more fields is an edit gmshload would misread as a node
      if (words >> id >> x >> y >> z && !(words >> extra)) {
        if (!(std::isfinite(x) && std::isfinite(y) && std::fabs(x) < 1e12 && std::fabs(y) < 1e12)) {
          if (!node_bad) { node_bad = id; node_bad_text = line; }
          continue;
        }
        if (node.count(id) && !node_twice) node_twice = id;
        node[id] = {x, y};
      } else if (!node_bad) {
        node_bad = node_lines;
        node_bad_text = line;
      }
    } else if (section == elems) {
      if (declared < 0) {
        if (!(words >> declared) || declared < 0) declared = -2;
        continue;
      }
      ++elements;
      std::vector<std::string> f;
      for (std::string w; words >> w;) f.push_back(w);
      auto whole = [](const std::string& w, long& out) {
        char* end = nullptr;
        errno = 0;
        out = std::strtol(w.c_str(), &end, 10);
        return !w.empty() && *end == '\0' && errno == 0;
      };
      long id = 0, type = 0, ntags = 0;
      const long corners = f.size() >= 2 && whole(f[1], type) ? (type == 15 ? 1 : type == 1 ? 2 : type == 2 ? 3 : 0) : 0;
      if (f.size() < 3 || !whole(f[0], id) || !whole(f[2], ntags) || ntags < 0 ||
          corners == 0 || (long)f.size() != 3 + ntags + corners) {
        if (!element_bad) {
          element_bad = elements;
          element_bad_text = line;
          element_bad_why = corners == 0 && f.size() >= 2
                                ? "its type " + f[1] + " is not a point (15), a line (1) or a triangle (2) of a 2D mesh"
                                : "it is not 'id type ntags', the tags and the element's nodes";
        }
        continue;
      }
      if (type != 2) continue;
      long v[3];
      if (!whole(f[3 + ntags], v[0]) || !whole(f[4 + ntags], v[1]) || !whole(f[5 + ntags], v[2])) continue;
      std::array<long, 3> key{v[0], v[1], v[2]};
      std::sort(key.begin(), key.end());
      const auto [where, fresh] = seen_triangles.emplace(key, id);
      if (!fresh && !triangle_twice) { triangle_twice = id; triangle_first = where->second; }
      if (!node.count(v[0]) || !node.count(v[1]) || !node.count(v[2])) {
        if (!missing) missing = id;
        continue;
      }
      const auto [xa, ya] = node[v[0]];
      const auto [xb, yb] = node[v[1]];
      const auto [xc, yc] = node[v[2]];
      double area = ((xb - xa) * (yc - ya) - (xc - xa) * (yb - ya)) / 2;
      const double cx = (xa + xb + xc) / 3, cy = (ya + yb + yc) / 3;
      if (area < 0) {
        if (!clockwise) { clockwise = id; cw_x = cx; cw_y = cy; }
        area = -area;
      }
      const double l2 = (xb - xa) * (xb - xa) + (yb - ya) * (yb - ya) + (xc - xb) * (xc - xb) +
                        (yc - yb) * (yc - yb) + (xa - xc) * (xa - xc) + (ya - yc) * (ya - yc);
      const double q = l2 > 0 ? 4 * std::sqrt(3.0) * area / l2 : 0;
      ++triangles;
      total += area;
      if (triangles == 1 || q < worst_q) { worst_q = q; worst_q_id = id; worst_q_area = area; worst_x = cx; worst_y = cy; }
      if (triangles == 1 || area < min_area) { min_area = area; min_area_id = id; min_area_q = q; min_x = cx; min_y = cy; }
    }
  }
  if (!saw_format) return name + " is not a gmsh MSH file (no $MeshFormat)";
  const double v = std::atof(version.c_str());
  if (v >= 3 || v < 2) return name + " is MSH " + version + ": FreeFEM's gmshload reads MSH 2.2 only (gmsh -format msh22)";
  if (binary != "0") return name + " is a binary MSH file: gmshload reads ASCII MSH 2.2 (gmsh -format msh22 without -bin)";
  if (declared == -2) return name + ": its $Elements section does not start with a count of elements >= 0";
  if (!saw_elements || declared < 0)
    return name + " is cut off before its elements (an interrupted gmsh or copy? run 'make meshes')";
  if (!end_elements || elements != declared)
    return name + " is cut off: " + std::to_string(elements) + " of the " + std::to_string(declared) +
           " elements it declares, " + (end_elements ? "then $EndElements" : "and no $EndElements") +
           " (an interrupted gmsh or copy? run 'make meshes')";
  if (nodes_declared == -2) return name + ": its $Nodes section does not start with the number of nodes";
  if (node_bad)
    return name + ": a node line is not 'id x y z' with finite coordinates below 1e12 in size: '" + node_bad_text + "'";
  if (nodes_declared >= 0 && node_lines != nodes_declared)
    return name + " declares " + std::to_string(nodes_declared) + " nodes and lists " + std::to_string(node_lines) +
           " (a cut or edited file? run 'make meshes')";
  if (node_twice) return name + ": node " + std::to_string(node_twice) + " is defined twice";
  if (element_bad)
    return name + ": element line " + std::to_string(element_bad) + " of $Elements ('" + element_bad_text.substr(0, 80) +
           "'): " + element_bad_why;
  if (missing) return name + ": triangle " + std::to_string(missing) + " uses a node the file does not define";
  if (triangle_twice)
    return name + ": triangle " + std::to_string(triangle_twice) + " repeats triangle " + std::to_string(triangle_first) +
           " (the same three nodes)";
  if (clockwise)
    return name + ": triangle " + std::to_string(clockwise) + detail::format(" (centroid %.6g, %.6g)", cw_x, cw_y) +
           " is clockwise: FreeFEM needs counter-clockwise triangles (regenerate the mesh with gmsh)";
  if (triangles == 0) return name + " has no triangle";
  if (min_area < 1e-8)
    return name + ": triangle " + std::to_string(min_area_id) +
           detail::format(" (centroid %.6g, %.6g) has area %.3g < 1e-8 (mean %.3g, quality %.3g)", min_x, min_y,
                          min_area, total / triangles, min_area_q) +
           ": FreeFEM's gmshload rejects any triangle below 1e-8 (in the mesh's units)";
  if (min_quality > 0 && worst_q < min_quality)
    return name + ": triangle " + std::to_string(worst_q_id) +
           detail::format(" (centroid %.6g, %.6g) has quality %.3g < %g (4 sqrt(3) area / sum of squared edges; "
                          "area %.3g, mean %.3g)", worst_x, worst_y, worst_q, min_quality, worst_q_area,
                          total / triangles) +
           ": a nearly degenerate triangle (pass -meshminquality 0 to accept it)";
  return {};
}

}  // namespace sma::mesh
