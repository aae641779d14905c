#include "analysis/isolated_body.h"

#include "core/error.h"

namespace pat {

ActionModel isolated_body_model(const ActionModel& action, const std::string& body_name,
                                bool keep_frame_contacts) {
  const int index = action.body_index(body_name);
  if (index < 0)
    throw InputError(action.source_file + ": the action has no body named '" + body_name + "'");
  const Body& body = action.bodies[index];
  if (body.parent >= 0)
    throw InputError(action.source_file + ": body '" + body_name + "' hangs on '" +
                     action.bodies[body.parent].name +
                     "'; only a body on the frame can be taken out alone");
  ActionModel alone;
  alone.schema = action.schema;
  alone.kind = action.kind;
  alone.name = action.name + " (" + body_name + " alone)";
  alone.description = "the " + body_name + " of " + action.name + " alone on its joint";
  alone.source_file = action.source_file;
  alone.gravity = action.gravity;
  alone.bodies.push_back(body);
  alone.landmarks.key = index == action.landmarks.key ? 0 : -1;
  alone.landmarks.key_front = action.landmarks.key_front;
  alone.landmarks.hammer = index == action.landmarks.hammer ? 0 : -1;
  alone.landmarks.strike_point = action.landmarks.strike_point;
  alone.landmarks.string_normal = action.landmarks.string_normal;
  alone.landmarks.string_point = action.landmarks.string_point;
  if (!keep_frame_contacts) return alone;
  for (std::size_t c = 0; c < action.contacts.size(); ++c) {
    Contact contact = action.contacts[c];
    const bool a_alone = contact.body_a == index && contact.body_b < 0;
    const bool b_alone = contact.body_b == index && contact.body_a < 0;
    if (!a_alone && !b_alone) continue;
    if (a_alone) contact.body_a = 0;
    if (b_alone) contact.body_b = 0;
    if (static_cast<int>(c) == action.landmarks.key_bottom_contact)
      alone.landmarks.key_bottom_contact = static_cast<int>(alone.contacts.size());
    alone.contacts.push_back(contact);
  }
  return alone;
}

}  // namespace pat
