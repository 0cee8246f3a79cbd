// Input script files: accepted forms, the sorted order, and the exact error messages (source,
// event index, field).
#include <gtest/gtest.h>

#include "DiagnosticText.h"

#include <string>

#include "input/InputScript.h"

namespace toyhost {
namespace {

std::string mouseError(const std::string& json) {
    auto result = parseMouseScript(json, "mouse.json");
    return result.ok() ? "(parsed without error)" : toyhost::testing::plainText(result.error());
}

std::string keyError(const std::string& json) {
    auto result = parseKeyScript(json, "keys.json");
    return result.ok() ? "(parsed without error)" : toyhost::testing::plainText(result.error());
}

TEST(InputScriptParse, MouseEventsOfEveryType) {
    auto script = parseMouseScript(R"([
        {"frame": 10, "type": "down", "x": 120, "y": 80, "comment": "grab"},
        {"time": 0.5, "type": "move", "x": 130.5, "y": 90},
        {"frame": 40, "type": "up"},
        {"frame": 41, "type": "up", "x": 1, "y": 2},
        {"frame": 50, "type": "click", "x": -3, "y": 4}
    ])", "mouse.json");
    ASSERT_TRUE(script.ok()) << script.error().text();
    const auto& e = script->events;
    ASSERT_EQ(e.size(), 5u);
    using Type = MouseScriptEvent::Type;
    EXPECT_EQ(e[0].type, Type::Down);
    EXPECT_EQ(e[0].at.frame, 10);
    EXPECT_EQ(*e[0].position, glm::vec2(120, 80));
    EXPECT_EQ(e[1].type, Type::Up);
    EXPECT_FALSE(e[1].position.has_value());
    EXPECT_EQ(e[2].type, Type::Up);
    EXPECT_EQ(*e[2].position, glm::vec2(1, 2));
    EXPECT_EQ(e[3].type, Type::Click);
    EXPECT_EQ(*e[3].position, glm::vec2(-3, 4));
    EXPECT_EQ(e[4].type, Type::Move);  // "time" events after all "frame" events
    EXPECT_EQ(e[4].at.clock, ScriptMoment::Clock::Time);
    EXPECT_DOUBLE_EQ(e[4].at.seconds, 0.5);
    EXPECT_EQ(*e[4].position, glm::vec2(130.5f, 90));
}

TEST(InputScriptParse, SortsStablyFrameEventsThenTimeEvents) {
    auto script = parseMouseScript(R"([
        {"time": 2.0, "type": "move", "x": 0, "y": 0},
        {"frame": 7, "type": "move", "x": 1, "y": 0},
        {"time": 0.5, "type": "move", "x": 2, "y": 0},
        {"frame": 3, "type": "move", "x": 3, "y": 0},
        {"frame": 7, "type": "move", "x": 4, "y": 0},
        {"frame": 3, "type": "move", "x": 5, "y": 0},
        {"time": 0.5, "type": "move", "x": 6, "y": 0}
    ])", "mouse.json");
    ASSERT_TRUE(script.ok()) << script.error().text();
    std::vector<float> order;
    for (const auto& e : script->events) order.push_back(e.position->x);
    EXPECT_EQ(order, (std::vector<float>{3, 5, 1, 4, 2, 6, 0}));
}

TEST(InputScriptParse, EmptyArrayIsAnEmptyScript) {
    auto script = parseMouseScript("[]", "mouse.json");
    ASSERT_TRUE(script.ok());
    EXPECT_TRUE(script->events.empty());
}

