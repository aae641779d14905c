// Bad presets and bad model edits (model/preset_loader.h, model/model_edits.h): every message
// names the file, the field and the problem; the shipped presets load and cite their sources.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "model/action_model.h"
#include "model/model_edits.h"
#include "model/preset_loader.h"
#include "sim/key_travel.h"
#include "sim/simulation.h"

namespace pat {
namespace {

using nlohmann::json;

constexpr const char* kBrokenName = "broken.json";

std::string preset_path(const std::string& name) {
  return std::string(PAT_PRESET_DIR) + "/" + name + ".json";
}

std::string preset_text(const std::string& name) {
  std::ifstream in(preset_path(name), std::ios::binary);
  EXPECT_TRUE(in) << "cannot open " << preset_path(name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

json preset_json(const std::string& name) {
  return json::parse(preset_text(name));
}

// The InputError message parse_action gives for `text`, or "" (and a failure) if none.
std::string parse_error(const std::string& text) {
  try {
    parse_action(text, kBrokenName);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "parse_action accepted a broken preset";
  return "";
}

void expect_contains_all(const std::string& message, std::initializer_list<const char*> parts) {
  for (const char* part : parts)
    EXPECT_NE(message.find(part), std::string::npos)
        << "message does not contain \"" << part << "\": " << message;
}

// Parses the edited preset and checks that the error contains the file name and `parts`.
void expect_preset_error(const json& preset, std::initializer_list<const char*> parts) {
  const std::string message = parse_error(preset.dump(1));
  expect_contains_all(message, {kBrokenName});
  expect_contains_all(message, parts);
}

template <typename Edit>
std::string edit_error(const ActionModel& model, Edit edit) {
  try {
    edit(model);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the edit was accepted";
  return "";
}

TEST(PresetErrors, UnmodifiedGrandTextParses) {
  const ActionModel model = parse_action(preset_json("grand").dump(1), kBrokenName);
  EXPECT_EQ(model.kind, "grand");
  EXPECT_EQ(model.source_file, kBrokenName);
}

TEST(PresetErrors, MissingFieldNamesBodyAndField) {
  json preset = preset_json("grand");
  ASSERT_TRUE(preset["bodies"][2].contains("mass_g"));
  preset["bodies"][2].erase("mass_g");
  expect_preset_error(preset, {"bodies[2]", "mass_g", "missing"});
}

TEST(PresetErrors, WrongTypeNamesField) {
  json preset = preset_json("grand");
  preset["bodies"][0]["mass_g"] = "95";
  expect_preset_error(preset, {"bodies[0]", "mass_g", "expected a number", "a string"});
}

TEST(PresetErrors, NegativeMassMustBePositive) {
  json preset = preset_json("grand");
  preset["bodies"][1]["mass_g"] = -3;
  expect_preset_error(preset, {"bodies[1]", "mass_g", "must be positive", "-3"});
}

TEST(PresetErrors, ZeroMassMustBePositive) {
  json preset = preset_json("upright");
  preset["bodies"][3]["mass_g"] = 0;
  expect_preset_error(preset, {"bodies[3]", "mass_g", "must be positive"});
}

TEST(PresetErrors, NegativeInertiaMustBePositive) {
  json preset = preset_json("grand");
  preset["bodies"][4]["inertia_com_g_cm2"] = -1.5;
  expect_preset_error(preset, {"bodies[4]", "inertia_com_g_cm2", "must be positive"});
}

TEST(PresetErrors, MalformedJsonGivesLineAndColumn) {
  const std::string text = preset_text("grand");
  // delete a closing brace from the middle of the file
  const std::size_t brace = text.find('}', text.size() / 2);
  ASSERT_NE(brace, std::string::npos);
  const std::string broken = text.substr(0, brace) + text.substr(brace + 1);
  const std::string message = parse_error(broken);
  expect_contains_all(message, {kBrokenName, "line ", "column ", "malformed"});

  // the parser notices the damage at or after the line of the deleted brace
  const int brace_line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + brace, '\n'));
  const std::size_t at = message.find("line ");
  ASSERT_NE(at, std::string::npos);
  const int reported_line = std::stoi(message.substr(at + 5));
  EXPECT_GE(reported_line, brace_line) << message;
  EXPECT_LE(reported_line, static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1);
}

TEST(PresetErrors, MalformedJsonOnFirstLine) {
  const std::string message = parse_error("{\"schema\": 1,, }");
  expect_contains_all(message, {kBrokenName, "line 1", "malformed"});
}

// a number beyond a double's range is named with the file, in words (the library's own text,
// "[json.exception.out_of_range.406] …", had been shown with no file)
TEST(PresetErrors, ANumberBeyondADoubleNamesTheFileAndTheNumber) {
  std::string text = preset_text("grand");
  const std::size_t mass = text.find("\"mass_g\":");
  ASSERT_NE(mass, std::string::npos);
  text.insert(text.find(':', mass) + 1, " 1e999, \"was\":");
  const std::string message = parse_error(text);
  expect_contains_all(message, {kBrokenName, "malformed JSON", "1e999"});
  EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
}

// a preset edited by hand: what is wrong is named, not a consequence of it ("unknown body" for a
// parent listed later or the body itself; a second spring of the same name had been accepted,
// and --without listed it twice; an empty name had surfaced as an unknown body in a contact)
TEST(PresetErrors, ParentsOrderNamesAndDuplicatePartsAreNamed) {
  json later = preset_json("grand");
  later["bodies"][1]["parent"] = later["bodies"][2]["name"];
  expect_preset_error(later, {"bodies[1]", "parent", "listed after it", "bodies[2]"});
  json own = preset_json("grand");
  own["bodies"][1]["parent"] = own["bodies"][1]["name"];
  expect_preset_error(own, {"bodies[1]", "parent", "its own parent"});
  json empty = preset_json("grand");
  empty["bodies"][5]["name"] = "";
  expect_preset_error(empty, {"bodies[5]", "name", "must not be empty"});
  json springs = preset_json("grand");
  springs["springs"][1]["name"] = springs["springs"][0]["name"];
  expect_preset_error(springs, {"springs[1]", "name", "duplicate name"});
  json adjusters = preset_json("grand");
  adjusters["adjusters"][1]["name"] = adjusters["adjusters"][0]["name"];
  expect_preset_error(adjusters, {"adjusters[1]", "name", "duplicate adjuster name"});
}

// values no action has, a slip of units or a typo, are named (they had loaded and run, or
// failed later as an action that does not come to rest)
TEST(PresetErrors, ValuesBeyondAnyActionAreNamed) {
  struct Case {
    const char* preset;
    const char* field;  // a JSON pointer
    json value;
    std::vector<const char*> expected;  // in the message
  };
  const std::vector<Case> cases = {
      {"grand", "/bodies/4/com_mm", {1e300, 0.0}, {"bodies[4]", "com_mm", "mm away"}},
      {"grand", "/bodies/2/mass_g", 1e9, {"bodies[2]", "mass_g", "at most"}},
      {"grand", "/bodies/2/inertia_com_g_cm2", 1e12, {"bodies[2]", "inertia_com_g_cm2", "at most"}},
      {"grand",
       "/springs/0/stiffness_n_mm_per_rad",
       1e300,
       {"springs[0]", "stiffness_n_mm_per_rad", "at most"}},
      {"grand", "/springs/2/preload_n_mm", -1e300, {"springs[2]", "preload_n_mm", "at least -"}},
      {"grand",
       "/contacts/0/max_penetration_mm",
       1e300,
       {"contacts[0]", "max_penetration_mm", "at most 25"}},
      {"upright",
       "/straps/0/stiffness_n_per_mm",
       1e300,
       {"straps[0]", "stiffness_n_per_mm", "at most"}},
      {"upright", "/straps/0/slack_mm", 1e300, {"straps[0]", "slack_mm", "at most"}},
      {"grand", "/bodies/0/trace_sign", 5, {"bodies[0]", "trace_sign", "1 or -1"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.field);
    json preset = preset_json(c.preset);
    preset[json::json_pointer(c.field)] = c.value;
    const std::string message = parse_error(preset.dump(1));
    expect_contains_all(message, {kBrokenName});
    for (const char* part : c.expected) expect_contains_all(message, {part});
  }
}

TEST(PresetErrors, NotAnObject) {
  const std::string message = parse_error("[1, 2, 3]");
  expect_contains_all(message, {kBrokenName, "object"});
}

TEST(PresetErrors, UnknownBodyInContact) {
  json preset = preset_json("grand");
  preset["contacts"][3]["body_a"] = "sostenuto";
  expect_preset_error(preset, {"contacts[3]", "body_a", "unknown body", "sostenuto"});
}

TEST(PresetErrors, UnknownFeltLaw) {
  json preset = preset_json("grand");
  preset["contacts"][0]["felt"] = "velvet";
  expect_preset_error(preset, {"contacts[0]", "felt", "unknown felt law", "velvet"});
}

// A felt whose unloading curve lies above its loading curve runs its hysteresis loop backwards
// and gives back more energy than it took: refused, naming the contact, the law and where.
TEST(PresetErrors, AnUnloadingCurveAboveTheLoadingCurveIsRefused) {
  json preset = preset_json("grand");
  const std::string law = preset["contacts"][0]["felt"];
  json& felt = preset["felts"][law];
  felt["unloading"] = felt["loading"];
  for (const char* key : {"a_n_per_mm", "c_n_per_mm"})
    if (felt["unloading"].contains(key))
      felt["unloading"][key] = 3.0 * felt["loading"][key].get<double>();
  expect_preset_error(preset, {"contacts[0]", "felt", law.c_str(), "unloading curve pushes harder",
                               "max_penetration_mm"});
  // in a contact's own law, too
  json own = preset_json("grand");
  own["contacts"][0]["felt"] = felt;
  expect_preset_error(own, {"contacts[0]", ").felt: its unloading curve pushes harder"});
}

TEST(PresetErrors, ClosedEndNamesTheChoicesAndRefusesRoundedCorners) {
  json preset = preset_json("grand");
  preset["contacts"][0]["closed_end"] = "middle";
  expect_preset_error(preset, {"contacts[0]", "closed_end", "unknown end 'middle'", "start, end"});
  preset = preset_json("grand");
  for (json& contact : preset["contacts"])
    if (contact["shape"] == "hybrid") contact["closed_end"] = "both";
  expect_preset_error(preset, {"closed_end", "rounded"});
}

// A face's normal tilted against its segment would make the distance jump at the span's ends
// (and the cull of apart contacts rests on it not jumping): refused, with the angle.
TEST(PresetErrors, SegmentNormalMustStandSquareToItsFace) {
  json preset = preset_json("grand");
  std::size_t index = 0;
  while (!preset["contacts"][index].contains("segment_mm")) ++index;
  json& contact = preset["contacts"][index];
  const double dx =
      contact["segment_mm"][1][0].get<double>() - contact["segment_mm"][0][0].get<double>();
  const double dy =
      contact["segment_mm"][1][1].get<double>() - contact["segment_mm"][0][1].get<double>();
  // the normal turned 5° toward the segment's direction
  const double length = std::hypot(dx, dy), turn = 5.0 * kPi / 180.0;
  const double nx = contact["normal"][0].get<double>(), ny = contact["normal"][1].get<double>();
  contact["normal"] = {nx * std::cos(turn) + dx / length * std::sin(turn),
                       ny * std::cos(turn) + dy / length * std::sin(turn)};
  const std::string where = "contacts[" + std::to_string(index) + "]";
  expect_preset_error(preset,
                      {where.c_str(), "normal", "not perpendicular to segment_mm", "off by 5°"});
}

TEST(PresetErrors, AMisspeltFieldIsNamedNotIgnored) {
  // an optional field misspelt used to load silently with its default: a hammer without joint
  // friction swung 35 round trips in the swing test
  json preset = preset_json("grand");
  std::size_t hammer = 0;
  while (hammer < preset["bodies"].size() && preset["bodies"][hammer]["name"] != "hammer") ++hammer;
  ASSERT_LT(hammer, preset["bodies"].size());
  ASSERT_TRUE(preset["bodies"][hammer].contains("friction"));
  preset["bodies"][hammer]["fricton"] = preset["bodies"][hammer]["friction"];
  preset["bodies"][hammer].erase("friction");
  expect_preset_error(preset, {"bodies", "(hammer)", "fricton", "not read here", "friction"});
  // the same inside a nested object, and at the top
  json nested = preset_json("grand");
  nested["springs"][0]["preload_n_mn"] = 1.0;
  expect_preset_error(nested, {"springs[0]", "preload_n_mn", "not read here"});
  json top = preset_json("grand");
  top["adjuster"] = json::array();
  expect_preset_error(top, {"adjuster", "not read here", "adjusters"});
  // what only documents a value is not a field the model reads, and is allowed anywhere read
  json documented = preset_json("grand");
  documented["bodies"][0]["note"] = "weighed on a kitchen scale";
  documented["contacts"][0]["_comment"] = "the usual JSON comment";
  EXPECT_NO_THROW(parse_action(documented.dump(1), kBrokenName));
}

TEST(PresetErrors, UnsupportedSchema) {
  json preset = preset_json("grand");
  preset["schema"] = 2;
  expect_preset_error(preset, {"schema", "unsupported schema 2"});
}

TEST(PresetErrors, MissingTopLevelList) {
  json preset = preset_json("upright");
  preset.erase("contacts");
  expect_preset_error(preset, {"contacts", "missing"});
}

TEST(PresetErrors, UnknownKind) {
  json preset = preset_json("grand");
  preset["kind"] = "harpsichord";
  expect_preset_error(preset, {"kind", "harpsichord"});
}

TEST(PresetErrors, MissingSourceOnBody) {
  json preset = preset_json("grand");
  preset["bodies"][1].erase("source");
  expect_preset_error(preset, {"bodies[1]", "source", "missing"});
}

TEST(PresetErrors, MissingSourceOnFeltLaw) {
  json preset = preset_json("grand");
  const std::string law = preset["felts"].begin().key();
  preset["felts"][law].erase("source");
  expect_preset_error(preset, {"felts", "source", "missing"});
}

TEST(PresetErrors, NegativeStrapStiffness) {
  json preset = preset_json("upright");
  ASSERT_FALSE(preset["straps"].empty());
  preset["straps"][0]["stiffness_n_per_mm"] = -2;
  expect_preset_error(preset, {"straps[0]", "stiffness_n_per_mm", "must be positive"});
}

TEST(PresetErrors, UnknownAdjusterContact) {
  json preset = preset_json("grand");
  json& move = preset["adjusters"][0]["moves"][0];
  ASSERT_TRUE(move.contains("contact"));
  move["contact"] = "no such contact";
  expect_preset_error(preset, {"adjusters[0]", "moves[0]", "contact", "unknown contact"});
}

// A regulation setting's `clear_first` names another adjuster and a position inside its range.
TEST(PresetErrors, ClearFirstNamesAnotherAdjusterWithinItsRange) {
  json preset = preset_json("grand");
  json* let_off = nullptr;
  for (json& setting : preset["regulation"])
    if (setting["name"] == "let_off") let_off = &setting;
  ASSERT_TRUE(let_off && let_off->contains("clear_first"));
  json bad_name = preset;
  for (json& setting : bad_name["regulation"])
    if (setting["name"] == "let_off") setting["clear_first"]["adjuster"] = "no_such_screw";
  expect_preset_error(bad_name, {"let_off", "clear_first.adjuster", "no_such_screw"});
  json out_of_range = preset;
  for (json& setting : out_of_range["regulation"])
    if (setting["name"] == "let_off") setting["clear_first"]["position_mm"] = 9.0;
  expect_preset_error(out_of_range, {"let_off", "clear_first.position_mm",
                                     "outside the adjuster's physical range"});
}

// A regulated offset (written by regulate, summed over regulations) stays within the
// adjuster's whole travel.
TEST(PresetErrors, RegulatedOffsetOutsideTheAdjustersRange) {
  json preset = preset_json("grand");
  preset["adjusters"][0]["regulated_offset_mm"] = 50;  // key_dip's range is [-3, 3]
  expect_preset_error(preset, {"adjusters[0]", "regulated_offset_mm", "±6 mm", "[-3, 3]", "50"});
}

TEST(PresetErrors, MissingFileNamesThePath) {
  const std::string path = preset_path("no_such_preset");
  try {
    load_action(path);
    FAIL() << "load_action accepted a missing file";
  } catch (const InputError& e) {
    expect_contains_all(e.what(), {"no_such_preset.json"});
  }
}

// A folder or an empty file is named as what it is, not as JSON malformed at line 1, column 1;
// a field of the top-level object is named without a leading dot.
TEST(PresetErrors, AFolderAnEmptyFileAndARootFieldAreNamedPlainly) {
  const std::string folder = ::testing::TempDir() + "/folder.json";
  std::filesystem::create_directories(folder);
  try {
    load_action(folder);
    FAIL() << "load_action accepted a folder";
  } catch (const InputError& e) {
    expect_contains_all(e.what(), {"folder.json: is a folder, not a preset file"});
  }
  expect_contains_all(parse_error(" \n"), {kBrokenName, "the preset file is empty"});
  const std::string schema = parse_error(R"({"schema": "one"})");
  expect_contains_all(schema, {": schema: expected a number, got a string"});
  EXPECT_EQ(schema.find(".schema"), std::string::npos) << schema;
}

TEST(PresetShipped, BothLoadByNameAndByPath) {
  for (const char* name : {"grand", "upright"}) {
    SCOPED_TRACE(name);
    const ActionModel by_name = load_action(name);
    const ActionModel by_path = load_action(preset_path(name));
    EXPECT_EQ(by_name.kind, name);
    EXPECT_EQ(by_path.kind, name);
    EXPECT_FALSE(by_path.bodies.empty());
    EXPECT_FALSE(by_path.contacts.empty());
    EXPECT_FALSE(by_path.adjusters.empty());
    EXPECT_EQ(by_name.bodies.size(), by_path.bodies.size());
    EXPECT_EQ(by_name.contacts.size(), by_path.contacts.size());
    EXPECT_EQ(by_path.source_file, preset_path(name));
  }
}

// A "source" is a non-empty string, or an object of non-empty strings.
bool has_source(const json& item) {
  if (!item.is_object() || !item.contains("source")) return false;
  const json& source = item["source"];
  if (source.is_string()) return !source.get<std::string>().empty();
  if (!source.is_object() || source.empty()) return false;
  for (const auto& [key, value] : source.items())
    if (!value.is_string() || value.get<std::string>().empty()) return false;
  return true;
}

TEST(PresetShipped, EveryPartAndFeltLawHasASource) {
  for (const char* name : {"grand", "upright"}) {
    SCOPED_TRACE(name);
    const json preset = preset_json(name);
    int checked = 0;
    for (const char* list : {"bodies", "contacts", "springs", "straps"}) {
      if (!preset.contains(list)) continue;
      ASSERT_TRUE(preset[list].is_array()) << list;
      for (std::size_t i = 0; i < preset[list].size(); ++i) {
        const json& item = preset[list][i];
        EXPECT_TRUE(has_source(item)) << list << "[" << i << "] " << item.value("name", "");
        ++checked;
        // a felt law written inside a contact needs its own source too
        if (item.contains("felt") && item["felt"].is_object()) {
          EXPECT_TRUE(has_source(item["felt"])) << list << "[" << i << "].felt";
          ++checked;
        }
      }
    }
    ASSERT_TRUE(preset.contains("felts"));
    for (const auto& [law, value] : preset["felts"].items()) {
      EXPECT_TRUE(has_source(value)) << "felts." << law;
      ++checked;
    }
    EXPECT_GT(checked, 20);
  }
}

TEST(PresetEdits, UnknownSettingNamesItAndTheChoices) {
  const ActionModel grand = load_action("grand");
  const std::string message =
      edit_error(grand, [](const ActionModel& m) { with_setting(m, "nonsense=1"); });
  expect_contains_all(message, {"nonsense", "let_off"});
}

TEST(PresetEdits, SettingOutOfRangeNamesItAndTheRange) {
  const ActionModel grand = load_action("grand");
  const std::string message =
      edit_error(grand, [](const ActionModel& m) { with_setting(m, "let_off=99"); });
  expect_contains_all(message, {"let_off", "99", "range", "[-4 mm, 4 mm]"});
}

TEST(PresetEdits, SettingWithoutANumber) {
  const ActionModel grand = load_action("grand");
  expect_contains_all(
      edit_error(grand, [](const ActionModel& m) { with_setting(m, "let_off=wide"); }),
      {"let_off=wide", "not a number"});
  expect_contains_all(edit_error(grand, [](const ActionModel& m) { with_setting(m, "let_off"); }),
                      {"let_off", "NAME=MM"});
}

TEST(PresetEdits, SettingInRangeIsApplied) {
  const ActionModel grand = load_action("grand");
  const ActionModel set = with_setting(grand, "let_off=0.5");
  const int index = set.adjuster_index("let_off");
  ASSERT_GE(index, 0);
  EXPECT_DOUBLE_EQ(set.adjusters[index].value, 0.5e-3);
}

TEST(PresetEdits, WithoutBridleOnTheUpright) {
  const ActionModel upright = load_action("upright");
  ASSERT_GE(upright.strap_index("bridle"), 0);
  const ActionModel without = without_part(upright, "bridle");
  EXPECT_LT(without.strap_index("bridle"), 0);
  EXPECT_EQ(without.straps.size() + 1, upright.straps.size());
  EXPECT_EQ(without.springs.size(), upright.springs.size());
  ASSERT_EQ(without.removed_parts.size(), 1u);
  EXPECT_EQ(without.removed_parts[0], "bridle");
  EXPECT_GE(upright.strap_index("bridle"), 0);  // the original is unchanged
}

// Issue 2: --without repetition_spring on the grand. Without the spring nothing holds the
// lever's front up: it comes to rest on the lever rest (the stand-in for the whippen body under
// it), the hammer a little lower on its jack, and a blow still strikes.
TEST(PresetEdits, GrandWithoutTheRepetitionSpringRestsAndStrikes) {
  const ActionModel grand = without_part(load_action("grand"), "repetition_spring");
  const RestState rest = find_rest_state(grand);
  const auto input = parse_input_spec("force:pulse:20:40", input_context(grand, rest));
  SimulationOptions options;
  options.duration_s = 0.1;
  const SimulationResult r = simulate(grand, input.get(), options, &rest);
  ASSERT_EQ(r.status, "ok") << r.stop_cause;
  EXPECT_TRUE(std::any_of(r.events.begin(), r.events.end(),
                          [](const SimEvent& e) { return e.type == "impact"; }));
  // at rest the lever lies on its rest: that contact carries its weight
  const std::vector<double> rest_force =
      r.trace.column(column_name("repetition lever–whippen (lever rest)") + "_force_n");
  ASSERT_FALSE(rest_force.empty());
  EXPECT_GT(rest_force.front(), 0.0);
}

TEST(PresetEdits, WithoutBridleOnTheGrandListsRemovableParts) {
  const ActionModel grand = load_action("grand");
  const std::string message =
      edit_error(grand, [](const ActionModel& m) { without_part(m, "bridle"); });
  expect_contains_all(message, {"bridle", "grand", "removable parts"});
  for (const JointSpring& spring : grand.springs)
    EXPECT_NE(message.find(spring.name), std::string::npos) << message;
}

}  // namespace
}  // namespace pat
