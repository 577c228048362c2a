// The plugin's VTU writer (plugin/core/output.hpp): base64 against RFC 4648's test vectors, the
// binary arrays' length header, savevtk's vertex values (a sum over the triangles around a vertex
// divided by their count: not always the vertex's value to the last bit), and the file's layout on
// a two-triangle mesh. The byte-for-byte equality with FreeFEM's savevtk on a whole scene is
// checked by the scenes' runs (the frames of results/sleeve-circular are unchanged by the switch).
#include <gtest/gtest.h>

#include <random>

#include <cmath>
#include <cstdio>
#include <limits>
#include <cstdint>
#include <string>
#include <vector>

#include "core/output.hpp"

namespace out = sma::output;

namespace {

std::string b64(const std::string& text) {
  std::string s;
  out::base64_append(reinterpret_cast<const unsigned char*>(text.data()), text.size(), s);
  return s;
}

// Two triangles sharing the edge (1, 2): vertices 1 and 2 are in both, 0 and 3 in one each.
out::VtuMesh TwoTriangles() {
  out::VtuMesh m;
  m.x = {0, 1, 0, 1};
  m.y = {0, 0, 1, 1};
  m.triangles = {0, 1, 2, 1, 3, 2};
  m.labels = {7, 8};
  return m;
}

}  // namespace

TEST(Output, Base64MatchesRfc4648Vectors) {
  EXPECT_EQ(b64(""), "");
  EXPECT_EQ(b64("f"), "Zg==");
  EXPECT_EQ(b64("fo"), "Zm8=");
  EXPECT_EQ(b64("foo"), "Zm9v");
  EXPECT_EQ(b64("foob"), "Zm9vYg==");
  EXPECT_EQ(b64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(b64("foobar"), "Zm9vYmFy");
  const unsigned char high[] = {0xff, 0xfe, 0xfd};  // the digits 62 and 63 and the high bits
  std::string s;
  out::base64_append(high, 3, s);
  EXPECT_EQ(s, "//79");
}

TEST(Output, BinaryArrayStartsWithItsByteLength) {
  // [4, 0, 0, 0] (the length of one int32) then [1, 0, 0, 0]
  EXPECT_EQ(out::vtu_binary(std::vector<std::int32_t>{1}), "BAAAAAEAAAA=");
  // an empty array is its length alone: 4 zero bytes
  EXPECT_EQ(out::vtu_binary(std::vector<double>{}), "AAAAAA==");
  // 3 bytes of UInt8: length 3, then 5 5 5 (7 bytes in all: one '=')
  EXPECT_EQ(out::vtu_binary(std::vector<std::uint8_t>{5, 5, 5}), "AwAAAAUFBQ==");
}

TEST(Output, VertexValuesAreSavevtkSumsOverTrianglesDividedByTheirCount) {
  out::VtuMesh m = TwoTriangles();
  m.triangles = {0, 1, 2, 1, 3, 2, 2, 1, 0};  // a third triangle: vertices 1 and 2 in three, 0 in two
  m.labels = {1, 1, 1};
  out::VtuField f{"v", 1, {0.1, 0.1, -0.0, 2.5}};
  const std::vector<double> v = out::savevtk_vertex_values(m, f);
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[0], (0. + 0.1 + 0.1) / 2);         // exactly 0.1: 2 x 0.1 is exact
  const double three = 0. + 0.1 + 0.1 + 0.1;     // 0.30000000000000004
  EXPECT_EQ(v[1], three / 3);
  EXPECT_NE(v[1], 0.1);                           // the rule, not the vertex's value
  EXPECT_EQ(v[2], 0.);
  EXPECT_FALSE(std::signbit(v[2]));               // a -0 summed from +0 is +0
  EXPECT_EQ(v[3], 2.5);
  // a vertex of no triangle: 0 / 0, as savevtk
  m.x.push_back(2); m.y.push_back(2);
  f.values.push_back(1.);
  EXPECT_TRUE(std::isnan(out::savevtk_vertex_values(m, f)[4]));
}

