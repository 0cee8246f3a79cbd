// TexelCornerReads: which texture() reads of a buffer land where linear and nearest differ (texel
// corners; uv-space steps in a pass that compares exactly) and which land on exact centres, where
// the filter makes no difference (measured on llvmpipe: docs/porting.md). Pure.
#include <gtest/gtest.h>

#include <string>

#include "shader/TexelCornerReads.h"

using namespace toyhost;

namespace {

std::string mainImage(const std::string& body) {
    return "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n" + body + "\n}\n";
}

std::vector<TexelLanding> landings(const std::string& code) {
    std::vector<TexelLanding> out;
    for (const TexelRead& read : texelReads(code)) out.push_back(read.landing);
    return out;
}

ManifestDesc automaton(const std::string& code, Filter filter) {
    ManifestDesc desc;
    PassDesc pass;
    pass.id = PassId::BufferA;
    pass.sourceName = "life/buffer_a.glsl";
    pass.code = code;
    pass.channels[1].kind = ChannelKind::Buffer;
    pass.channels[1].buffer = 0;
    pass.channels[1].sampler.filter = filter;
    desc.passes.push_back(pass);
    return desc;
}

constexpr TexelLanding kCorner = TexelLanding::Corner;
constexpr TexelLanding kStep = TexelLanding::UvStep;
using L = std::vector<TexelLanding>;

}  // namespace

TEST(TexelCornerReads, ExactCentresAreNotListed) {
    EXPECT_EQ(landings(mainImage("fragColor = texture(iChannel0, fragCoord / iResolution.xy);")), L{});
    EXPECT_EQ(landings(mainImage("fragColor = texture(iChannel0, fragCoord.xy / iResolution.xy);")), L{});
    EXPECT_EQ(landings(mainImage("fragColor = texture(iChannel0, (fragCoord + vec2(1, 0)) / iResolution.xy);")), L{});
    EXPECT_EQ(landings(mainImage("fragColor = texture(iChannel2, (fragCoord + vec2(0., -1.)) / iChannelResolution[2].xy);")), L{});
    EXPECT_EQ(landings(mainImage("ivec2 p = ivec2(fragCoord);\n"
                                 "fragColor = texture(iChannel0, (vec2(p) + 0.5) / iResolution.xy);")), L{});
    EXPECT_EQ(landings(mainImage("fragColor = texture(iChannel0, (floor(fragCoord) + 0.5) / vec2(textureSize(iChannel0, 0)));")), L{});
    // Loop integers as the offset, and a resolution held in a variable.
    EXPECT_EQ(landings(mainImage("vec2 R = iResolution.xy; float n = 0.0;\n"
                                 "for (int y = -1; y <= 1; y++) for (int x = -1; x <= 1; x++)\n"
                                 "  n += texture(iChannel0, (fragCoord + vec2(x, y)) / R).x;")), L{});
}

TEST(TexelCornerReads, CornersAreListedWithTheirChannelAndLine) {
    const std::string code = mainImage("vec2 uv = fragCoord / iResolution.xy;\n"
                                       "vec2 cell = floor(uv * iResolution.xy) / iResolution.xy;\n"
                                       "fragColor = texture(iChannel1, cell);\n"
                                       "ivec2 p = ivec2(fragCoord) + ivec2(1, 0);\n"
                                       "fragColor += texture(iChannel3, vec2(p) / iResolution.xy);\n"
                                       "fragColor += texture(iChannel0, (fragCoord + 0.5) / iResolution.xy);\n"
                                       "fragColor += textureLod(iChannel2, floor(fragCoord) / iResolution.xy, 0.0);");
    const std::vector<TexelRead> reads = texelReads(code);
    ASSERT_EQ(reads.size(), 4u);
    EXPECT_EQ(reads[0].channel, 1);
    EXPECT_EQ(reads[0].line, 4);
    EXPECT_EQ(reads[1].channel, 3);
    EXPECT_EQ(reads[1].line, 6);
    EXPECT_EQ(reads[2].channel, 0);
    EXPECT_EQ(reads[3].channel, 2);
    for (const TexelRead& read : reads) EXPECT_EQ(read.landing, kCorner);
}

TEST(TexelCornerReads, GolfedParameterNamesAreFollowed) {
    EXPECT_EQ(landings("void mainImage(out vec4 o, vec2 u) { o = texture(iChannel0, floor(u) / iResolution.xy); }"),
              L{kCorner});
    EXPECT_EQ(landings("void mainImage(out vec4 o, vec2 u) { o = texture(iChannel0, u / iResolution.xy); }"), L{});
}

TEST(TexelCornerReads, HelperParametersHaveWhatTheirCallSitesPass) {
    const std::string helper = "float cell(vec2 p, vec2 o) { return texture(iChannel0, (p + o) / iResolution.xy).x; }\n";
    EXPECT_EQ(landings(helper + mainImage("float n = cell(fragCoord, vec2(1, 0)) + cell(fragCoord, vec2(0, -1));")), L{});
    EXPECT_EQ(landings(helper + mainImage("vec2 q = floor(fragCoord);\n"
                                          "float n = cell(q, vec2(1, 0)) + cell(q, vec2(0, -1));")),
              L{kCorner});
    // Call sites that disagree (a corner here, a centre there) leave the parameter unknown.
    EXPECT_EQ(landings(helper + mainImage("float n = cell(floor(fragCoord), vec2(1, 0)) + cell(fragCoord, vec2(0));")), L{});
}

