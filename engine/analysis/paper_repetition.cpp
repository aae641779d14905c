#include "analysis/paper_repetition.h"

#include <algorithm>

#include "core/format.h"

namespace pat {

std::optional<PaperRepetitionLimits> paper_repetition_limits(const std::string& kind,
                                                             Stroke stroke) {
  // reference paper, Table 2 "Maximum playing frequencies": simulation and experiments
  if (kind == "upright" && stroke == Stroke::full) return PaperRepetitionLimits{11.0, 13.0, false};
  if (kind == "grand" && stroke == Stroke::full) return PaperRepetitionLimits{13.0, 14.0, false};
  if (kind == "grand" && stroke == Stroke::half) return PaperRepetitionLimits{19.0, 20.0, true};
  return std::nullopt;
}

std::string compare_with_paper(const SweepResult& result, const std::string& kind,
                               const std::string& settings) {
  const auto paper = paper_repetition_limits(kind, result.stroke);
  // an upright has no repetition lever: its jack slips back under the butt only once the key
  // has come most of the way up, so a key kept between full dip and half release repeats nothing
  // (the paper gives no figure for it)
  if (kind == "upright" && result.stroke == Stroke::half && !result.max_frequency_hz)
    return "An upright has no repetition lever: its jack resets under the butt only when the key "
           "comes most of the way up, so a halfway stroke is not expected to repeat (the paper "
           "gives no figure for it).";
  if (!paper || !result.max_frequency_hz) return {};
  const double low = std::min(paper->model_hz, paper->experiment_hz);
  const double high = std::max(paper->model_hz, paper->experiment_hz);
  std::string text = "The paper (Table 2): model " + format_number(paper->model_hz) +
                     " Hz, experiment " + (paper->experiment_at_least ? "at least " : "") +
                     format_number(paper->experiment_hz) + " Hz; ";
  // why a sweep may differ: the action's own settings, or (regulated) the model; the grand's
  // repetition limits are the model's known limit, and the README says why
  const bool regulated = settings.empty() || settings == "regulated";
  const std::string why = !regulated
                              ? "; the action is not regulated (" + settings + "), the paper's was."
                          : kind == "grand" ? ", a known limit of this model (README, Limits)."
                                            : " (README, Limits).";
  const double found = *result.max_frequency_hz;
  if (!result.limit_found) {
    // the repeating range runs to the band's end: only a lower bound
    text += "this sweep's repeating range reaches its top, " + format_number(found) + " Hz";
    if (found > high + kPaperAgreementHz && !paper->experiment_at_least)
      return text + ", above both" + why;
    return text + (found < low - kPaperAgreementHz ? ": raise the maximum frequency to compare."
                                                   : ", which agrees so far.");
  }
  text += "this sweep's " + format_number(found) + " Hz ";
  if (found < low - kPaperAgreementHz) return text + "is below both" + why;
  if (found > high + kPaperAgreementHz)
    return paper->experiment_at_least ? text + "agrees with the experiment's bound (at least " +
                                            format_number(paper->experiment_hz) + " Hz)."
                                      : text + "is above both" + why;
  if (found >= low && found <= high) return text + "agrees (between them).";
  return text + "agrees (within " + format_number(kPaperAgreementHz) + " Hz).";
}

}  // namespace pat