TEST(Output, VtuFileHasSavevtksLayout) {
  const out::VtuMesh m = TwoTriangles();
  const std::vector<out::VtuField> cells = {{"c", 1, {-0.0, 1.5}}};
  const std::vector<out::VtuField> points = {{"u", 2, {1, 2, 3, 4, 5, 6, 7, 8}}, {"T", 1, {1, 2, 3, 4}}};
  const std::string text = out::vtu_file(m, cells, points);
  const std::string expectedStart =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"  byte_order=\"LittleEndian\">\n"
      "<UnstructuredGrid>\n<Piece NumberOfPoints=\"4\" NumberOfCells=\" 2\">\n<Points>\n"
      "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">\n\t";
  EXPECT_EQ(text.substr(0, expectedStart.size()), expectedStart);
  std::vector<float> points3 = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  EXPECT_NE(text.find("\t" + out::vtu_binary(points3) + "\n</DataArray>\n</Points>\n<Cells>\n"), std::string::npos);
  EXPECT_NE(text.find("Name=\"connectivity\" format=\"binary\">\n\t"
                      + out::vtu_binary(std::vector<std::int32_t>{0, 1, 2, 1, 3, 2})),
            std::string::npos);
  EXPECT_NE(text.find("Name=\"offsets\" format=\"binary\">\n    " + out::vtu_binary(std::vector<std::int32_t>{3, 6})),
            std::string::npos);
  EXPECT_NE(text.find("Name=\"types\" format=\"binary\" >\n    " + out::vtu_binary(std::vector<std::uint8_t>{5, 5})),
            std::string::npos);
  EXPECT_NE(text.find("<CellData Scalars=\"Label\">\n<DataArray type=\"Int32\" Name=\"Label\" format=\"binary\">\n"
                      + out::vtu_binary(std::vector<std::int32_t>{7, 8})),
            std::string::npos);
  // the cell field's -0 written +0
  EXPECT_NE(text.find("<DataArray type=\"Float64\" Name=\"c\" NumberOfComponents=\"1\" format=\"binary\">\n"
                      + out::vtu_binary(std::vector<double>{0., 1.5}) + "\n</DataArray>\n</CellData>\n<PointData>\n"),
            std::string::npos);
  // the vector padded to 3 components; vertices 1 and 2 in two triangles: (v + v) / 2 = v exactly
  EXPECT_NE(text.find("Name=\"u\" NumberOfComponents=\"3\" format=\"binary\">\n"
                      + out::vtu_binary(std::vector<double>{1, 2, 0, 3, 4, 0, 5, 6, 0, 7, 8, 0})),
            std::string::npos);
  const std::string expectedEnd = "Name=\"T\" NumberOfComponents=\"1\" format=\"binary\">\n"
                                  + out::vtu_binary(std::vector<double>{1, 2, 3, 4})
                                  + "\n</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  ASSERT_GE(text.size(), expectedEnd.size());
  EXPECT_EQ(text.substr(text.size() - expectedEnd.size()), expectedEnd);
}

// The mesh part and the fields part make the file (the frames write a kept mesh part and their
// fields); the kept text is remade when any value of the mesh changes, also a +0 turned -0 (its
// float has other bits), and only then.
TEST(Output, MeshTextIsKeptForTheSameMeshAndRemadeForAnother) {
  out::VtuMesh m = TwoTriangles();
  const std::vector<out::VtuField> cells = {{"c", 1, {-0.0, 1.5}}};
  const std::vector<out::VtuField> points = {{"u", 2, {1, 2, 3, 4, 5, 6, 7, 8}}, {"T", 1, {1, 2, 3, 4}}};
  out::VtuMeshText kept;
  std::string text = kept.of(m);
  out::vtu_fields_part(m, cells, points, text);
  EXPECT_EQ(text, out::vtu_file(m, cells, points));
  EXPECT_EQ(kept.of(m), out::vtu_mesh_part(m));
  EXPECT_EQ(kept.encodings, 1);
  const out::VtuMesh first = m;
  m.x[0] = -0.0;  // == +0, other bytes in the file
  EXPECT_NE(out::vtu_mesh_part(m), out::vtu_mesh_part(first));
  EXPECT_EQ(kept.of(m), out::vtu_mesh_part(m));
  EXPECT_EQ(kept.encodings, 2);
  m.labels[1] = 9;
  EXPECT_EQ(kept.of(m), out::vtu_mesh_part(m));
  m.triangles = {0, 2, 1, 1, 3, 2};
  EXPECT_EQ(kept.of(m), out::vtu_mesh_part(m));
  EXPECT_EQ(kept.encodings, 4);
  EXPECT_EQ(kept.of(first), out::vtu_mesh_part(first));
  EXPECT_EQ(kept.of(first), out::vtu_mesh_part(first));
  EXPECT_EQ(kept.encodings, 5);
}

