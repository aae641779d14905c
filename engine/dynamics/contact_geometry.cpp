#include "dynamics/contact_geometry.h"

#include <cmath>

namespace pat {

bool circle_circle_patch(const Vec2& center_a, double radius_a, const Vec2& center_b,
                         double radius_b, ContactPatch& patch) {
  return patch_at(circle_circle_distance(center_a, radius_a, center_b, radius_b), center_a,
                  radius_a, patch);
}

bool circle_segment_patch(const Vec2& center_a, double radius_a, const Vec2& s0, const Vec2& s1,
                          const Vec2& normal, double corner_radius, ContactPatch& patch) {
  const Vec2 u = s1 - s0;
  return patch_at(circle_segment_distance(center_a, radius_a, s0, u, 1.0 / u.squaredNorm(), normal,
                                          corner_radius),
                  center_a, radius_a, patch);
}

double circle_circle_penetration(const Vec2& center_a, double radius_a, const Vec2& center_b,
                                 double radius_b) {
  return circle_circle_distance(center_a, radius_a, center_b, radius_b).penetration;
}

double circle_segment_penetration(const Vec2& center_a, double radius_a, const Vec2& s0,
                                  const Vec2& s1, const Vec2& normal, double corner_radius) {
  const Vec2 u = s1 - s0;
  return circle_segment_distance(center_a, radius_a, s0, u, 1.0 / u.squaredNorm(), normal,
                                 corner_radius)
      .penetration;
}

}  // namespace pat
