// Contact geometry (paper section 4.2; numerics.md section 5): penetration at the patch centre.
//
// Body A carries a circle (centre c, radius r; r = 0 is a point). Body B carries either a circle
// or a segment [s0, s1] with a unit normal m toward the free side. For a segment,
//   t* = (c − s0)·(s1 − s0)/|s1 − s0|²;  inside [0, 1]: x = r − m·(c − s0)  (circle–line),
//   outside: circle against the rounded corner of radius ρ centred at the end point − ρ m
//   (circle–circle), which makes the hybrid knuckle–jack contact continuous. A hybrid contact
//   (ρ > 0) whose circle centre lies below the face (m·(c − s0) < 0) also uses the nearer
//   corner: the circle is then beside the segment (a jack pushing on the knuckle's side).
// For two circles, x = r_A + r_B − |c_A − c_B|. The normal n points from B toward A; the patch
// centre is the middle of the overlap.
#pragma once

#include <cmath>

#include "core/types.h"

namespace pat {

struct ContactPatch {
  double penetration = 0.0;  ///< x, m (> 0: overlap)
  Vec2 normal;               ///< unit, from B toward A
  Vec2 point;                ///< patch centre, m
};

/// Signed penetration x (m; > 0 overlap, < 0 minus the gap still open) and the unit normal from
/// B toward A. Any frame: the normal comes out in the frame the arguments are given in.
struct ContactDistance {
  double penetration = 0.0;
  Vec2 normal = Vec2(0.0, 1.0);
};

/// Circle A against circle B. Inline, like the two below: they run for every contact at every
/// position update of the dynamics.
inline ContactDistance circle_circle_distance(const Vec2& center_a, double radius_a,
                                              const Vec2& center_b, double radius_b) {
  const Vec2 d = center_a - center_b;
  const double dist = d.norm();
  ContactDistance out;
  out.penetration = radius_a + radius_b - dist;
  if (dist > 1e-12) out.normal = d / dist;
  return out;
}

/// Circle A against segment B from s0 along u = s1 − s0 (inverse_length2 = 1/|u|², given so
/// that a caller can precompute it), unit normal toward A, corner radius ρ.
inline ContactDistance circle_segment_distance(const Vec2& center_a, double radius_a,
                                               const Vec2& s0, const Vec2& u,
                                               double inverse_length2, const Vec2& normal,
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

/// The patch of a contact at this distance (world frame); false when apart (x ≤ 0).
inline bool patch_at(const ContactDistance& distance, const Vec2& center_a, double radius_a,
                     ContactPatch& patch) {
  if (distance.penetration <= 0.0) return false;
  patch.penetration = distance.penetration;
  patch.normal = distance.normal;
  patch.point = center_a - (radius_a - 0.5 * distance.penetration) * distance.normal;
  return true;
}

/// Circle A (centre, radius) against circle B. Returns false when the circles are apart.
bool circle_circle_patch(const Vec2& center_a, double radius_a, const Vec2& center_b,
                         double radius_b, ContactPatch& patch);

/// Circle A against segment B (ends s0, s1, unit normal toward A, corner radius).
/// Returns false when they are apart.
bool circle_segment_patch(const Vec2& center_a, double radius_a, const Vec2& s0, const Vec2& s1,
                          const Vec2& normal, double corner_radius, ContactPatch& patch);

/// Signed penetration (m) of the same pairs: > 0 overlap, < 0 minus the gap still open.
double circle_circle_penetration(const Vec2& center_a, double radius_a, const Vec2& center_b,
                                 double radius_b);
double circle_segment_penetration(const Vec2& center_a, double radius_a, const Vec2& s0,
                                  const Vec2& s1, const Vec2& normal, double corner_radius);

}  // namespace pat
