// The certified "still apart" test of the contacts (contact_cull.h) against exact distances.
#include <gtest/gtest.h>

#include "dynamics/action_dynamics.h"
#include "test_support.h"

namespace pat {
namespace {

TEST(ContactCull, BoundsNeverHideATouchingContact) {
  // Along forte double blows sampled every 0.1 ms (every contact opens and closes), the culled
  // dynamics' penetrations must be the exact ones wherever a contact touches, and upper bounds of
  // the exact ones (negative) wherever they are culled. The exact values come from a second
  // object whose contact_penetrations() computes every distance.
  for (const std::string name : {"grand", "upright"}) {
    const ActionModel model = test::shipped(name);
    const RestState rest = find_rest_state(model);
    const SimulationResult run = test::run(model, "force:double:40:30:50", 0.25);
    ActionDynamics culled(model, nullptr), exact(model, nullptr);
    std::vector<double> bounds, truth;
    int culled_count = 0, touching_count = 0;
    for (const std::vector<double>& row : run.trace.rows) {
      DofVector q(model.dofs());
      for (int k = 0; k < model.dofs(); ++k)
        q[k] = rest.q[k] + rad(row[1 + k]) * model.bodies[k].trace_sign;
      culled.contact_penetration_bounds(q, bounds);
      exact.contact_penetrations(q, truth);
      for (std::size_t c = 0; c < truth.size(); ++c) {
        if (truth[c] > 0.0) {
          EXPECT_EQ(bounds[c], truth[c]) << name << " contact " << c << " t " << row[0];
          ++touching_count;
        } else {
          EXPECT_LE(bounds[c], 0.0) << name << " contact " << c << " t " << row[0];
          // the bound is a sum of rounded terms: allow rounding (1e-15 m)
          EXPECT_GE(bounds[c], truth[c] - 1e-15) << name << " contact " << c << " t " << row[0];
          if (bounds[c] != truth[c]) ++culled_count;
        }
      }
    }
    // the test exercises both cases
    EXPECT_GT(culled_count, 1000) << name;
    EXPECT_GT(touching_count, 1000) << name;
  }
}

}  // namespace
}  // namespace pat
