// Result files of the scenes written in the plugin: CSV rows of numbers, in the bytes of an
// ostream of that precision, and a triangle mesh with fields as a ParaView VTU
// file, in the very bytes FreeFEM's savevtk writes (iovtk, binary XML), without going through
// FreeFEM's finite-element evaluation, which cost a periodic frame of the default run about 9
// million instructions (8 % of the run): every value of every field was evaluated as an
// expression at every vertex of every triangle.
//
// savevtk's layout, kept byte for byte: the mesh as Float32 points (z = 0), Int32 connectivity and
// offsets, UInt8 cell types (5, triangles), the triangles' labels; then the cell fields (one
// Float64 value per triangle), then the point fields (Float64, a vector field padded with z = 0
// to 3 components). Each array is base64 of its byte length (4 bytes, little endian) followed by
// its values. A point field's value at a vertex is what savevtk computes: the field evaluated at
// that vertex in each triangle around it (for P1, the vertex's value), summed over those
// triangles from 0 and divided by their number (so the mean of equal values, to round-off).
#pragma once

#include <charconv>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace sma::output {

// Base64 (RFC 4648, '=' padding) of n bytes, appended to out (written in place: a frame's arrays
// are some 70 kB of text).
inline void base64_append(const unsigned char* bytes, std::size_t n, std::string& out) {
  static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const std::size_t start = out.size();
  out.resize(start + 4 * ((n + 2) / 3));
  char* o = &out[0] + start;
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3, o += 4) {
    const unsigned v = (unsigned(bytes[i]) << 16) | (unsigned(bytes[i + 1]) << 8) | unsigned(bytes[i + 2]);
    o[0] = digits[(v >> 18) & 63];
    o[1] = digits[(v >> 12) & 63];
    o[2] = digits[(v >> 6) & 63];
    o[3] = digits[v & 63];
  }
  if (i < n) {
    const unsigned b1 = i + 1 < n ? bytes[i + 1] : 0;
    const unsigned v = (unsigned(bytes[i]) << 16) | (b1 << 8);
    o[0] = digits[(v >> 18) & 63];
    o[1] = digits[(v >> 12) & 63];
    o[2] = i + 1 < n ? digits[(v >> 6) & 63] : '=';
    o[3] = '=';
  }
}

// A binary VTU array's text: base64 of [byte length as uint32 little endian, the values' bytes],
// appended to out (bytes: a buffer, reused).
template <class T>
void vtu_binary_append(const std::vector<T>& values, std::vector<unsigned char>& bytes, std::string& out) {
  const std::uint32_t length = static_cast<std::uint32_t>(values.size() * sizeof(T));
  bytes.resize(sizeof length + values.size() * sizeof(T));
  std::memcpy(bytes.data(), &length, sizeof length);  // (x86: little endian, as savevtk)
  if (!values.empty()) std::memcpy(bytes.data() + sizeof length, values.data(), values.size() * sizeof(T));
  base64_append(bytes.data(), bytes.size(), out);
}
template <class T>
std::string vtu_binary(const std::vector<T>& values) {
  std::vector<unsigned char> bytes;
  std::string out;
  vtu_binary_append(values, bytes, out);
  return out;
}

// A triangle mesh: vertex coordinates, 3 vertex indices per triangle, one label per triangle.
struct VtuMesh {
  std::vector<double> x, y;
  std::vector<int> triangles;
  std::vector<int> labels;
  std::size_t vertices() const { return x.size(); }
  std::size_t cells() const { return labels.size(); }
};

