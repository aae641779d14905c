#include "action_setup.h"

#include <map>

#include "core/error.h"
#include "model/effects.h"
#include "model/model_edits.h"
#include "model/preset_loader.h"
#include "sim/simulation.h"

namespace pat::app {

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

ActionModel load_configured_action(const CommandLine& cl, bool needs_rest) {
  refuse_repeated_names("--set", cl.values("--set"));
  refuse_repeated_names("--effect", cl.values("--effect"));
  refuse_repeated_names("--without", cl.values("--without"));
  const ActionModel loaded = load_action(cl.value("--action"));
  ActionModel model = loaded;
  for (const std::string& assignment : cl.values("--set")) model = with_setting(model, assignment);
  for (const std::string& part : cl.values("--without")) {
    // a part the action cannot rest without (the grand's jack spring holds the jack under the
    // knuckle): refused as the choice it is, not reported later as a run that failed. Tried on
    // the preset as given, so that a --set or --effect is not blamed on the part
    if (needs_rest) {
      try {
        find_rest_state(without_part(loaded, part));
      } catch (const InputError&) {
        throw;
      } catch (const std::exception& e) {
        throw InputError("--without " + part + ": without it the action has no rest (" + e.what() +
                         "); it holds the action at rest, so no run can leave it out");
      }
    }
    model = without_part(model, part);
  }
  for (const std::string& effect : cl.values("--effect"))
    model = with_effect(model, parse_effect(effect));
  // settings that leave the action no rest position (every adjuster at an end of its range) are
  // the choice they are, named with the options (the engine's message leaves adjusters out: it
  // also reaches a student whose exercise hides them)
  if (needs_rest && cl.has("--set") && adjuster_settings_text(model) != "regulated") {
    try {
      find_rest_state(model);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      std::string given;
      for (const std::string& assignment : cl.values("--set"))
        given += (given.empty() ? "" : ", ") + assignment;
      throw InputError("--set " + given + ": with these settings the action has no rest (" +
                       e.what() + "); move them back toward 0, one at a time to find which");
    }
  }
  return model;
}

}  // namespace pat::app
