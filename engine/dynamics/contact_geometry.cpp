#include "dynamics/contact_geometry.h"

#include <cmath>

namespace pat {

bool circle_circle_patch(const Vec2& center_a, double radius_a, const Vec2& center_b,
                         double radius_b, ContactPatch& patch) {
  const Vec2 d = center_a - center_b;
  const double reach = radius_a + radius_b;
  const double dist2 = d.squaredNorm();
  if (dist2 >= reach * reach) return false;
  const double dist = std::sqrt(dist2);
  patch.penetration = reach - dist;
  patch.normal = dist > 1e-12 ? Vec2(d / dist) : Vec2(0.0, 1.0);
  patch.point = center_b + (radius_b - 0.5 * patch.penetration) * patch.normal;
  return true;
}

bool circle_segment_patch(const Vec2& center_a, double radius_a, const Vec2& s0, const Vec2& s1,
                          const Vec2& normal, double corner_radius, ContactPatch& patch) {
  const Vec2 u = s1 - s0;
  const Vec2 rel = center_a - s0;
  const double t = rel.dot(u) / u.squaredNorm();
  // a hybrid contact whose circle centre has gone below the face (the jack swinging back
  // under a dropped knuckle) meets the nearer rounded corner from the side, not the face
  const bool beside = corner_radius > 0.0 && normal.dot(rel) < 0.0;
  if (t >= 0.0 && t <= 1.0 && !beside) {
    const double x = radius_a - normal.dot(rel);
    if (x <= 0.0) return false;
    patch.penetration = x;
    patch.normal = normal;
    patch.point = center_a - (radius_a - 0.5 * x) * normal;
    return true;
  }
  // past an end: the rounded corner
  const Vec2 corner = (t < 0.5 ? s0 : s1) - corner_radius * normal;
  return circle_circle_patch(center_a, radius_a, corner, corner_radius, patch);
}

}  // namespace pat
