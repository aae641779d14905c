#include "inputs/cubic_spline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace pat {

CubicSpline::CubicSpline(std::vector<double> x, const std::vector<double>& y) : x_(std::move(x)) {
  const std::size_t n = x_.size();
  if (n < 2 || y.size() != n) {
    throw std::invalid_argument("CubicSpline: needs at least 2 points and as many y as x");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y[i]) || (i > 0 && !(x_[i] > x_[i - 1]))) {
      throw std::invalid_argument("CubicSpline: x must increase strictly and values be finite");
    }
  }

  // Second derivatives m_i at the knots: m_0 = m_{n-1} = 0 and, for the inner knots,
  // h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1} = 6 (slope_i - slope_{i-1}).
  // Tridiagonal, diagonally dominant: Thomas algorithm without pivoting.
  std::vector<double> h(n - 1), slope(n - 1), m(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = x_[i + 1] - x_[i];
    slope[i] = (y[i + 1] - y[i]) / h[i];
  }
  if (n > 2) {
    const std::size_t inner = n - 2;
    std::vector<double> diag(inner), rhs(inner);
    for (std::size_t k = 0; k < inner; ++k) {
      diag[k] = 2.0 * (h[k] + h[k + 1]);
      rhs[k] = 6.0 * (slope[k + 1] - slope[k]);
    }
    for (std::size_t k = 1; k < inner; ++k) {  // forward elimination; sub = super = h[k]
      const double factor = h[k] / diag[k - 1];
      diag[k] -= factor * h[k];
      rhs[k] -= factor * rhs[k - 1];
    }
    m[inner] = rhs[inner - 1] / diag[inner - 1];
    for (std::size_t k = inner - 1; k-- > 0;) m[k + 1] = (rhs[k] - h[k + 1] * m[k + 2]) / diag[k];
  }

  a_.assign(y.begin(), y.end() - 1);
  b_.resize(n - 1);
  c_.resize(n - 1);
  d_.resize(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    b_[i] = slope[i] - h[i] * (2.0 * m[i] + m[i + 1]) / 6.0;
    c_[i] = 0.5 * m[i];
    d_[i] = (m[i + 1] - m[i]) / (6.0 * h[i]);
  }
  a_.push_back(y.back());  // a_[n-1]: the held end value
}

CubicSpline::Sample CubicSpline::evaluate(double x) const {
  if (x < x_.front()) return {a_.front(), 0.0, 0.0};
  if (x >= x_.back()) return {a_.back(), 0.0, 0.0};
  // The interval i with x_i <= x < x_{i+1}.
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
  const double s = x - x_[i];
  return {a_[i] + s * (b_[i] + s * (c_[i] + s * d_[i])),
          b_[i] + s * (2.0 * c_[i] + 3.0 * s * d_[i]), 2.0 * c_[i] + 6.0 * s * d_[i]};
}

}  // namespace pat
