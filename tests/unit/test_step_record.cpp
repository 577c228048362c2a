// The fraction model's step record (plugin/core/step_record.hpp) against the script's formulas
// computed here independently, on small hand-made operators.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/step_record.hpp"

namespace {

// y = M x for a dense row-major M (rows x cols).
struct Dense {
  std::vector<double> a;
  std::size_t rows, cols;
  void operator()(const double* x, double* y) const {
    for (std::size_t i = 0; i < rows; ++i) {
      double s = 0;
      for (std::size_t j = 0; j < cols; ++j) s += a[i * cols + j] * x[j];
      y[i] = s;
    }
  }
};

const sma::ThermalLaw law{6500, 300, 12000, 237, 300};

TEST(StepRecord, LoadStressAndFractionsAsTheScriptComputesThem) {
  // 3 points, 2 heat nodes: Q (2 x 3) spreads a point's load over nodes, Interp (3 x 2) averages.
  const Dense Q{{0.5, 0.25, 0.0, 0.5, 0.75, 1.0}, 2, 3};
  const Dense interp{{1.0, 0.0, 0.5, 0.5, 0.0, 1.0}, 3, 2};
  std::vector<double> chi = {0.25, -0.5, 0.0}, b = {0.0, 0.75, 0.0}, T = {250.0, 320.0};
  std::vector<double> load(2), s(3);
  const double rate = 6500.0 * 12000.0 / 0.1;
  sma::fraction_step_record(law, rate, sma::span<const double>(chi.data(), 3), sma::span<double>(b),
                            sma::span<const double>(T.data(), 2), Q, interp, sma::span<double>(load),
                            sma::span<double>(s));
  // b = |chi|; load = Q (|chi| - b_old) rate: changes 0.25, -0.25, 0
  EXPECT_EQ(b, (std::vector<double>{0.25, 0.5, 0.0}));
  EXPECT_DOUBLE_EQ(load[0], (0.5 * 0.25 - 0.25 * 0.25) * rate);
  EXPECT_DOUBLE_EQ(load[1], (0.5 * 0.25 - 0.75 * 0.25) * rate);
  // s = alpha(T at the point) chi: 250 K (alpha > 0), 285 K (alpha > 0), 320 K (above Tc: 0)
  EXPECT_DOUBLE_EQ(s[0], 6500.0 * 300.0 * (300.0 - 250.0) * 0.25);
  EXPECT_DOUBLE_EQ(s[1], 6500.0 * 300.0 * (300.0 - 285.0) * -0.5);
  EXPECT_EQ(s[2], 0.0);
}

TEST(StepRecord, NoChangeNoLoad) {
  // The fractions the last heat solve saw are the step's: no latent heat, whatever the operators.
  const Dense Q{{2.0, 3.0}, 1, 2};
  const Dense interp{{1.0}, 2, 1};
  std::vector<double> chi = {-1.0, 0.5}, b = {1.0, 0.5}, T = {200.0}, load(1), s(2);
  sma::fraction_step_record(law, 1e9, sma::span<const double>(chi.data(), 2), sma::span<double>(b),
                            sma::span<const double>(T.data(), 1), Q, interp, sma::span<double>(load),
                            sma::span<double>(s));
  EXPECT_EQ(load[0], 0.0);
  EXPECT_EQ(b, (std::vector<double>{1.0, 0.5}));
}

TEST(StepRecord, MismatchedSizesAndBadLawAreRefused) {
  const Dense Q{{1.0}, 1, 1};
  std::vector<double> chi = {0.5}, b = {0.0, 0.0}, T = {250.0}, load(1), s(1);
  EXPECT_THROW(sma::fraction_step_record(law, 1.0, sma::span<const double>(chi.data(), 1), sma::span<double>(b),
                                         sma::span<const double>(T.data(), 1), Q, Q, sma::span<double>(load),
                                         sma::span<double>(s)),
               std::invalid_argument);
  b.resize(1);
  const sma::ThermalLaw hot{6500, 300, 12000, 400, 300};  // T0 > Tc
  EXPECT_THROW(sma::fraction_step_record(hot, 1.0, sma::span<const double>(chi.data(), 1), sma::span<double>(b),
                                         sma::span<const double>(T.data(), 1), Q, Q, sma::span<double>(load),
                                         sma::span<double>(s)),
               std::invalid_argument);
}

}  // namespace

namespace {

TEST(StepRecord, AreaFractionsOfSignedFractions) {
  // 4 points: austenite, all martensite 1, half martensite 2, a quarter martensite 1.
  std::vector<double> chi = {0.0, 1.0, -0.5, 0.25}, area = {1.0, 2.0, 4.0, 8.0};
  double f[3];
  sma::area_fractions(sma::span<const double>(chi.data(), 4), sma::span<const double>(area.data(), 4), f);
  const double total = 15.0;
  EXPECT_DOUBLE_EQ(f[1], (2.0 * 1.0 + 8.0 * 0.25) / total);  // martensite 1: 4 of 15
  EXPECT_DOUBLE_EQ(f[2], (4.0 * 0.5) / total);               // martensite 2: 2 of 15
  EXPECT_DOUBLE_EQ(f[0], 1.0 - 6.0 / total);                 // the rest austenite
  EXPECT_NEAR(f[0] + f[1] + f[2], 1.0, 1e-15);
  std::vector<double> shortArea = {1.0};
  EXPECT_THROW(sma::area_fractions(sma::span<const double>(chi.data(), 4),
                                   sma::span<const double>(shortArea.data(), 1), f),
               std::invalid_argument);
}

}  // namespace

