// A certified test that a contact found apart is still apart, cheaper than its distance.
//
// When a contact's distance is computed at q_ref and found open (gap g > 0), the penetration at
// q can exceed −g only by the relative motion of its features: rotating joint j by Δq_j moves a
// point at distance r from its pivot by at most r |Δq_j|, and joints that move both bodies
// (common ancestors) leave the distance unchanged. With r_j bounding, for every relevant joint j,
// the distance from its pivot of the contact points and of the other relevant pivots (each within
// its margin of the value at q_ref while the test holds),
//
//   moved(q) = Σ_j (r_j + m) |q_j − q_ref,j|  <  m   ⇒   penetration(q) ≤ moved − g < 0,
//
// with the margin m = g, or less where the distance formula switches branch (contact_geometry.h:
// a circle centre behind a segment's face jumps to the in-face formula when it crosses the face
// line inside the segment, or when it enters the segment's span behind a plain face). The
// relevant joints are those on exactly one of the two bodies' chains (at most kMaxDof).
#pragma once

#include <cmath>

#include "core/types.h"

namespace pat {

class ContactCull {
 public:
  /// Joints that move one body of the contact but not the other.
  void set_joints(const int* joints, int count) {
    count_ = count;
    for (int k = 0; k < count; ++k) joint_[k] = joints[k];
    valid_ = false;
  }
  int joint_count() const { return count_; }
  int joint(int k) const { return joint_[k]; }

  /// Records an open contact at q: gap g > 0 (m), margin m ≤ g (m), and for each relevant
  /// joint k the distance bound r_k (m) at q.
  void arm(const DofVector& q, double gap, double margin, const double* reach) {
    valid_ = gap > 0.0 && margin > 0.0;
    gap_ = gap;
    margin_ = margin;
    for (int k = 0; k < count_; ++k) {
      q_ref_[k] = q[joint_[k]];
      reach_[k] = reach[k] + margin;
    }
  }
  void disarm() { valid_ = false; }

  /// True if the contact is certainly still open at q; then `bound` receives an upper bound of
  /// its penetration (negative, m).
  bool still_open(const DofVector& q, double& bound) const {
    if (!valid_) return false;
    double moved = 0.0;
    for (int k = 0; k < count_; ++k) moved += reach_[k] * std::abs(q[joint_[k]] - q_ref_[k]);
    if (!(moved < margin_)) return false;
    bound = moved - gap_;
    return true;
  }

 private:
  int count_ = 0;
  int joint_[kMaxDof] = {};
  double q_ref_[kMaxDof] = {};
  double reach_[kMaxDof] = {};
  double gap_ = 0.0, margin_ = 0.0;
  bool valid_ = false;
};

}  // namespace pat
