#include "plot_stack.h"

#include <QGridLayout>
#include <algorithm>

#include "plot_panel.h"
#include "plot_styles.h"
#include "sim/simulation.h"

namespace pat::ui {
namespace {

constexpr double kKeptSeconds = 60.0;  // plot memory bound in long runs
constexpr int kReplotIntervalMs = 33;
// Smallest value spans of the live plots: an action at rest settles by thousandths of a degree
// or millimetre, which an axis fitted to the data would show as large motion.
constexpr double kMinimumAngleSpanDeg = 2.0;
constexpr double kMinimumGapSpanMm = 2.0;
constexpr double kMinimumForceSpanN = 1.0;

// a legend label short enough for six series on one line
QString short_contact_label(const ActionModel& model, int c) {
  const ActionLandmarks& m = model.landmarks;
  if (c == m.escapement_contact) return model.kind == "grand" ? "jack–knuckle" : "jack–butt";
  if (c == m.letoff_contact) return "let-off";
  if (c == m.string_contact) return "string";
  if (c == m.check_contact) return "backcheck";
  if (c == m.key_bottom_contact) return "key bottom";
  const std::string& name = model.contacts[c].name;
  if (name.find("capstan") != std::string::npos) return "capstan";
  return QString::fromStdString(name);
}

}  // namespace

PlotStack::PlotStack(QWidget* parent) : QWidget(parent) {
  using namespace plot_titles;
  angles_ = new PlotPanel(tr(kAngles), tr(kAnglesAxis), this);
  gap_ = new PlotPanel(tr(kGap), tr(kGapAxis), this);
  finger_ = new PlotPanel(tr(kFinger), tr(kFingerAxis), this);
  contacts_ = new PlotPanel(tr(kContacts), tr(kContactsAxis), this);
  angles_->add_series(tr("key"), "key_angle_deg", series_colour(0));
  angles_->add_series(tr("hammer"), "hammer_angle_deg", series_colour(1));
  gap_->add_series(tr("hammer–string gap"), "hammer_string_gap_mm", series_colour(2));
  finger_->add_series(tr("finger force"), "finger_force_n", series_colour(3));
  angles_->set_minimum_value_span(kMinimumAngleSpanDeg);
  gap_->set_minimum_value_span(kMinimumGapSpanMm);
  finger_->set_minimum_value_span(kMinimumForceSpanN);
  contacts_->set_minimum_value_span(kMinimumForceSpanN);
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->setSpacing(4);
  grid->addWidget(angles_, 0, 0);
  grid->addWidget(gap_, 0, 1);
  grid->addWidget(finger_, 1, 0);
  grid->addWidget(contacts_, 1, 1);
  grid->setColumnStretch(0, 1);
  grid->setColumnStretch(1, 1);
  since_replot_.start();
  deferred_replot_.setSingleShot(true);
  connect(&deferred_replot_, &QTimer::timeout, this, &PlotStack::replot);
  for (PlotPanel* panel : panels()) {
    connect(panel, &PlotPanel::userChangedTimeRange, this,
            [this, panel](double lo, double hi) { sync_time_range(panel, lo, hi); });
  }
}

std::vector<PlotPanel*> PlotStack::panels() const {
  return {angles_, gap_, finger_, contacts_};
}

void PlotStack::set_model(const ActionModel& model) {
  key_body_ = model.landmarks.key;
  hammer_body_ = model.landmarks.hammer;
  // the contacts that tell the story of a blow, when the model has them
  const ActionLandmarks& m = model.landmarks;
  std::vector<int> wanted;
  for (std::size_t c = 0; c < model.contacts.size(); ++c)
    if (model.contacts[c].name.find("capstan") != std::string::npos) wanted.push_back(int(c));
  for (int c : {m.escapement_contact, m.letoff_contact, m.string_contact, m.check_contact,
                m.key_bottom_contact})
    if (c >= 0) wanted.push_back(c);
  if (wanted == plotted_contacts_) return;
  // a new action: the contact plot gets new series
  auto* old = contacts_;
  contacts_ = new PlotPanel(tr(plot_titles::kContacts), tr(plot_titles::kContactsAxis), this);
  static_cast<QGridLayout*>(layout())->replaceWidget(old, contacts_);
  old->deleteLater();
  connect(contacts_, &PlotPanel::userChangedTimeRange, this,
          [this, panel = contacts_](double lo, double hi) { sync_time_range(panel, lo, hi); });
  contacts_->set_minimum_value_span(kMinimumForceSpanN);
  contacts_->set_time_mark(marked_t_);
  // as the plots beside it: their time span and the cursors on or off (View > Plot cursors)
  const auto [lo, hi] = angles_->x_range();
  contacts_->set_x_range(lo, hi);
  contacts_->set_cursors_enabled(angles_->cursors_enabled());
  plotted_contacts_ = wanted;
  int colour = 0;
  for (int c : wanted) {
    const std::string& name = model.contacts[c].name;
    contacts_->add_series(short_contact_label(model, c),
                          QString::fromStdString(column_name(name) + "_force_n"),
                          series_colour(colour++));
  }
}

void PlotStack::clear() {
  for (PlotPanel* panel : panels()) {
    panel->clear_data();
    panel->set_time_mark(std::nullopt);
  }
  latest_t_ = 0.0;
  marked_t_.reset();
  // a new run: the axes follow it again, unless the whole run was asked for (a class watching a
  // slow press's let-off and drop together wants that for the next run too)
  if (whole_run_)
    fit_whole_run();
  else
    set_following(true);
  replot();
}

void PlotStack::append(const std::vector<Frame>& frames) {
  if (frames.empty()) return;
  for (const Frame& f : frames) {
    // a frame of another action (more bodies) is never handed here; fewer would read past it
    const int bodies = static_cast<int>(f.angle_deg.size());
    if (key_body_ < bodies) angles_->append(0, f.t, f.angle_deg[key_body_]);
    if (hammer_body_ < bodies) angles_->append(1, f.t, f.angle_deg[hammer_body_]);
    gap_->append(0, f.t, f.hammer_string_gap_mm);
    finger_->append(0, f.t, f.finger_force_n);
    for (std::size_t s = 0; s < plotted_contacts_.size(); ++s) {
      const int c = plotted_contacts_[s];
      if (c < static_cast<int>(f.contact_force_n.size()))
        contacts_->append(static_cast<int>(s), f.t, f.contact_force_n[c]);
    }
  }
  latest_t_ = frames.back().t;
  if (latest_t_ > kKeptSeconds)
    for (PlotPanel* panel : panels()) panel->remove_before(latest_t_ - kKeptSeconds);
  show_time(latest_t_);
}

void PlotStack::show_time(double t) {
  if (whole_run_) {  // the whole run, growing with it
    fit_whole_run();
    replot();
    return;
  }
  if (following_) {
    // zoomed on the data at first, then a window sliding with the time; a time taken back into
    // the recorded run (a rewind) shows the window's span of what was recorded after it (it had
    // shown the first 5 ms only)
    const double lo = std::max(0.0, t - window_s_ * 0.95);
    const double hi =
        std::max(lo + std::min(window_s_, 1.15 * std::max(t, latest_t_) - lo), lo + 5e-3);
    for (PlotPanel* panel : panels()) {
      panel->set_x_range(lo, hi);
      panel->fit_values();
    }
  }
  replot();
}

void PlotStack::set_window(double seconds) {
  window_s_ = seconds;
  if (following_) show_time(latest_t_);
}

void PlotStack::show_whole_run() {
  if (following_) {
    following_ = false;
    emit followingChanged(false);
  }
  set_whole_run(true);
  fit_whole_run();
  replot();
}

void PlotStack::set_whole_run(bool whole) {
  if (whole == whole_run_) return;
  whole_run_ = whole;
  emit wholeRunChanged(whole);
}

void PlotStack::fit_whole_run() {
  const double lo = std::max(0.0, latest_t_ - kKeptSeconds);
  const double hi = std::max(latest_t_, lo + 5e-3);
  for (PlotPanel* panel : panels()) {
    panel->set_x_range(lo, hi);
    panel->fit_values();
  }
}

void PlotStack::mark_time(double t) {
  marked_t_ = t;
  for (PlotPanel* panel : panels()) panel->set_time_mark(t);
  const auto [lo, hi] = angles_->x_range();
  if (following_ && !whole_run_ && (t < lo || t > hi)) {
    show_time(t);  // stepped or rewound out of the window: it moves back to the shown time
    return;
  }
  replot();
}

void PlotStack::set_following(bool follow) {
  if (follow) set_whole_run(false);
  if (follow == following_) return;
  following_ = follow;
  if (follow) show_time(latest_t_);
  emit followingChanged(follow);
}

void PlotStack::sync_time_range(PlotPanel* source, double lo, double hi) {
  for (PlotPanel* panel : panels())
    if (panel != source) panel->set_x_range(lo, hi);
  for (PlotPanel* panel : panels()) panel->fit_values();
  set_whole_run(false);  // zoomed or panned by hand: it stays where the user put it
  set_following(false);
  replot();
}

void PlotStack::replot() {
  const qint64 elapsed = since_replot_.elapsed();
  if (elapsed < kReplotIntervalMs) {
    if (!deferred_replot_.isActive()) deferred_replot_.start(int(kReplotIntervalMs - elapsed));
    return;
  }
  since_replot_.restart();
  for (PlotPanel* panel : panels()) panel->request_replot();
}

}  // namespace pat::ui