namespace {

TEST(StepRecord, PhaseLabelsAreTheSignOfChi) {
  // a partly transformed point carries its martensite's label; a signed zero and a NaN are austenite
  std::vector<double> chi = {0.0, -0.0, 1e-300, -1e-300, 0.5, -1.0, std::nan("")}, labels(7, -1.0);
  sma::phase_labels(sma::span<const double>(chi.data(), 7), sma::span<double>(labels));
  EXPECT_EQ(labels, (std::vector<double>{0, 0, 1, 2, 1, 2, 0}));
  std::vector<double> shortLabels(6);
  EXPECT_THROW(sma::phase_labels(sma::span<const double>(chi.data(), 7), sma::span<double>(shortLabels)),
               std::invalid_argument);
}

TEST(StepRecord, StepDataSegmentsAtTheSolversLayout) {
  // 2 points, 3 heat nodes, 4 dofs: data = [area | kappa | offset | chi | b | rhs | mask | force | free];
  // the five a step changes are written at their offsets, the run's four kept, bit for bit.
  const std::size_t n = 2, nodes = 3, dofs = 4, size = 5 * n + 2 * nodes + 2 * dofs;
  std::vector<double> data(size);
  for (std::size_t i = 0; i < size; ++i) data[i] = -1.0 - double(i);  // the run's values, to be kept
  std::vector<double> chi = {0.25, -0.0}, b = {0.5, 1.0 / 3.0}, rhs = {1e300, -2.5, 3.0}, mask = {1, 0, 1},
                      force = {0.1, 0.2, 0.3, 0.4};
  std::vector<double> expected = data;
  std::copy(chi.begin(), chi.end(), expected.begin() + 3 * n);
  std::copy(b.begin(), b.end(), expected.begin() + 4 * n);
  std::copy(rhs.begin(), rhs.end(), expected.begin() + 5 * n);
  std::copy(mask.begin(), mask.end(), expected.begin() + 5 * n + nodes);
  std::copy(force.begin(), force.end(), expected.begin() + 5 * n + 2 * nodes);
  sma::set_step_data(sma::span<double>(data), chi, b, rhs, mask, force);
  for (std::size_t i = 0; i < size; ++i) EXPECT_EQ(data[i], expected[i]) << "at " << i;
  EXPECT_TRUE(std::signbit(data[3 * n + 1]));  // -0 stays -0 (a copy, not arithmetic)
  // the area, kappa, offset and free segments untouched
  for (std::size_t i = 0; i < 3 * n; ++i) EXPECT_EQ(data[i], -1.0 - double(i));
  for (std::size_t i = 5 * n + 2 * nodes + dofs; i < size; ++i) EXPECT_EQ(data[i], -1.0 - double(i));
  // a data array of another layout, or b not one value per point: refused
  std::vector<double> shortData(size - 1), shortB = {0.5};
  EXPECT_THROW(sma::set_step_data(sma::span<double>(shortData), chi, b, rhs, mask, force), std::invalid_argument);
  EXPECT_THROW(sma::set_step_data(sma::span<double>(data), chi, shortB, rhs, mask, force), std::invalid_argument);
}

}  // namespace

namespace {

TEST(StepRecord, AllAusteniteStressIsChiWithoutTheInterpolation) {
  // Every chi zero (of either sign): s = alpha(Interp T) chi is a zero of chi's sign, alpha >= 0
  // finite; the record skips the interpolation then, and only then, with the same bits.
  const Dense Q{{0.5, 0.25, 0.0, 0.5, 0.75, 1.0}, 2, 3};
  const Dense interp{{1.0, 0.0, 0.5, 0.5, 0.0, 1.0}, 3, 2};
  const std::vector<double> chi = {0.0, -0.0, 0.0};
  auto run = [&](const sma::ThermalLaw& lawUsed, std::vector<double> T, int& calls) {
    std::vector<double> b = {0.0, 0.0, 0.0}, load(2, 7.0), s(3, 7.0);
    calls = 0;
    auto counted = [&](const double* x, double* y) { ++calls; interp(x, y); };
    sma::fraction_step_record(lawUsed, 1.0, sma::span<const double>(chi.data(), 3), sma::span<double>(b),
                              sma::span<const double>(T.data(), 2), Q, counted, sma::span<double>(load),
                              sma::span<double>(s));
    EXPECT_EQ(load, (std::vector<double>{0.0, 0.0}));
    return s;
  };
  // T below Tc at one node, above at the other: alpha > 0 and alpha = 0 at the points
  for (const std::vector<double>& T : {std::vector<double>{250.0, 320.0}, std::vector<double>{300.0, 300.0}}) {
    int calls = -1;
    const std::vector<double> s = run(law, T, calls);
    EXPECT_EQ(calls, 0);
    for (int i = 0; i < 3; ++i) {
      const double Tq = interp.a[2 * i] * T[0] + interp.a[2 * i + 1] * T[1];
      const double expected = law.alpha(Tq) * chi[i];  // the interpolated path's formula
      EXPECT_EQ(s[i], expected) << i;
      EXPECT_EQ(std::signbit(s[i]), std::signbit(expected)) << i;
    }
  }
  // Not skipped: a NaN or an unbounded temperature, a law with a = 0 (alpha = +0 or -0 times a zero)
  int calls = -1;
  run(law, {std::nan(""), 250.0}, calls);
  EXPECT_EQ(calls, 1);
  run(law, {1e300, 250.0}, calls);
  EXPECT_EQ(calls, 1);
  const sma::ThermalLaw noA{6500, 0.0, 12000, 237, 300};
  run(noA, {250.0, 320.0}, calls);
  EXPECT_EQ(calls, 1);
  // (the first test's chi has points not austenite: its interpolation ran)
  EXPECT_FALSE(sma::alpha_finite_at(noA, std::vector<double>{250.0}));
  EXPECT_TRUE(sma::alpha_finite_at(law, std::vector<double>{250.0, -1e100}));
}

}  // namespace