TEST(InputScriptParse, KeyEventsByNameAndCode) {
    auto script = parseKeyScript(R"([
        {"frame": 3, "type": "down", "key": "space"},
        {"frame": 9, "type": "up", "key": 32},
        {"time": 1.25, "type": "tap", "key": "Left"},
        {"frame": 4, "type": "tap", "key": "200"}
    ])", "keys.json");
    ASSERT_TRUE(script.ok()) << script.error().text();
    const auto& e = script->events;
    ASSERT_EQ(e.size(), 4u);
    using Type = KeyScriptEvent::Type;
    EXPECT_EQ(e[0].type, Type::Down);
    EXPECT_EQ(e[0].keyCode, 32);
    EXPECT_EQ(e[1].type, Type::Tap);
    EXPECT_EQ(e[1].keyCode, 200);
    EXPECT_EQ(e[2].type, Type::Up);
    EXPECT_EQ(e[2].keyCode, 32);
    EXPECT_EQ(e[3].type, Type::Tap);
    EXPECT_EQ(e[3].keyCode, 37);
}

TEST(InputScriptParse, MalformedJsonSaysWhereAndWhatInWords) {
    std::string message = mouseError(R"([{"frame": 1,]")");
    EXPECT_EQ(message.rfind("mouse.json:1:14: invalid JSON: found ']' after a comma", 0), 0u) << message;
    EXPECT_EQ(message.find("parse error"), std::string::npos) << message;  // not the parser's words
}

TEST(InputScriptParse, DocumentMustBeAnArrayOfObjects) {
    EXPECT_EQ(mouseError(R"({"frame": 1})"),
              "mouse.json: expected a JSON array of events, got object");
    EXPECT_EQ(mouseError(R"([{"frame": 0, "type": "up"}, 5])"),
              "mouse.json: event 1: expected an object, got 5");
    EXPECT_EQ(keyError(R"(["space"])"),
              "keys.json: event 0: expected an object, got string \"space\"");
}

TEST(InputScriptParse, MissingCoordinateNamesEventAndField) {
    EXPECT_EQ(mouseError(R"([
        {"frame": 0, "type": "down", "x": 1, "y": 1},
        {"frame": 1, "type": "move", "x": 1, "y": 1},
        {"frame": 2, "type": "up"},
        {"frame": 3, "type": "down", "y": 80}
    ])"), "mouse.json: event 3: \"x\" is missing");
    EXPECT_EQ(mouseError(R"([{"frame": 0, "type": "click", "x": 1}])"),
              "mouse.json: event 0: \"y\" is missing");
    EXPECT_EQ(mouseError(R"([{"frame": 0, "type": "up", "x": 1}])"),
              "mouse.json: event 0: \"y\" is missing");
}

TEST(InputScriptParse, WrongTypesAreNamed) {
    EXPECT_EQ(mouseError(R"([{"frame": 0, "type": "down", "x": 1, "y": "80"}])"),
              "mouse.json: event 0: \"y\" must be a number of pixels within +-1000000, got string \"80\"");
    EXPECT_EQ(mouseError(R"([{"frame": 0, "type": 3}])"),
              "mouse.json: event 0: \"type\" must be a string, got 3");
    EXPECT_EQ(mouseError(R"([{"frame": "2", "type": "up"}])"),
              "mouse.json: event 0: \"frame\" must be an integer >= 0, got string \"2\"");
    EXPECT_EQ(mouseError(R"([{"time": true, "type": "up"}])"),
              "mouse.json: event 0: \"time\" must be a number of seconds from 0 to 1e9, got boolean");
    EXPECT_EQ(keyError(R"([{"frame": 0, "type": "down", "key": null}])"),
              "keys.json: event 0: \"key\" must be a key name or a keyCode, got null");
}

TEST(InputScriptParse, FrameAndTimeExactlyOne) {
    EXPECT_EQ(mouseError(R"([{"frame": 0, "type": "up"},
                             {"frame": 1, "time": 0.5, "type": "up"}])"),
              "mouse.json: event 1: give one of \"frame\" and \"time\", not both");
    EXPECT_EQ(mouseError(R"([{"type": "up"}])"),
              "mouse.json: event 0: \"frame\" or \"time\" is missing");
}

