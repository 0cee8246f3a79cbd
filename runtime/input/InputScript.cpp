#include "input/InputScript.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "core/Defaults.h"
#include "core/JsonText.h"
#include "input/KeyCodes.h"

namespace toyhost {

namespace {

using nlohmann::json;

// "time" events may fire this much early so that iTime = frame / fps, computed with rounding,
// still reaches a time written as that same fraction.
constexpr double kTimeTolerance = 1e-6;

std::string inQuotes(std::string_view s) {
    std::string quoted(1, '"');  // appended, not "\"" + s: GCC 12 warns falsely (-Wrestrict)
    quoted += s;
    quoted += '"';
    return quoted;
}

std::string describe(const json& value) {
    if (value.is_number_integer() || value.is_number_float()) return value.dump();
    if (value.is_string()) return "string " + value.dump();
    return value.type_name();
}

// Builds the messages of one event: "<source>: event <index>: <what>".
class EventContext {
public:
    EventContext(std::string_view source, std::size_t index)
        : source_(source), field_("event " + std::to_string(index)) {}
    Error error(const std::string& what) const {
        Diagnostic d;
        d.code = Code::ScriptEvent;
        d.file = source_;
        d.field = field_;
        d.message = what;
        return Error(std::move(d));
    }

private:
    std::string source_;
    std::string field_;
};

Result<json> parseArray(std::string_view text, std::string_view source) {
    Result<json> parsed = parseJsonStrictly(text, std::string(source), Code::ScriptJson);
    if (!parsed) return parsed.error();
    json doc = std::move(*parsed);
    if (!doc.is_array())
        return fileError(std::string(source), std::string("expected a JSON array of events, got ") + doc.type_name(),
                         Code::ScriptJson);
    return doc;
}

// Checks that `event` is an object holding only known fields.
Status checkFields(const json& event, std::initializer_list<std::string_view> allowed,
                   const EventContext& ctx) {
    if (!event.is_object()) return ctx.error("expected an object, got " + describe(event));
    for (const auto& item : event.items()) {
        const std::string& key = item.key();
        if (key == "frame" || key == "time" || key == "type" || key == "comment") continue;
        if (std::ranges::find(allowed, std::string_view(key)) == allowed.end())
            return ctx.error("unknown field " + inQuotes(key));
    }
    if (event.contains("comment") && !event["comment"].is_string())
        return ctx.error("\"comment\" must be a string, got " + describe(event["comment"]));
    return okStatus();
}

Result<ScriptMoment> readMoment(const json& event, const EventContext& ctx) {
    bool hasFrame = event.contains("frame"), hasTime = event.contains("time");
    if (hasFrame && hasTime) return ctx.error("give one of \"frame\" and \"time\", not both");
    if (!hasFrame && !hasTime) return ctx.error("\"frame\" or \"time\" is missing");
    if (hasFrame) {
        const json& v = event["frame"];
        // nlohmann stores every non-negative integer literal as unsigned.
        constexpr auto kMaxFrame = std::uint64_t(std::numeric_limits<std::int64_t>::max());
        if (v.is_number_unsigned() && v.get<std::uint64_t>() <= kMaxFrame)
            return ScriptMoment::atFrame(v.get<std::int64_t>());
        return ctx.error("\"frame\" must be an integer >= 0, got " + describe(v));
    }
    const json& v = event["time"];
    if (v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= 0.0 &&
        v.get<double>() <= defaults::kMaxSeconds)
        return ScriptMoment::atTime(v.get<double>());
    return ctx.error("\"time\" must be a number of seconds from 0 to 1e9, got " + describe(v));
}

Result<std::string> readType(const json& event, const EventContext& ctx) {
    if (!event.contains("type")) return ctx.error("\"type\" is missing");
    const json& v = event["type"];
    if (!v.is_string()) return ctx.error("\"type\" must be a string, got " + describe(v));
    return v.get<std::string>();
}

Result<float> readCoordinate(const json& event, const char* field, const EventContext& ctx) {
    if (!event.contains(field)) return ctx.error(inQuotes(field) + " is missing");
    const json& v = event[field];
    if (!v.is_number() || !std::isfinite(v.get<double>()) || std::abs(v.get<double>()) > defaults::kMaxPixelCoordinate)
        return ctx.error(inQuotes(field) + " must be a number of pixels within +-1000000, got " + describe(v));
    return v.get<float>();
}

Result<glm::vec2> readPosition(const json& event, const EventContext& ctx) {
    auto x = readCoordinate(event, "x", ctx);
    if (!x) return x.error();
    auto y = readCoordinate(event, "y", ctx);
    if (!y) return y.error();
    return glm::vec2(*x, *y);
}

Result<int> readKey(const json& event, const EventContext& ctx) {
    if (!event.contains("key")) return ctx.error("\"key\" is missing");
    const json& v = event["key"];
    if (v.is_number_integer()) {
        if (v.is_number_unsigned() && v.get<std::uint64_t>() <= 255) return v.get<int>();
        return ctx.error("key code " + v.dump() + " is out of range 0..255");
    }
    if (!v.is_string())
        return ctx.error("\"key\" must be a key name or a keyCode, got " + describe(v));
    auto code = keyCodeFromName(v.get<std::string>());
    if (!code) return ctx.error(code.error().first().message);
    return *code;
}

// "to": {"frame"|"time": ..., "x": ..., "y": ...}, the end of a glide that starts at `start`.
Result<MouseGlide> readGlide(const json& to, const ScriptMoment& start, const EventContext& ctx) {
    if (!to.is_object()) return ctx.error("\"to\" must be an object such as {\"frame\": 60, \"x\": 10, \"y\": 20}, got " + describe(to));
    for (const auto& item : to.items())
        if (item.key() != "frame" && item.key() != "time" && item.key() != "x" && item.key() != "y")
            return ctx.error("\"to\": unknown field " + inQuotes(item.key()) + " (known: frame, time, x, y)");
    auto end = readMoment(to, ctx);
    if (!end) return ctx.error("\"to\": " + end.error().first().message);
    if (end->clock != start.clock)
        return ctx.error(std::string("\"to\" must use the event's own clock (\"") +
                         (start.clock == ScriptMoment::Clock::Frame ? "frame" : "time") + "\")");
    if (!firesEarlier(start, *end))
        return ctx.error("\"to\" must end after the event starts");
    auto position = readPosition(to, ctx);
    if (!position) return ctx.error("\"to\": " + position.error().first().message);
    return MouseGlide{*end, *position};
}

Result<MouseScriptEvent> readMouseEvent(const json& event, const EventContext& ctx) {
    if (auto s = checkFields(event, {"x", "y", "to"}, ctx); !s) return s.error();
    auto at = readMoment(event, ctx);
    if (!at) return at.error();
    auto type = readType(event, ctx);
    if (!type) return type.error();

    using Type = MouseScriptEvent::Type;
    MouseScriptEvent out;
    out.at = *at;
    if (*type == "down") out.type = Type::Down;
    else if (*type == "move") out.type = Type::Move;
    else if (*type == "up") out.type = Type::Up;
    else if (*type == "click") out.type = Type::Click;
    else return ctx.error("unknown type " + inQuotes(*type) + " (expected down, move, up, click)");

    if (event.contains("to")) {
        if (out.type != Type::Move) return ctx.error("\"to\" is only for \"move\" events");
        auto glide = readGlide(event["to"], out.at, ctx);
        if (!glide) return glide.error();
        out.to = *glide;
    }
    bool positionOptional = (out.type == Type::Up || out.to) && !event.contains("x") && !event.contains("y");
    if (!positionOptional) {
        auto pos = readPosition(event, ctx);
        if (!pos) return pos.error();
        out.position = *pos;
    }
    return out;
}

Result<KeyScriptEvent> readKeyEvent(const json& event, const EventContext& ctx) {
    if (auto s = checkFields(event, {"key"}, ctx); !s) return s.error();
    auto at = readMoment(event, ctx);
    if (!at) return at.error();
    auto type = readType(event, ctx);
    if (!type) return type.error();

    using Type = KeyScriptEvent::Type;
    KeyScriptEvent out;
    out.at = *at;
    if (*type == "down") out.type = Type::Down;
    else if (*type == "up") out.type = Type::Up;
    else if (*type == "tap") out.type = Type::Tap;
    else return ctx.error("unknown type " + inQuotes(*type) + " (expected down, up, tap)");

    auto key = readKey(event, ctx);
    if (!key) return key.error();
    out.keyCode = *key;
    return out;
}

template <class Script, class ReadEvent>
Result<Script> parseScript(std::string_view text, std::string_view source, ReadEvent read) {
    auto doc = parseArray(text, source);
    if (!doc) return doc.error();
    Script script;
    for (std::size_t i = 0; i < doc->size(); ++i) {
        auto event = read((*doc)[i], EventContext(source, i));
        if (!event) return event.error();
        script.events.push_back(*event);
    }
    using Event = typename decltype(script.events)::value_type;
    std::ranges::stable_sort(script.events, firesEarlier, &Event::at);
    return script;
}

}  // namespace

bool ScriptMoment::dueBefore(std::int64_t frameNumber, double iTime) const {
    return clock == Clock::Frame ? frameNumber >= frame : iTime + kTimeTolerance >= seconds;
}

bool firesEarlier(const ScriptMoment& a, const ScriptMoment& b) {
    if (a.clock != b.clock) return a.clock == ScriptMoment::Clock::Frame;
    return a.clock == ScriptMoment::Clock::Frame ? a.frame < b.frame : a.seconds < b.seconds;
}

Result<MouseScript> parseMouseScript(std::string_view jsonText, std::string_view sourceName) {
    return parseScript<MouseScript>(jsonText, sourceName, readMouseEvent);
}

Result<KeyScript> parseKeyScript(std::string_view jsonText, std::string_view sourceName) {
    return parseScript<KeyScript>(jsonText, sourceName, readKeyEvent);
}

MouseScript mouseHeldAt(float x, float y) {
    MouseScriptEvent down;
    down.at = ScriptMoment::atFrame(0);
    down.type = MouseScriptEvent::Type::Down;
    down.position = glm::vec2(x, y);
    return MouseScript{{down}};
}

}  // namespace toyhost
