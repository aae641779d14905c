// A key input started later in a running simulation: the blow struck from the keyboard at time
// t0 behaves as its SPEC says from t = 0 (force:pulse starts its ramp at t0).
#pragma once

#include <algorithm>
#include <memory>

#include "inputs/key_input.h"

namespace pat::ui {

class ShiftedKeyInput : public KeyInput {
 public:
  ShiftedKeyInput(std::unique_ptr<KeyInput> inner, double t0) : inner_(std::move(inner)), t0_(t0) {}

  bool is_motion() const override { return inner_->is_motion(); }
  double force_n(double t) const override { return t < t0_ ? 0.0 : inner_->force_n(t - t0_); }
  KeyMotionSample motion(double t) const override { return inner_->motion(std::max(t - t0_, 0.0)); }
  double added_mass_kg() const override { return inner_->added_mass_kg(); }
  const std::string& spec() const override { return inner_->spec(); }

 private:
  std::unique_ptr<KeyInput> inner_;
  double t0_;
};

}  // namespace pat::ui