TEST(InputScriptParse, NegativeAndFractionalMomentsAreRejected) {
    EXPECT_EQ(mouseError(R"([{"frame": -1, "type": "up"}])"),
              "mouse.json: event 0: \"frame\" must be an integer >= 0, got -1");
    EXPECT_EQ(mouseError(R"([{"frame": 2.5, "type": "up"}])"),
              "mouse.json: event 0: \"frame\" must be an integer >= 0, got 2.5");
    EXPECT_EQ(mouseError(R"([{"time": -0.5, "type": "up"}])"),
              "mouse.json: event 0: \"time\" must be a number of seconds from 0 to 1e9, got -0.5");
    EXPECT_TRUE(parseMouseScript(R"([{"time": 0, "type": "up"}])", "m").ok());
}

TEST(InputScriptParse, UnknownTypesAndFields) {
    EXPECT_EQ(mouseError(R"([{"frame": 0, "type": "drag", "x": 1, "y": 1}])"),
              "mouse.json: event 0: unknown type \"drag\" (expected down, move, up, click)");
    EXPECT_EQ(mouseError(R"([{"frame": 0}])"), "mouse.json: event 0: \"type\" is missing");
    EXPECT_EQ(mouseError(R"([{"frame": 0, "type": "down", "x": 1, "y": 1, "button": 2}])"),
              "mouse.json: event 0: unknown field \"button\"");
    EXPECT_EQ(keyError(R"([{"frame": 0, "type": "press", "key": "a"}])"),
              "keys.json: event 0: unknown type \"press\" (expected down, up, tap)");
    EXPECT_EQ(keyError(R"([{"frame": 0, "type": "down", "key": "a", "x": 1}])"),
              "keys.json: event 0: unknown field \"x\"");
}

TEST(InputScriptParse, KeyErrors) {
    EXPECT_EQ(keyError(R"([{"frame": 0, "type": "down", "key": "spacebar"}])"),
              "keys.json: event 0: unknown key \"spacebar\"");
    EXPECT_EQ(keyError(R"([{"frame": 0, "type": "tap", "key": "a"}, {"frame": 1, "type": "up"}])"),
              "keys.json: event 1: \"key\" is missing");
    EXPECT_EQ(keyError(R"([{"frame": 0, "type": "down", "key": 300}])"),
              "keys.json: event 0: key code 300 is out of range 0..255");
    EXPECT_EQ(keyError(R"([{"frame": 0, "type": "down", "key": -1}])"),
              "keys.json: event 0: key code -1 is out of range 0..255");
    EXPECT_EQ(keyError(R"([{"frame": 0, "type": "down", "key": "999"}])"),
              "keys.json: event 0: key code 999 is out of range 0..255");
}

TEST(InputScriptParse, ErrorsUseTheGivenSourceName) {
    auto result = parseKeyScript(R"([{"frame": 0, "type": "down", "key": "nope"}])",
                                 "scripts/demo/keys.json");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(toyhost::testing::plainText(result.error()), "scripts/demo/keys.json: event 0: unknown key \"nope\"");
    EXPECT_EQ(result.error().first().file, "scripts/demo/keys.json");
    EXPECT_EQ(result.error().first().field, "event 0");
    EXPECT_EQ(result.error().first().code, Code::ScriptEvent);
}

TEST(InputScriptParse, MomentDueRules) {
    EXPECT_FALSE(ScriptMoment::atFrame(5).dueBefore(4, 100.0));  // a frame event ignores iTime
    EXPECT_TRUE(ScriptMoment::atFrame(5).dueBefore(5, 0.0));
    EXPECT_TRUE(ScriptMoment::atFrame(5).dueBefore(9, 0.0));
    EXPECT_FALSE(ScriptMoment::atTime(1.0).dueBefore(1000, 0.99));  // a time event ignores iFrame
    EXPECT_TRUE(ScriptMoment::atTime(1.0).dueBefore(0, 1.0));
    EXPECT_TRUE(ScriptMoment::atTime(1.0).dueBefore(0, 1.0 - 1e-9));  // rounding tolerance
}

}  // namespace
}  // namespace toyhost
