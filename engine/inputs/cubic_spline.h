// Natural cubic spline through points (x_i, y_i) with strictly increasing x: twice continuously
// differentiable, zero second derivative at both ends. Units are those of x and y.
#pragma once

#include <cstddef>
#include <vector>

namespace pat {

class CubicSpline {
 public:
  struct Sample {
    double value = 0.0;   ///< y
    double first = 0.0;   ///< dy/dx
    double second = 0.0;  ///< d²y/dx²
  };

  /// Needs at least 2 points, x strictly increasing, all values finite (throws
  /// std::invalid_argument otherwise). With 2 points the spline is the straight line.
  CubicSpline(std::vector<double> x, const std::vector<double>& y);

  /// The spline and its derivatives at x. Outside [x_0, x_n] the end value is held (first and
  /// second derivatives zero; at x_0 itself the spline's own derivatives are returned).
  /// O(log n): binary search for the interval.
  Sample evaluate(double x) const;

  double x_min() const { return x_.front(); }
  double x_max() const { return x_.back(); }

 private:
  // On [x_i, x_{i+1}], with s = x - x_i: y = a_i + b_i s + c_i s² + d_i s³.
  std::vector<double> x_, a_, b_, c_, d_;
};

}  // namespace pat
