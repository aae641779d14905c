#include "action_setup.h"

#include <set>

#include "model/effects.h"
#include "model/model_edits.h"
#include "model/preset_loader.h"

namespace pat::app {

ActionModel load_configured_action(const CommandLine& cl) {
  ActionModel model = load_action(cl.value("--action"));
  for (const std::string& assignment : cl.values("--set")) model = with_setting(model, assignment);
  std::set<std::string> removed;
  for (const std::string& part : cl.values("--without"))
    if (removed.insert(part).second) model = without_part(model, part);  // twice is once
  for (const std::string& effect : cl.values("--effect"))
    model = with_effect(model, parse_effect(effect));
  return model;
}

}  // namespace pat::app
