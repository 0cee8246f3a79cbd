// The settings' and defaults' one lists (toyhost/Settings.h, toyhost/Defaults.h, issue 41): the
// public runDefaults() gives every default (the sampling ones read 0 while the struct was filled by
// hand), every setting's fallback names a default that a session given nothing really takes, and
// the validation table refuses a bad value of each checked setting naming it. No GL context: the
// session's preparation only.
#include "GlTestSupport.h"

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <type_traits>

#include <toyhost/Defaults.h>
#include <toyhost/Settings.h>

#include "session/SessionOptions.h"
#include "session/SettingChecks.h"

namespace toyhost::testing {
namespace {

// Every default of the list by member name, as numbers.
std::map<std::string, double> defaultsByMember() {
    const Defaults d = runDefaults();
    std::map<std::string, double> out;
#define TOYHOST_TEST_DEFAULT(Type, member, key, value, what) out[#member] = static_cast<double>(d.member);
    TOYHOST_DEFAULTS(TOYHOST_TEST_DEFAULT)
#undef TOYHOST_TEST_DEFAULT
    return out;
}

template <class T>
std::optional<double> asNumber(const std::optional<T>& value) {
    if constexpr (std::is_arithmetic_v<T>) {
        if (value) return static_cast<double>(*value);
    }
    return std::nullopt;
}
template <class T>
std::optional<double> asNumber(const T& value) {
    if constexpr (std::is_arithmetic_v<T>) return static_cast<double>(value);
    return std::nullopt;
}

// A resolved setting by member name, as a number (absent or not a number: nullopt).
std::optional<double> settingByMember(const SessionSettings& s, const std::string& name) {
#define TOYHOST_TEST_SETTING(Type, member, key, initial, fallback) \
    if (name == #member) return asNumber(s.member);
    TOYHOST_SESSION_SETTINGS(TOYHOST_TEST_SETTING)
#undef TOYHOST_TEST_SETTING
    ADD_FAILURE() << "no setting " << name;
    return std::nullopt;
}

TEST(SettingsList, RunDefaultsGivesEveryDefaultOfTheList) {
    const Defaults d = runDefaults();
    EXPECT_EQ(d.supersample, 1);
    EXPECT_EQ(d.motionBlur, 1);
    EXPECT_EQ(d.shutterDegrees, 180.0);
    EXPECT_EQ(d.maxSupersample, 16);
    EXPECT_EQ(d.maxMotionBlur, 256);
    EXPECT_EQ(d.maxSamplesPerFrame, 4096);
    EXPECT_EQ(d.width, 800);
    EXPECT_EQ(d.height, 450);
    for (const auto& [member, value] : defaultsByMember()) EXPECT_GT(value, 0) << member << " has no default";
}

TEST(SettingsList, EveryFallbackIsADefaultThatASessionGivenNothingTakes) {
    const std::filesystem::path dir = freshOutputDir("settings_list");
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5); }\n");
    SessionOptions options;
    options.target = dir;
    Result<SessionPlan> plan = prepareSession(options);
    ASSERT_TRUE(plan.ok()) << plan.error().text();
    const std::map<std::string, double> defaults = defaultsByMember();
    int checked = 0;
    for (const SettingField& field : settingFields()) {
        if (std::string(field.fallback) == "initial") continue;
        auto it = defaults.find(field.fallback);
        ASSERT_NE(it, defaults.end()) << field.member << ": fallback " << field.fallback << " is not a default";
        const std::optional<double> taken = settingByMember(plan->options.settings, field.member);
        ASSERT_TRUE(taken.has_value()) << field.member << " was left unset";
        EXPECT_EQ(*taken, it->second) << field.member;
        ++checked;
    }
    EXPECT_GE(checked, 8);  // size (2), fps, both timeouts, the three sampling settings
}

TEST(SettingsList, TheValidationTableRefusesABadValueOfEachCheckedSettingNamingIt) {
    auto refused = [](const SessionSettings& s) {
        Status checked = checkSessionSettings(s, SettingContext{});
        return checked ? std::string("(accepted)") : checked.error().first().field;
    };
    EXPECT_EQ(refused(SessionSettings{}), "(accepted)");
    SessionSettings s;
    s.width = 0;
    s.height = 4;
    EXPECT_EQ(refused(s), "size");
    s = {};
    s.fps = std::nan("");
    EXPECT_EQ(refused(s), "fps");
    s = {};
    s.startTime = 1e300;
    EXPECT_EQ(refused(s), "start_time");
    s = {};
    s.date = "2026-13-45T99:99:99";
    EXPECT_EQ(refused(s), "date");
    s = {};
    s.frameTimeout = -1;
    EXPECT_EQ(refused(s), "frame_timeout");
    s = {};
    s.compileTimeout = 0.01;
    EXPECT_EQ(refused(s), "compile_timeout");
    s = {};
    s.supersample = 17;
    EXPECT_EQ(refused(s), "supersample");
    s = {};
    s.motionBlur = 0;
    EXPECT_EQ(refused(s), "motion_blur");
    s = {};
    s.shutterDegrees = 400;
    EXPECT_EQ(refused(s), "shutter");
    s = {};
    s.dither = true;
    EXPECT_EQ(refused(s), "dither");
    s = {};
    s.motionBlur = 2;
    s.shutterOffset = "middle";
    EXPECT_EQ(refused(s), "shutter_offset");
    s = {};
    s.sampleSpace = "gamma";
    EXPECT_EQ(refused(s), "sample_space");
    s = {};
    s.defines = {"GL_NOPE"};
    EXPECT_EQ(refused(s), "defines");
    s = {};
    s.mediaFolders = {freshOutputDir("settings_list_media") / "missing"};
    EXPECT_NE(refused(s), "(accepted)");
    s = {};
    s.mouseScript = freshOutputDir("settings_list_script") / "missing.json";
    EXPECT_NE(refused(s), "(accepted)");
}

}  // namespace
}  // namespace toyhost::testing
