// The tabulated sin and cos against the library's.
#include "core/table_sincos.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace pat {
namespace {

TEST(TableSincos, MatchesTheLibraryToAboutOneUnitInTheLastPlace) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> inside(-16.0, 16.0), small(-0.02, 0.02);
  // tolerance: two units in the last place of a value of magnitude ≤ 1 (the table entries and
  // the polynomials round once each; the library's own error is below one unit)
  const double tolerance = 2.0 * std::numeric_limits<double>::epsilon();
  auto check = [&](double angle) {
    double c = 0.0, s = 0.0;
    table_sincos(angle, c, s);
    EXPECT_NEAR(c, std::cos(angle), tolerance) << angle;
    EXPECT_NEAR(s, std::sin(angle), tolerance) << angle;
  };
  for (int i = 0; i < 20000; ++i) check(inside(random));
  for (int i = 0; i < 20000; ++i) check(small(random));
  // on the grid, half-way between grid points, and past the table (library fallback)
  for (double angle : {0.0, -0.0, 1.0 / 64.0, 1.5 / 64.0, -2.5 / 64.0, 15.99, -15.99, 17.0, -40.0,
                       1e-300, 3.14159265358979})
    check(angle);
  double c = 0.0, s = 0.0;
  table_sincos(std::nan(""), c, s);
  EXPECT_TRUE(std::isnan(c) && std::isnan(s));
}

}  // namespace
}  // namespace pat
