// The tabulated exponential against the library's.
#include "core/table_exp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace pat {
namespace {

TEST(TableExp, TableHoldsTwoToTheJOver64) {
  for (int j = 0; j < table_exp_detail::kPerOctave; ++j) {
    const double hi = table_exp_detail::kTwoTo[j][0], lo = table_exp_detail::kTwoTo[j][1];
    EXPECT_EQ(hi, std::exp2(j / 64.0)) << j;
    // hi + lo against the long double exp2 (64-bit significand, within about 1e-19 relative
    // where long double is wider than double; elsewhere only |lo| ≤ half a unit of hi is checked)
    const long double exact = std::exp2(static_cast<long double>(j) / 64);
    const double tolerance = sizeof(long double) > sizeof(double) ? 1e-18 : 1.2e-16;
    EXPECT_NEAR(static_cast<double>((static_cast<long double>(hi) + lo - exact) / exact), 0.0,
                tolerance)
        << j;
  }
}

TEST(TableExp, MatchesTheLibraryToAboutOneUnitInTheLastPlace) {
  std::mt19937 random(7);
  // the force laws' arguments: felt curves b x (up to about 10), the tanh's −2|x| down to −38
  std::uniform_real_distribution<double> laws(-40.0, 12.0), small(-0.01, 0.01), wide(-700, 700);
  // tolerance: two units in the last place of the result (the table entry and the last two
  // operations round once each; the library's own error is below one unit)
  const double eps = std::numeric_limits<double>::epsilon();
  auto check = [&](double x) {
    const double expected = std::exp(x);
    EXPECT_NEAR(table_exp(x), expected, 2.0 * eps * expected) << x;
  };
  for (int i = 0; i < 50000; ++i) check(laws(random));
  for (int i = 0; i < 20000; ++i) check(small(random));
  for (int i = 0; i < 20000; ++i) check(wide(random));
  // on table points, half-way between them (the rounding of k), near 0 and at the range's ends
  const double step = std::log(2.0) / 64.0;
  for (double x : {0.0, -0.0, 1e-300, -1e-300, 1e-17, step, 0.5 * step, -0.5 * step, 1.5 * step,
                   -38.0, 1.0, -1.0, 700.0, -700.0})
    check(x);
  EXPECT_EQ(table_exp(0.0), 1.0);
}

TEST(TableExp, OutsideItsRangeIsTheLibrarys) {
  for (double x : {701.0, -701.0, 709.0, -745.0, 1e4, -1e4})
    EXPECT_EQ(table_exp(x), std::exp(x)) << x;
  EXPECT_EQ(table_exp(std::numeric_limits<double>::infinity()),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(table_exp(-std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_TRUE(std::isnan(table_exp(std::nan(""))));
}

}  // namespace
}  // namespace pat
