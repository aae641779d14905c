#include "measured/alignment.h"

#include <cmath>
#include <limits>

namespace pat {
namespace {

/// Σ r² after removing the mean, for a shift δt (fills mean).
double shifted_cost(const MeasuredTrial& trial, const ModelTrace& model, double shift,
                    double& mean) {
  double sum = 0.0, sum2 = 0.0;
  const std::size_t n = trial.t.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double r = trial.hammer_deg[i] - model.hammer_at(trial.t[i] - shift);
    sum += r;
    sum2 += r * r;
  }
  mean = sum / static_cast<double>(n);
  return sum2 - sum * mean;
}

}  // namespace

Alignment align(const MeasuredTrial& trial, const ModelTrace& model, double max_shift_s) {
  const double grid = 2e-4;
  double best_shift = 0.0, best = std::numeric_limits<double>::infinity(), mean = 0.0;
  for (double s = -max_shift_s; s <= max_shift_s + 1e-12; s += grid) {
    const double c = shifted_cost(trial, model, s, mean);
    if (c < best) best = c, best_shift = s;
  }
  Alignment out;
  out.time_offset_s = max_shift_s > 0.0 ? best_shift : 0.0;  // not the grid's −0
  if (max_shift_s > 0.0) {  // with none searched, the model's clock is the file's
    // golden-section refinement in [best − grid, best + grid]
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = best_shift - grid, b = best_shift + grid;
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double f1 = shifted_cost(trial, model, x1, mean), f2 = shifted_cost(trial, model, x2, mean);
    for (int it = 0; it < 12; ++it) {
      if (f1 < f2) {
        b = x2, x2 = x1, f2 = f1;
        x1 = b - g * (b - a);
        f1 = shifted_cost(trial, model, x1, mean);
      } else {
        a = x1, x1 = x2, f1 = f2;
        x2 = a + g * (b - a);
        f2 = shifted_cost(trial, model, x2, mean);
      }
    }
    if (std::min(f1, f2) < best) out.time_offset_s = f1 < f2 ? x1 : x2;
  }
  shifted_cost(trial, model, out.time_offset_s, mean);
  out.angle_offset_deg = mean;
  out.residual.resize(trial.t.size());
  for (std::size_t i = 0; i < trial.t.size(); ++i) {
    out.residual[i] = trial.hammer_deg[i] - model.hammer_at(trial.t[i] - out.time_offset_s) - mean;
    out.rss += out.residual[i] * out.residual[i];
  }
  return out;
}

Alignment referenced_to_rest(const Alignment& alignment, const std::vector<bool>& at_rest) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < alignment.residual.size() && i < at_rest.size(); ++i)
    if (at_rest[i]) {
      sum += alignment.residual[i];
      ++count;
    }
  if (count < kMinRestSamplesForOffset) return alignment;
  const double shift = sum / static_cast<double>(count);
  Alignment out = alignment;
  out.angle_offset_deg += shift;
  out.rss = 0.0;
  for (double& r : out.residual) {
    r -= shift;
    out.rss += r * r;
  }
  return out;
}

}  // namespace pat
