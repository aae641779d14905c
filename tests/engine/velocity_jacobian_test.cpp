// The closed-form velocity block of the Jacobian (ActionDynamics::velocity_jacobian) against
// forward differences of the right-hand side.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dynamics/action_dynamics.h"
#include "integrators/w_method.h"
#include "test_support.h"

namespace pat {
namespace {

TEST(VelocityJacobian, MatchesFiniteDifferencesOfTheRightHandSide) {
  // Configurations along a forte double blow (contacts engaged and apart), with small random
  // joint rates (|q̇| ≤ 1e-3 rad/s). The closed form leaves out the velocity-dependent inertia
  // terms ∂c/∂q̇, which are linear in q̇: at these rates they are below ~1e-2 s⁻¹, while the
  // entries that matter (felt hysteresis, contact and joint friction) reach 1e3–1e5 s⁻¹. The
  // rates also keep every contact on one side of its kinks (ẋ = 0, slip = 0) for the
  // finite-difference increment (~1.5e-9 rad/s). Each entry is held to its own size (the block
  // spans 1e-1 to 2e7 s⁻¹, and a joint friction's 76–276 s⁻¹ would hide under a tolerance scaled
  // by the block's largest, a felt's): 1e-5 relative (the differences' truncation, measured at
  // most 4e-7 of the large entries) plus 0.05 s⁻¹ (their rounding, ε·|q̈ terms|/increment with
  // terms up to ~1e5 rad/s², about 0.015 s⁻¹, and the ∂c/∂q̇ left out; measured at most 0.026).
  for (const std::string name : {"grand", "upright"}) {
    const ActionModel model = test::shipped(name);
    const RestState rest = find_rest_state(model);
    const auto input = parse_input_spec("force:const:30", input_context(model, rest));
    const SimulationResult run = test::run(model, "force:double:40:30:50", 0.25);
    ActionDynamics dynamics(model, input.get());
    const int n = model.dofs();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> rate(-1e-3, 1e-3);
    int compared = 0;
    for (std::size_t row = 0; row < run.trace.rows.size(); row += 20) {
      DofVector q(n), v(n);
      for (int k = 0; k < n; ++k) {
        q[k] = rest.q[k] + rad(run.trace.rows[row][1 + k]) * model.bodies[k].trace_sign;
        v[k] = rate(random);
      }
      const StateVector y = dynamics.compress(q, v);
      StateVector f0, y_work, f_work;
      StateMatrix finite, closed = StateMatrix::Zero(2 * n, 2 * n);
      dynamics.rhs(0.01, y, f0);
      ASSERT_TRUE(dynamics.velocity_jacobian(closed));
      forward_difference_jacobian(dynamics, 0.01, y, f0, y_work, f_work, finite);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          EXPECT_NEAR(closed(n + i, n + j), finite(n + i, n + j),
                      1e-5 * std::abs(finite(n + i, n + j)) + 0.05)
              << name << " row " << row << " entry " << i << "," << j;
      // the other blocks are left alone
      EXPECT_EQ(closed.topRows(n).cwiseAbs().maxCoeff(), 0.0);
      ++compared;
    }
    EXPECT_GE(compared, 10);
  }
}

}  // namespace
}  // namespace pat