// A field: per triangle (cell field) or per vertex (point field), `components` values each,
// interleaved.
struct VtuField {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

// A point field's values as savevtk writes them (see the header): vertex v's value summed from 0
// over the triangles around v, then divided by their count (0/0, NaN, for a vertex of no triangle,
// as savevtk).
inline std::vector<double> savevtk_vertex_values(const VtuMesh& mesh, const VtuField& field) {
  const std::size_t nv = mesh.vertices(), nc = static_cast<std::size_t>(field.components);
  std::vector<int> around(nv, 0);
  for (int v : mesh.triangles) around[static_cast<std::size_t>(v)]++;
  std::vector<double> out(nv * nc, 0.);
  for (std::size_t v = 0; v < nv; ++v)
    for (std::size_t c = 0; c < nc; ++c) {
      double sum = 0.;
      for (int k = 0; k < around[v]; ++k) sum += field.values[v * nc + c];
      out[v * nc + c] = sum / around[v];
    }
  return out;
}

// The mesh's part of a VTU file, from its start to the triangles' labels (the same for every
// file of one mesh: a run's frames share it, VtuMeshText).
inline std::string vtu_mesh_part(const VtuMesh& mesh) {
  const std::size_t nv = mesh.vertices(), nt = mesh.cells();
  std::string out;
  out += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"  byte_order=\"LittleEndian\">\n";
  out += "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(nv) + "\" NumberOfCells=\" "
         + std::to_string(nt) + "\">\n";
  std::vector<float> points(3 * nv, 0.f);
  for (std::size_t v = 0; v < nv; ++v) {
    points[3 * v] = static_cast<float>(mesh.x[v]);
    points[3 * v + 1] = static_cast<float>(mesh.y[v]);
  }
  out += "<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">\n\t"
         + vtu_binary(points) + "\n</DataArray>\n</Points>\n<Cells>\n";
  std::vector<std::int32_t> connectivity(mesh.triangles.begin(), mesh.triangles.end()), offsets(nt), labels(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    offsets[t] = static_cast<std::int32_t>(3 * (t + 1));
    labels[t] = mesh.labels[t];
  }
  std::vector<std::uint8_t> types(nt, 5);
  out += "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"binary\">\n\t" + vtu_binary(connectivity)
         + "\n</DataArray>\n";
  out += "<DataArray type=\"Int32\" Name=\"offsets\" format=\"binary\">\n    " + vtu_binary(offsets)
         + "\n</DataArray>\n";
  out += "<DataArray type=\"UInt8\" Name=\"types\" format=\"binary\" >\n    " + vtu_binary(types)
         + "\n</DataArray>\n</Cells>\n";
  out += "<CellData Scalars=\"Label\">\n<DataArray type=\"Int32\" Name=\"Label\" format=\"binary\">\n"
         + vtu_binary(labels) + "\n</DataArray>\n";
  return out;
}

// The fields' part of a VTU file (after vtu_mesh_part's text): the cell fields, then the point
// fields (a field of 2 components is a vector, padded with z = 0), and the file's end.
inline void vtu_fields_part(const VtuMesh& mesh, const std::vector<VtuField>& cellFields,
                            const std::vector<VtuField>& pointFields, std::string& out) {
  const std::size_t nv = mesh.vertices();
  // the text's length known ahead (each array's base64 and some 100 characters of markup): one
  // allocation instead of the string's doublings and copies
  std::size_t length = out.size() + 200;
  for (const VtuField& f : cellFields) length += 4 * ((4 + 8 * f.values.size() + 2) / 3) + 100 + f.name.size();
  for (const VtuField& f : pointFields) length += 4 * ((4 + 8 * 3 * nv + 2) / 3) + 100 + f.name.size();
  out.reserve(length);
  std::vector<unsigned char> bytes;
  auto array = [&](const std::string& name, int components, const std::vector<double>& values) {
    out += "<DataArray type=\"Float64\" Name=\"";
    out += name;
    out += "\" NumberOfComponents=\"";
    out += std::to_string(components);
    out += "\" format=\"binary\">\n";
    vtu_binary_append(values, bytes, out);
    out += "\n</DataArray>\n";
  };
  for (const VtuField& f : cellFields) {
    std::vector<double> values(f.values.size());
    // (savevtk evaluates each value as a sum from 0: a -0 is written +0)
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0. + f.values[i];
    array(f.name, f.components, values);
  }
  out += "</CellData>\n<PointData>\n";
  for (const VtuField& f : pointFields) {
    if (f.components == 2) {  // a vector: (x, y, 0)
      VtuField padded{f.name, 3, std::vector<double>(3 * nv, 0.)};
      for (std::size_t v = 0; v < nv; ++v) {
        padded.values[3 * v] = f.values[2 * v];
        padded.values[3 * v + 1] = f.values[2 * v + 1];
      }
      array(f.name, 3, savevtk_vertex_values(mesh, padded));
    } else {
      array(f.name, f.components, savevtk_vertex_values(mesh, f));
    }
  }
  out += "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

// The VTU file of the mesh with its cell fields and point fields, in savevtk's bytes.
inline std::string vtu_file(const VtuMesh& mesh, const std::vector<VtuField>& cellFields,
                            const std::vector<VtuField>& pointFields) {
  std::string out = vtu_mesh_part(mesh);
  vtu_fields_part(mesh, cellFields, pointFields, out);
  return out;
}

// Whether two arrays hold the same bytes (a -0 is not a +0 there: its float is written otherwise).
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// The mesh part of the last mesh written, kept with a copy of that mesh: a file of the same mesh
// (compared value by value, a pass over its arrays) reuses the text instead of converting and
// base64-encoding its points, connectivity, offsets, types and labels again (a third of a sleeve
// frame's encoding). `encodings` counts the texts made.
struct VtuMeshText {
  VtuMesh mesh;
  std::string text;
  long encodings = 0;
  const std::string& of(const VtuMesh& m) {
    if (encodings == 0 || !same_bits(m.x, mesh.x) || !same_bits(m.y, mesh.y) || !same_bits(m.triangles, mesh.triangles)
        || !same_bits(m.labels, mesh.labels)) {
      text = vtu_mesh_part(m);
      mesh = m;
      ++encodings;
    }
    return text;
  }
};

// ---- The output fields' stresses ----
// The in-plane stresses of a P1 displacement u (interleaved: u[2v], u[2v + 1] at vertex v) on each
// triangle, in the arithmetic of FreeFEM's P0 interpolation of edp/lib/elasticity.idp's
//   SigmaXX = lambda * (dx(u1) + dy(u2)) + 2. * mu * dx(u1) - 0,
//   SigmaYY = lambda * (dx(u1) + dy(u2)) + 2. * mu * dy(u2) - 0,   SigmaXY = mu * (dy(u1) + dx(u2)):
// a derivative is the sum from 0, over the triangle's vertices in their local order, of the
// vertex's value times its basis function's derivative (gx, gy: 3 per triangle, in that order, as
// FreeFEM's element computes them). So the values are the same to the last bit, at a fraction of
// the cost of evaluating the expression through the finite-element machinery.
inline void plane_stress_p1(const std::vector<int>& triangles, const std::vector<double>& gx,
                            const std::vector<double>& gy, const double* u, double lambda, double mu,
                            double* sxx, double* syy, double* sxy) {
  const std::size_t nt = triangles.size() / 3;
  const double twoMu = 2. * mu;
  for (std::size_t t = 0; t < nt; ++t) {
    double dxu1 = 0., dyu1 = 0., dxu2 = 0., dyu2 = 0.;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t v = static_cast<std::size_t>(triangles[3 * t + k]);
      dxu1 += u[2 * v] * gx[3 * t + k];
      dyu1 += u[2 * v] * gy[3 * t + k];
      dxu2 += u[2 * v + 1] * gx[3 * t + k];
      dyu2 += u[2 * v + 1] * gy[3 * t + k];
    }
    sxx[t] = lambda * (dxu1 + dyu2) + twoMu * dxu1 - 0.;
    syy[t] = lambda * (dxu1 + dyu2) + twoMu * dyu2 - 0.;
    sxy[t] = mu * (dyu1 + dxu2);
  }
}

// plane_stress_p1's gx (or gy) from the entries of the P0 <- P1 derivative matrix (interpolate(Ph,
// Wh, op = 1) or op = 2), given as triplets in their storage order (row: triangle, column: vertex,
// indices from `shift`): the coefficient of triangle t's k-th vertex is its entry, the entries of
// one (t, v) summed in their order (as Eigen's setFromTriplets, and its coeff, which the glue
// used: the matrix converted at every frame), 0 where there is none; entries off the triangle's
// vertices are not read.
inline std::vector<double> centroid_gradients(const std::vector<int>& triangles, const int* rows, const int* cols,
                                              const double* values, std::size_t nnz, int shift) {
  const std::size_t nt = triangles.size() / 3;
  std::vector<double> g(3 * nt, 0.);
  std::vector<char> seen(3 * nt, 0);
  for (std::size_t e = 0; e < nnz; ++e) {
    const long t = rows[e] - shift, v = cols[e] - shift;
    if (t < 0 || t >= static_cast<long>(nt)) throw std::invalid_argument("a derivative matrix's row is not a triangle");
    for (std::size_t k = 0; k < 3; ++k)
      if (triangles[3 * t + k] == v) {
        g[3 * t + k] = seen[3 * t + k] ? g[3 * t + k] + values[e] : values[e];
        seen[3 * t + k] = 1;
      }
  }
  return g;
}

// ---- CSV rows ----
// x as `stream << x` prints it on a stream of that precision in its default float format, i.e.
// printf's %.<precision>g (the C++ standard defines both so): std::to_chars gives the same
// characters, about ten times faster than the stream (a per-step row of the default run cost 60
// thousand instructions through FreeFEM's <<). An integer-valued x below 10^precision prints as the
// integer: the rows' counts stay as `stream << n` wrote them.
inline void append_general(double x, int precision, std::string& out) {
  char buffer[64];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general,
                                               precision);
  out.append(buffer, r.ptr);
}