TEST(TexelCornerReads, UvStepsAreListedApartFromCorners) {
    EXPECT_EQ(landings(mainImage("vec2 uv = fragCoord / iResolution.xy;\n"
                                 "fragColor = texture(iChannel0, uv + vec2(1, 0) / iResolution.xy);")),
              L{kStep});
    EXPECT_EQ(landings(mainImage("vec2 uv = fragCoord / iResolution.xy; vec2 px = 1.0 / iResolution.xy;\n"
                                 "fragColor = texture(iChannel0, uv - vec2(0, 1) * px);")),
              L{kStep});
}

TEST(TexelCornerReads, WhatTheScanCannotFollowIsNotListed) {
    // A parameter, a variable written twice, a scaled or warped coordinate, a texelFetch.
    EXPECT_EQ(landings("vec4 at(vec2 q) { return texture(iChannel0, floor(q) / iResolution.xy); }"), L{});
    EXPECT_EQ(landings(mainImage("vec2 p = floor(fragCoord); p += sin(iTime);\n"
                                 "fragColor = texture(iChannel0, p / iResolution.xy);")),
              L{});
    EXPECT_EQ(landings(mainImage("fragColor = texture(iChannel0, floor(fragCoord * 0.25) / iResolution.xy);")), L{});
    EXPECT_EQ(landings(mainImage("fragColor = texture(iChannel0, 0.5 * fragCoord / iResolution.xy);")), L{});
    EXPECT_EQ(landings(mainImage("fragColor = texelFetch(iChannel0, ivec2(fragCoord), 0);")), L{});
    EXPECT_EQ(landings(mainImage("// texture(iChannel0, floor(fragCoord) / iResolution.xy)\n"
                                 "fragColor = vec4(0);")),
              L{});
}

TEST(TexelCornerReads, ExactComparisonsAreThoseAgainstAFloatLiteral) {
    EXPECT_TRUE(comparesExactly("float a = n == 3.0 ? 1.0 : 0.0;"));
    EXPECT_TRUE(comparesExactly("if (1.0 != c) discard;"));
    EXPECT_FALSE(comparesExactly("float a = step(0.5, n); if (a > 2.5) a = 0.0;"));
    EXPECT_FALSE(comparesExactly("if (iFrame == frame) return;"));
    EXPECT_FALSE(comparesExactly("if (iFrame == 0) { fragColor = vec4(0); return; }"));
    EXPECT_FALSE(comparesExactly("// n == 3.0\n"));
}

TEST(TexelCornerReads, AWarningNamesFilePassChannelLineAndTheSetting) {
    const std::string corner = mainImage("ivec2 p = ivec2(fragCoord);\n"
                                         "float n = texture(iChannel1, vec2(p + ivec2(1, 0)) / iResolution.xy).x;\n"
                                         "fragColor = vec4(n == 1.0);");
    const std::vector<Diagnostic> warnings = texelCornerWarnings(automaton(corner, Filter::Linear));
    ASSERT_EQ(warnings.size(), 1u);
    const Diagnostic& w = warnings[0];
    EXPECT_EQ(w.severity, Severity::Warning);
    EXPECT_EQ(w.code, Code::ChannelFilter);
    EXPECT_EQ(w.file, "life/buffer_a.glsl");
    EXPECT_EQ(w.pass, "Buffer A");
    EXPECT_EQ(w.channel, 1);
    EXPECT_EQ(w.line, 3);
    EXPECT_NE(w.message.find("texel corners"), std::string::npos) << w.message;
    EXPECT_NE(w.message.find("\"filter\": \"nearest\""), std::string::npos) << w.message;
    EXPECT_NE(w.message.find("\"filter\": \"linear\""), std::string::npos) << w.message;
    // The same reads with nearest, or at centres, say nothing.
    EXPECT_TRUE(texelCornerWarnings(automaton(corner, Filter::Nearest)).empty());
    const std::string centres = mainImage("float n = texture(iChannel1, (fragCoord + vec2(1, 0)) / iResolution.xy).x;\n"
                                          "fragColor = vec4(n == 1.0);");
    EXPECT_TRUE(texelCornerWarnings(automaton(centres, Filter::Linear)).empty());
}

TEST(TexelCornerReads, UvStepsWarnOnlyWhereValuesAreComparedExactly) {
    const std::string step = "vec2 uv = fragCoord / iResolution.xy;\n"
                             "float n = texture(iChannel1, uv + vec2(1, 0) / iResolution.xy).x;\n";
    const std::vector<Diagnostic> exact =
        texelCornerWarnings(automaton(mainImage(step + "fragColor = vec4(n == 1.0);"), Filter::Linear));
    ASSERT_EQ(exact.size(), 1u);
    EXPECT_EQ(exact[0].line, 3);
    EXPECT_NE(exact[0].message.find("compares values exactly"), std::string::npos) << exact[0].message;
    EXPECT_TRUE(texelCornerWarnings(automaton(mainImage(step + "fragColor = vec4(step(0.5, n));"), Filter::Linear)).empty());
    EXPECT_TRUE(texelCornerWarnings(automaton(mainImage(step + "fragColor = vec4(n == 1.0);"), Filter::Nearest)).empty());
}

TEST(TexelCornerReads, OnlyBufferChannelsAreChecked) {
    ManifestDesc desc = automaton(mainImage("fragColor = texture(iChannel1, floor(fragCoord) / iResolution.xy);"),
                                  Filter::Linear);
    desc.passes[0].channels[1].kind = ChannelKind::ImageFile;  // a picture's corners are the author's business
    EXPECT_TRUE(texelCornerWarnings(desc).empty());
    desc.passes[0].channels[1].kind = ChannelKind::Buffer;
    desc.passes[0].channels[1].sampler.filter = Filter::Mipmap;
    EXPECT_EQ(texelCornerWarnings(desc).size(), 1u);
}