// The derivative coefficients read from a matrix's triplets: each (triangle, vertex) entry at the
// triangle's local vertex, repeated entries summed in their order (0.1 + 0.2 + 0.3 is not 0.1 +
// (0.2 + 0.3)), none: 0, an entry off the triangle's vertices ignored, indices from 1 (fortran).
TEST(Output, CentroidGradientsAreTheMatrixEntriesAtEachTrianglesVertices) {
  const std::vector<int> triangles = {0, 1, 2, 1, 3, 2};
  const std::vector<int> rows = {1, 0, 0, 1, 1, 1, 0, 1};
  const std::vector<int> cols = {2, 1, 0, 3, 3, 3, 3, 1};
  const std::vector<double> values = {-2., 5., 4., 0.1, 0.2, 0.3, 99., 7.};
  const std::vector<double> g = out::centroid_gradients(triangles, rows.data(), cols.data(), values.data(), 8, 0);
  ASSERT_EQ(g.size(), 6u);
  EXPECT_EQ(g[0], 4.);   // triangle 0, vertex 0
  EXPECT_EQ(g[1], 5.);   // vertex 1
  EXPECT_EQ(g[2], 0.);   // vertex 2: no entry
  EXPECT_EQ(g[3], 7.);   // triangle 1, vertex 1
  EXPECT_EQ(g[4], (0.1 + 0.2) + 0.3);
  EXPECT_NE(g[4], 0.1 + (0.2 + 0.3));
  EXPECT_EQ(g[5], -2.);
  std::vector<int> rows1 = rows, cols1 = cols;
  for (int& r : rows1) ++r;
  for (int& c : cols1) ++c;
  EXPECT_EQ(out::centroid_gradients(triangles, rows1.data(), cols1.data(), values.data(), 8, 1), g);
  const std::vector<int> badRow = {2};
  EXPECT_THROW(out::centroid_gradients(triangles, badRow.data(), cols.data(), values.data(), 1, 0),
               std::invalid_argument);
}