// Rows of values separated by commas (no line end), each column's text kept from the row before: a
// value with the same bits at the same precision has the same text (to_chars is a function of
// both), so a column that stands still (a run's tail: the pressures, fractions and counts of a step
// that moved nothing) is copied, not formatted again. A row's text does not depend on the rows
// before (csv_row below: a new formatter's first row).
class CsvRowFormatter {
 public:
  std::string row(const double* values, std::size_t n, int precision) {
    if (columns_.size() < n) columns_.resize(n);
    std::string out;
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0) out += ',';
      Column& c = columns_[i];
      std::uint64_t bits;
      std::memcpy(&bits, &values[i], sizeof bits);
      if (!c.set || c.bits != bits || c.precision != precision) {
        c.text.clear();
        append_general(values[i], precision, c.text);
        c.bits = bits, c.precision = precision, c.set = true;
        ++formatted_;
      }
      out += c.text;
    }
    return out;
  }
  // How many values it formatted (the others' texts were kept).
  std::size_t formatted() const { return formatted_; }

 private:
  struct Column {
    bool set = false;
    std::uint64_t bits = 0;
    int precision = 0;
    std::string text;
  };
  std::vector<Column> columns_;
  std::size_t formatted_ = 0;
};

// values[0], values[1], ... separated by commas (no line end): a formatter's first row.
inline std::string csv_row(const double* values, std::size_t n, int precision) {
  return CsvRowFormatter().row(values, n, precision);
}

}  // namespace sma::output
