#include "dynamics/contact_geometry.h"

#include <cmath>

namespace pat {

ContactDistance circle_circle_distance(const Vec2& center_a, double radius_a, const Vec2& center_b,
                                       double radius_b) {
  const Vec2 d = center_a - center_b;
  const double dist = d.norm();
  ContactDistance out;
  out.penetration = radius_a + radius_b - dist;
  if (dist > 1e-12) out.normal = d / dist;
  return out;
}

ContactDistance circle_segment_distance(const Vec2& center_a, double radius_a, const Vec2& s0,
                                        const Vec2& u, double inverse_length2, const Vec2& normal,
                                        double corner_radius) {
  const Vec2 rel = center_a - s0;
  const double t = rel.dot(u) * inverse_length2;
  const double height = normal.dot(rel);
  // A hybrid contact whose circle centre has gone below the face (the jack swinging back under a
  // dropped knuckle) meets the corner from the side, as it does past either end.
  const bool beside = corner_radius > 0.0 && height < 0.0;
  if (t >= 0.0 && t <= 1.0 && !beside) {
    ContactDistance out;
    out.penetration = radius_a - height;
    out.normal = normal;
    return out;
  }
  const Vec2 corner = (t < 0.5 ? s0 : Vec2(s0 + u)) - corner_radius * normal;
  return circle_circle_distance(center_a, radius_a, corner, corner_radius);
}

bool patch_at(const ContactDistance& distance, const Vec2& center_a, double radius_a,
              ContactPatch& patch) {
  if (distance.penetration <= 0.0) return false;
  patch.penetration = distance.penetration;
  patch.normal = distance.normal;
  patch.point = center_a - (radius_a - 0.5 * distance.penetration) * distance.normal;
  return true;
}

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