// The CSV rows: every value in the characters printf's %.<precision>g gives (what an ostream of
// that precision prints in its default format), checked against snprintf itself on awkward values
// and on 250000 pseudo-random doubles of every magnitude.
TEST(Output, CsvNumbersAreThoseOfPrintfG) {
  std::vector<double> values = {0., -0., 1., -1., 0.1, 1500., 156444166.454321, 1e-300, 4.9e-324, 2.2250738585072014e-308,
                                1.7976931348623157e308, 123456789012., 1234567890123., 0.000123456789012345,
                                1e-5, 1e-4, 99999999999.95, 999999999999.5, -7.48099499015e-18, 257.534209213,
                                std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  std::uint64_t state = 0x9e3779b97f4a7c15ull;
  for (int i = 0; i < 250000; ++i) {  // xorshift64: random bit patterns, NaNs skipped
    state ^= state << 13; state ^= state >> 7; state ^= state << 17;
    double x;
    std::memcpy(&x, &state, sizeof x);
    if (!std::isnan(x)) values.push_back(x);
  }
  for (int precision : {6, 10, 12, 17}) {
    for (double x : values) {
      char expected[64];
      std::snprintf(expected, sizeof expected, "%.*g", precision, x);
      std::string got;
      out::append_general(x, precision, got);
      ASSERT_EQ(got, expected) << "precision " << precision;
    }
  }
}

TEST(Output, CsvRowSeparatesByCommasWithoutLineEnd) {
  const double row[] = {1, 0.1, -2.5e-7, 1500};
  EXPECT_EQ(out::csv_row(row, 4, 12), "1,0.1,-2.5e-07,1500");
  EXPECT_EQ(out::csv_row(row, 0, 12), "");
}

// The row formatter keeps each column's text for its next row: every row must read as csv_row's,
// whatever came before (a column that stands, one that changes, a zero's sign, a NaN, a row of
// another length, another precision).
TEST(Output, CsvRowFormatterGivesCsvRowsText) {
  std::mt19937 random(12);
  std::uniform_int_distribution<int> pick(0, 5);
  const double values[] = {1500, 0.1, -2.5e-7, 0.0, -0.0, std::nan(""), 1.0 / 3.0, 156444166.454};
  out::CsvRowFormatter formatter;
  std::vector<double> row(6, 0.0);
  std::size_t cells = 0;
  for (int r = 0; r < 400; ++r) {
    const std::size_t n = r % 50 == 49 ? 3 : row.size();
    for (std::size_t i = 0; i < n; ++i)
      if (pick(random) == 0) row[i] = values[std::uniform_int_distribution<int>(0, 7)(random)];
    const int precision = r % 100 == 99 ? 6 : 12;
    ASSERT_EQ(formatter.row(row.data(), n, precision), out::csv_row(row.data(), n, precision)) << "row " << r;
    cells += n;
  }
  // (a sixth of the values change a row: most texts were kept, not formatted again)
  EXPECT_LT(formatter.formatted(), cells / 3);
  const double zeros[] = {0.0, -0.0};
  EXPECT_EQ(formatter.row(zeros, 2, 12), "0,-0");
  const double swapped[] = {-0.0, 0.0};
  EXPECT_EQ(formatter.row(swapped, 2, 12), "-0,0");
}

// The output fields' stresses: on a linear displacement u = (a x + b y, c x + d y) every triangle
// has the exact strain (a, d, (b + c) / 2), whatever its shape, with the basis functions'
// derivatives computed here from the triangles' geometry (grad l_k = perp(opposite edge) / 2 area).
TEST(Output, PlaneStressOfALinearDisplacementIsHookesLaw) {
  const std::vector<double> x = {0, 1, 0.2, 1.3}, y = {0, 0.1, 1, 0.9};
  const std::vector<int> triangles = {0, 1, 2, 1, 3, 2};
  const double a = 1e-3, b = -2e-4, c = 5e-4, d = 3e-4, lambda = 1.2e11, mu = 0.8e11;
  std::vector<double> u(8), gx(6), gy(6);
  for (int v = 0; v < 4; ++v) {
    u[2 * v] = a * x[v] + b * y[v];
    u[2 * v + 1] = c * x[v] + d * y[v];
  }
  for (int t = 0; t < 2; ++t) {
    const int* p = &triangles[3 * t];
    const double area2 = (x[p[1]] - x[p[0]]) * (y[p[2]] - y[p[0]]) - (x[p[2]] - x[p[0]]) * (y[p[1]] - y[p[0]]);
    for (int k = 0; k < 3; ++k) {
      const int i = p[(k + 1) % 3], j = p[(k + 2) % 3];  // the edge opposite vertex k
      gx[3 * t + k] = (y[i] - y[j]) / area2;
      gy[3 * t + k] = (x[j] - x[i]) / area2;
    }
  }
  std::vector<double> sxx(2), syy(2), sxy(2);
  out::plane_stress_p1(triangles, gx, gy, u.data(), lambda, mu, sxx.data(), syy.data(), sxy.data());
  for (int t = 0; t < 2; ++t) {
    EXPECT_NEAR(sxx[t], lambda * (a + d) + 2 * mu * a, 1e-9 * mu * a);
    EXPECT_NEAR(syy[t], lambda * (a + d) + 2 * mu * d, 1e-9 * mu * a);
    EXPECT_NEAR(sxy[t], mu * (b + c), 1e-9 * mu * a);
  }
}
