// A sweep's maximum set beside the paper's Table 2 (analysis/paper_repetition.h): the words
// say "agrees", "above both" or "below both" by the figures, so that a result that misses
// fact F4 says so in the window and on the command line.
#include "analysis/paper_repetition.h"

#include <gtest/gtest.h>

namespace pat {
namespace {

SweepResult sweep(Stroke stroke, std::optional<double> max_hz, bool limit_found) {
  SweepResult r;
  r.stroke = stroke;
  r.max_frequency_hz = max_hz;
  r.limit_found = limit_found;
  return r;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(PaperRepetition, TheTableTwoFigures) {
  const auto grand_full = paper_repetition_limits("grand", Stroke::full);
  ASSERT_TRUE(grand_full);
  EXPECT_EQ(grand_full->model_hz, 13.0);
  EXPECT_EQ(grand_full->experiment_hz, 14.0);
  const auto grand_half = paper_repetition_limits("grand", Stroke::half);
  ASSERT_TRUE(grand_half);
  EXPECT_TRUE(grand_half->experiment_at_least);  // "≥ 20": the actuator's own limit
  EXPECT_EQ(paper_repetition_limits("upright", Stroke::full)->model_hz, 11.0);
  EXPECT_FALSE(paper_repetition_limits("upright", Stroke::half));  // not in the paper
}

TEST(PaperRepetition, SaysWhetherASweepAgrees) {
  // the grand's full stroke: 13–14 Hz in the paper
  const std::string above = compare_with_paper(sweep(Stroke::full, 17.5, true), "grand");
  EXPECT_TRUE(has(above, "model 13 Hz, experiment 14 Hz")) << above;
  EXPECT_TRUE(has(above, "17.5 Hz is above both")) << above;
  EXPECT_TRUE(has(above, "known limit")) << above;
  // within 1 Hz of the span agrees; just beyond does not
  EXPECT_TRUE(has(compare_with_paper(sweep(Stroke::full, 14.9, true), "grand"), "agrees"));
  EXPECT_TRUE(has(compare_with_paper(sweep(Stroke::full, 12.0, true), "grand"), "agrees"));
  EXPECT_TRUE(has(compare_with_paper(sweep(Stroke::full, 11.5, true), "grand"), "below both"));
  // the grand's half stroke: 12.5 Hz is below 19 and "at least 20"
  const std::string below = compare_with_paper(sweep(Stroke::half, 12.5, true), "grand");
  EXPECT_TRUE(has(below, "experiment at least 20 Hz")) << below;
  EXPECT_TRUE(has(below, "below both")) << below;
  // above an "at least" experiment agrees with that bound (it is not "between them")
  const std::string bound = compare_with_paper(sweep(Stroke::half, 23, true), "grand");
  EXPECT_TRUE(has(bound, "agrees with the experiment's bound (at least 20 Hz)")) << bound;
  // inside the span: between them
  EXPECT_TRUE(
      has(compare_with_paper(sweep(Stroke::full, 13.5, true), "grand"), "agrees (between them)"));
}

TEST(PaperRepetition, ADeregulatedActionsDifferenceIsPutDownToItsSettings) {
  // let-off 3 mm down: the user's deregulation, not the model's limit
  const std::string moved =
      compare_with_paper(sweep(Stroke::full, 9.1, true), "grand", "let_off=3mm");
  EXPECT_TRUE(has(moved, "is below both; the action is not regulated (let_off=3mm)")) << moved;
  EXPECT_FALSE(has(moved, "known limit")) << moved;
  // a regulated upright's difference points to the README without calling it the grand's limit
  const std::string upright = compare_with_paper(sweep(Stroke::full, 14.3, true), "upright");
  EXPECT_TRUE(has(upright, "is above both (README, Limits).")) << upright;
}

TEST(PaperRepetition, ASweepWithoutAFailureIsALowerBound) {
  // no failure up to 20 Hz on the grand's full stroke (its last judged cycle at 19.8 Hz): beyond
  // the paper's 14 Hz, and the figure is the one the sweep's own summary gives, not the band's
  // top (they had said 11.4 and 11.5 Hz on two lines)
  const std::string beyond = compare_with_paper(sweep(Stroke::full, 19.8, false), "grand");
  EXPECT_TRUE(has(beyond, "repeating range reaches its top, 19.8 Hz, above both")) << beyond;
  // up to 10 Hz only: nothing to compare yet
  const std::string short_band = compare_with_paper(sweep(Stroke::full, 10, false), "grand");
  EXPECT_TRUE(has(short_band, "raise the maximum frequency")) << short_band;
  // no maximum, no paper figure: no sentence
  EXPECT_TRUE(compare_with_paper(sweep(Stroke::full, std::nullopt, false), "grand").empty());
  EXPECT_TRUE(compare_with_paper(sweep(Stroke::half, 15, true), "upright").empty());
  // an upright's halfway stroke that repeats nothing: why (it has no repetition lever)
  const std::string no_lever =
      compare_with_paper(sweep(Stroke::half, std::nullopt, true), "upright");
  EXPECT_TRUE(has(no_lever, "An upright has no repetition lever")) << no_lever;
}

}  // namespace
}  // namespace pat
