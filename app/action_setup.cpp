#include "action_setup.h"

#include <map>
#include <set>

#include "core/error.h"
#include "model/effects.h"
#include "model/model_edits.h"
#include "model/preset_loader.h"
#include "sim/simulation.h"

namespace pat::app {
namespace {

/// Refuses a NAME given twice among an option's NAME=VALUE assignments: one of the two values
/// would be dropped without a word (the edits' own parsers name any other problem).
void refuse_repeated_names(const std::string& option, const std::vector<std::string>& assignments) {
  std::map<std::string, std::string> seen;  // name → its first assignment
  for (const std::string& assignment : assignments) {
    const std::string name = assignment.substr(0, assignment.find('='));
    const auto [first, fresh] = seen.emplace(name, assignment);
    if (!fresh)
      throw InputError(option + ": " + name + " is given twice ('" + first->second + "' and '" +
                       assignment + "'); give it once");
  }
}

}  // namespace

ActionModel load_configured_action(const CommandLine& cl) {
  refuse_repeated_names("--set", cl.values("--set"));
  refuse_repeated_names("--effect", cl.values("--effect"));
  ActionModel model = load_action(cl.value("--action"));
  for (const std::string& assignment : cl.values("--set")) model = with_setting(model, assignment);
  std::set<std::string> removed;
  for (const std::string& part : cl.values("--without"))
    if (removed.insert(part).second) model = without_part(model, part);  // twice is once
  for (const std::string& effect : cl.values("--effect"))
    model = with_effect(model, parse_effect(effect));
  // a part the action cannot rest without (the grand's jack spring holds the jack under the
  // knuckle): refused as the choice it is, not reported later as a run that failed
  if (!removed.empty()) {
    try {
      find_rest_state(model);
    } catch (const std::exception& e) {
      std::string parts;
      for (const std::string& part : removed) parts += (parts.empty() ? "" : ", ") + part;
      throw InputError("--without " + parts + ": without it the action has no rest (" + e.what() +
                       "); it holds the action at rest, so no run can leave it out");
    }
  }
  return model;
}

}  // namespace pat::app
