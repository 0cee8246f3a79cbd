// ShaderAssembly: the generated header (content and order per SEMANTICS.md), Common pasting, the
// generated-line -> user-line mapping, and compiler-log translation for Mesa, ANGLE and NVIDIA.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "shader/ShaderAssembly.h"

using namespace toyhost;

namespace {

const std::string kPassCode =
    "// line 1\n"
    "float f(float x) { return x * 2.0; }\n"
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "    fragColor = vec4(f(fragCoord.x), 0.0, 0.0, 0.5);\n"
    "}\n";

AssembledShader assemble(PassId pass, const std::string* common = nullptr, std::string_view code = kPassCode,
                         std::array<SamplerType, kChannelCount> samplers = {}) {
    ShaderInputs in;
    in.pass = pass;
    in.common = common;
    in.code = code;
    in.samplers = samplers;
    return assembleFragmentShader(in);
}

// Splits on '\n'; a trailing newline does not make an extra empty line.
std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        lines.emplace_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

std::string headerOf(const AssembledShader& s) {
    std::string header;
    const std::vector<std::string> lines = splitLines(s.text);
    for (int i = 0; i < s.headerLines; ++i) header += lines.at(i) + "\n";
    return header;
}

// Offset of the first match of `pattern` in `text`, or npos.
size_t findRegex(const std::string& text, const std::string& pattern) {
    std::smatch m;
    if (!std::regex_search(text, m, std::regex(pattern))) return std::string::npos;
    return static_cast<size_t>(m.position(0));
}

int countMatches(const std::string& text, const std::string& pattern) {
    const std::regex re(pattern);
    return static_cast<int>(std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

// 1-based line of the first occurrence of `token` in the assembled text.
int generatedLineOf(const AssembledShader& s, const std::string& token) {
    const size_t at = s.text.find(token);
    EXPECT_NE(at, std::string::npos) << token;
    return 1 + static_cast<int>(std::count(s.text.begin(), s.text.begin() + static_cast<long>(at), '\n'));
}

const char* partName(SourceLine::Part p) {
    switch (p) {
        case SourceLine::Part::Header: return "Header";
        case SourceLine::Part::Common: return "Common";
        case SourceLine::Part::Pass: return "Pass";
    }
    return "?";
}

void expectMaps(const AssembledShader& s, int generated, SourceLine::Part part, int line) {
    const SourceLine got = mapGeneratedLine(s, generated);
    EXPECT_EQ(got.part, part) << "generated line " << generated << " -> " << partName(got.part) << " " << got.line;
    EXPECT_EQ(got.line, line) << "generated line " << generated << " -> " << partName(got.part);
}

}  // namespace

// ---- Header --------------------------------------------------------------------------------------

TEST(ShaderAssembly, HeaderStartsWithVersionThenPrecisionThenHwPerformance) {
    for (PassId pass : {PassId::Image, PassId::BufferA}) {
        const AssembledShader s = assemble(pass);
        const std::vector<std::string> lines = splitLines(s.text);
        ASSERT_FALSE(lines.empty());
        EXPECT_EQ(lines[0], "#version 300 es");
        const std::string header = headerOf(s);
        const size_t hw = header.find("\n#define HW_PERFORMANCE 1\n");
        ASSERT_NE(hw, std::string::npos) << header;
        for (const char* precision : {"precision highp float;", "precision highp int;", "precision mediump sampler3D;"}) {
            const size_t at = header.find(precision);
            EXPECT_NE(at, std::string::npos) << precision;
            EXPECT_LT(at, hw) << precision << " must come before HW_PERFORMANCE";
        }
        EXPECT_EQ(countMatches(header, "#version"), 1);
        EXPECT_EQ(countMatches(header, "HW_PERFORMANCE"), 1);
        // Nothing but preprocessor and precision statements before the uniforms.
        EXPECT_LT(hw, header.find("uniform"));
    }
}

TEST(ShaderAssembly, UniformsInDocumentedOrder) {
    const char* uniforms[][2] = {{"vec3", "iResolution"},        {"float", "iTime"},
                                 {"float", "iChannelTime\\[4\\]"}, {"vec4", "iMouse"},
                                 {"vec4", "iDate"},                {"float", "iSampleRate"},
                                 {"vec3", "iChannelResolution\\[4\\]"}, {"int", "iFrame"},
                                 {"float", "iTimeDelta"},          {"float", "iFrameRate"},
                                 {"sampler2D", "iChannel0"},       {"sampler2D", "iChannel1"},
                                 {"sampler2D", "iChannel2"},       {"sampler2D", "iChannel3"}};
    for (PassId pass : {PassId::Image, PassId::BufferC}) {
        const std::string header = headerOf(assemble(pass));
        const size_t hw = header.find("#define HW_PERFORMANCE 1");
        size_t previous = hw;
        for (const auto& [type, name] : uniforms) {
            const std::string pattern = std::string("\\n\\s*uniform\\s+") + type + "\\s+" + name + "\\s*;";
            const size_t at = findRegex(header, pattern);
            ASSERT_NE(at, std::string::npos) << passName(pass) << ": no " << type << " " << name;
            EXPECT_GT(at, previous) << passName(pass) << ": " << name << " out of order";
            EXPECT_EQ(countMatches(header, pattern), 1) << name;
            previous = at;
        }
        // Exactly these plain uniforms (plus the iCh structs in the Image pass).
        EXPECT_EQ(countMatches(header, "\\buniform\\s+(vec3|vec4|float|int|sampler2D|samplerCube|sampler3D)\\s"), 14);
    }
}

TEST(ShaderAssembly, ChannelStructsAndStAssertOnlyInImage) {
    const std::string image = headerOf(assemble(PassId::Image));
    for (int i = 0; i < 4; ++i) {
        const std::string pattern = "uniform\\s+struct\\s*\\{\\s*sampler2D\\s+sampler\\s*;\\s*vec3\\s+size\\s*;\\s*"
                                    "float\\s+time\\s*;\\s*int\\s+loaded\\s*;\\s*\\}\\s*iCh" +
                                    std::to_string(i) + "\\s*;";
        EXPECT_EQ(countMatches(image, pattern), 1) << "iCh" << i << " in\n" << image;
    }
    EXPECT_EQ(countMatches(image, "\\biCh[0-9]\\b"), 4);
    EXPECT_GE(countMatches(image, "void\\s+st_assert\\s*\\(\\s*bool\\s+\\w+\\s*\\)"), 1);
    EXPECT_GE(countMatches(image, "void\\s+st_assert\\s*\\(\\s*bool\\s+\\w+\\s*,\\s*int\\s+\\w+\\s*\\)"), 1);

    for (PassId buffer : {PassId::BufferA, PassId::BufferB, PassId::BufferC, PassId::BufferD}) {
        const std::string header = headerOf(assemble(buffer));
        EXPECT_EQ(countMatches(header, "\\biCh[0-9]\\b"), 0) << passName(buffer);
        EXPECT_EQ(header.find("struct"), std::string::npos) << passName(buffer);
        EXPECT_EQ(header.find("st_assert"), std::string::npos) << passName(buffer);
    }
}

TEST(ShaderAssembly, MainWrapperImageForcesAlphaBuffersKeepIt) {
    for (PassId pass : {PassId::Image, PassId::BufferA, PassId::BufferD}) {
        const std::string header = headerOf(assemble(pass));
        // The forward declaration comes before main().
        const size_t declaration =
            findRegex(header, "void\\s+mainImage\\s*\\(\\s*out\\s+vec4\\s+\\w+\\s*,\\s*in\\s+vec2\\s+\\w+\\s*\\)\\s*;");
        const size_t main = findRegex(header, "void\\s+main\\s*\\(\\s*void\\s*\\)");
        ASSERT_NE(declaration, std::string::npos) << passName(pass);
        ASSERT_NE(main, std::string::npos) << passName(pass);
        EXPECT_LT(declaration, main);
        EXPECT_EQ(countMatches(header, "\\bout\\s+vec4\\s+\\w+\\s*;"), 1) << passName(pass) << ": one output";

        const std::string body = header.substr(main);
        const size_t init = body.find("vec4 color = vec4(0.0,0.0,0.0,1.0);");
        const size_t call = body.find("mainImage( color, gl_FragCoord.xy );");
        ASSERT_NE(init, std::string::npos) << passName(pass);
        ASSERT_NE(call, std::string::npos) << passName(pass);
        EXPECT_LT(init, call);
        if (pass == PassId::Image) {
            const size_t write = body.find("shadertoy_out_color = vec4(color.xyz,1.0);");
            ASSERT_NE(write, std::string::npos);
            EXPECT_LT(call, write);
            EXPECT_NE(header.find("out vec4 shadertoy_out_color;"), std::string::npos);
        } else {
            const size_t write = body.find("outColor = color;");
            ASSERT_NE(write, std::string::npos) << passName(pass);
            EXPECT_LT(call, write);
            EXPECT_EQ(body.find("color.xyz"), std::string::npos) << passName(pass) << " must keep alpha";
            EXPECT_NE(header.find("out vec4 outColor;"), std::string::npos);
        }
    }
}

TEST(ShaderAssembly, SamplerKeywordsPerChannel) {
    const std::array<SamplerType, 4> samplers{SamplerType::SamplerCube, SamplerType::Sampler2D, SamplerType::Sampler3D,
                                              SamplerType::SamplerCube};
    const char* expected[] = {"samplerCube", "sampler2D", "sampler3D", "samplerCube"};
    for (PassId pass : {PassId::Image, PassId::BufferB}) {
        const std::string header = headerOf(assemble(pass, nullptr, kPassCode, samplers));
        for (int i = 0; i < 4; ++i) {
            EXPECT_EQ(countMatches(header, "\\buniform\\s+" + std::string(expected[i]) + "\\s+iChannel" +
                                               std::to_string(i) + "\\s*;"),
                      1)
                << passName(pass) << " iChannel" << i;
            if (pass == PassId::Image) {
                EXPECT_EQ(countMatches(header, "struct\\s*\\{\\s*" + std::string(expected[i]) +
                                                   "\\s+sampler\\s*;[^}]*\\}\\s*iCh" + std::to_string(i) + "\\s*;"),
                          1)
                    << "iCh" << i << " sampler type";
            }
        }
    }
}

// ---- Common and pass code ------------------------------------------------------------------------

TEST(ShaderAssembly, TextIsHeaderThenCommonAndNewlineThenPassCode) {
    const std::string common = "#define TAU 6.2831853\nfloat sq(float x) { return x * x; }";
    for (PassId pass : {PassId::Image, PassId::BufferA}) {
        const AssembledShader without = assemble(pass);
        const std::string header = headerOf(without);
        EXPECT_EQ(without.text, header + kPassCode);
        EXPECT_EQ(without.headerLines, static_cast<int>(std::count(header.begin(), header.end(), '\n')));
        EXPECT_EQ(without.commonLines, 0);
        EXPECT_EQ(without.passFirstLine, without.headerLines + 1);

        const AssembledShader with = assemble(pass, &common);
        EXPECT_EQ(with.text, header + common + "\n" + kPassCode);
        EXPECT_EQ(with.headerLines, without.headerLines);
        EXPECT_EQ(with.commonLines, 2);
        EXPECT_EQ(with.passFirstLine, with.headerLines + 3);

        const std::string commonWithNewline = common + "\n";
        const AssembledShader withNewline = assemble(pass, &commonWithNewline);
        EXPECT_EQ(withNewline.text, header + commonWithNewline + "\n" + kPassCode);
        EXPECT_EQ(withNewline.commonLines, 3);  // the pasted newline adds an empty line
        EXPECT_EQ(withNewline.passFirstLine, withNewline.headerLines + 4);

        const std::string empty;
        const AssembledShader withEmpty = assemble(pass, &empty);
        EXPECT_EQ(withEmpty.text, header + "\n" + kPassCode);
        EXPECT_EQ(withEmpty.commonLines, 1);
        EXPECT_EQ(withEmpty.passFirstLine, withEmpty.headerLines + 2);
    }
}

TEST(ShaderAssembly, FullscreenVertexShaderIsGlslEs300) {
    const std::string vs = fullscreenVertexShader();
    EXPECT_EQ(vs.rfind("#version 300 es\n", 0), 0u);
    EXPECT_NE(vs.find("gl_VertexID"), std::string::npos);
    EXPECT_NE(vs.find("gl_Position"), std::string::npos);
}

// ---- Line mapping --------------------------------------------------------------------------------

TEST(ShaderAssembly, MapGeneratedLineWithoutCommon) {
    const AssembledShader s = assemble(PassId::Image);
    const int h = s.headerLines;
    ASSERT_GT(h, 20);
    expectMaps(s, 1, SourceLine::Part::Header, 1);
    expectMaps(s, h, SourceLine::Part::Header, h);
    expectMaps(s, h + 1, SourceLine::Part::Pass, 1);
    expectMaps(s, h + 4, SourceLine::Part::Pass, 4);
}

TEST(ShaderAssembly, MapGeneratedLineWithCommonEndingWithoutNewline) {
    const std::string common = "c1\nc2\nc3";
    const AssembledShader s = assemble(PassId::BufferA, &common);
    const int h = s.headerLines;
    expectMaps(s, h, SourceLine::Part::Header, h);
    expectMaps(s, h + 1, SourceLine::Part::Common, 1);
    expectMaps(s, h + 3, SourceLine::Part::Common, 3);
    expectMaps(s, h + 4, SourceLine::Part::Pass, 1);
    expectMaps(s, h + 8, SourceLine::Part::Pass, 5);
}

TEST(ShaderAssembly, MapGeneratedLineWithCommonEndingWithNewline) {
    const std::string common = "c1\nc2\nc3\n";
    const AssembledShader s = assemble(PassId::Image, &common);
    const int h = s.headerLines;
    expectMaps(s, h + 1, SourceLine::Part::Common, 1);
    expectMaps(s, h + 3, SourceLine::Part::Common, 3);
    expectMaps(s, h + 4, SourceLine::Part::Common, 4);  // the empty line of the pasted newline
    expectMaps(s, h + 5, SourceLine::Part::Pass, 1);
    expectMaps(s, h + 9, SourceLine::Part::Pass, 5);
}

// Marker tokens on known lines: wherever they land in the assembled text, the mapping must lead
// back to their line, for every way Common can end (and with CRLF line endings).
TEST(ShaderAssembly, MappingIsRightByConstruction) {
    std::string pass;
    for (int line = 1; line <= 40; ++line) pass += "// pass line " + std::to_string(line) + " PASS_MARK_" + std::to_string(line) + "_\n";
    std::string passNoFinalNewline = pass.substr(0, pass.size() - 1);
    std::string passCrlf;
    for (int line = 1; line <= 40; ++line) passCrlf += "PASS_MARK_" + std::to_string(line) + "_ x\r\n";

    std::string common;
    for (int line = 1; line <= 7; ++line) common += "COMMON_MARK_" + std::to_string(line) + "_\n";
    const std::string commonNoFinalNewline = common.substr(0, common.size() - 1);

    const std::string* commons[] = {nullptr, &common, &commonNoFinalNewline};
    const std::string* passes[] = {&pass, &passNoFinalNewline, &passCrlf};
    for (PassId id : {PassId::Image, PassId::BufferB}) {
        for (const std::string* c : commons) {
            for (const std::string* p : passes) {
                const AssembledShader s = assemble(id, c, *p);
                for (int line = 1; line <= 40; ++line) {
                    const SourceLine got = mapGeneratedLine(s, generatedLineOf(s, "PASS_MARK_" + std::to_string(line) + "_"));
                    EXPECT_EQ(got.part, SourceLine::Part::Pass);
                    EXPECT_EQ(got.line, line) << "pass marker, common " << (c ? "yes" : "no");
                }
                if (!c) continue;
                for (int line = 1; line <= 7; ++line) {
                    const SourceLine got = mapGeneratedLine(s, generatedLineOf(s, "COMMON_MARK_" + std::to_string(line) + "_"));
                    EXPECT_EQ(got.part, SourceLine::Part::Common);
                    EXPECT_EQ(got.line, line) << "common marker";
                }
                // Every generated line maps to a line whose text is the generated line's text.
                const std::vector<std::string> generated = splitLines(s.text);
                const std::vector<std::string> header = splitLines(headerOf(s));
                const std::vector<std::string> passLines = splitLines(*p);
                const std::vector<std::string> commonLines = c ? splitLines(*c) : std::vector<std::string>{};
                for (int g = 1; g <= static_cast<int>(generated.size()); ++g) {
                    const SourceLine where = mapGeneratedLine(s, g);
                    const std::vector<std::string>& source = where.part == SourceLine::Part::Header ? header
                                                             : where.part == SourceLine::Part::Common ? commonLines
                                                                                                      : passLines;
                    const std::string expected =
                        where.line <= static_cast<int>(source.size()) ? source[where.line - 1] : std::string();
                    EXPECT_EQ(generated[g - 1], expected) << "generated line " << g << " -> " << partName(where.part)
                                                          << " " << where.line;
                }
            }
        }
    }
}

// ---- Compiler logs -------------------------------------------------------------------------------

namespace {
struct LogFixture {
    std::string common = "float c1;\nfloat c2;\nfloat c3;";
    AssembledShader shader = assemble(PassId::Image, &common);
    int h = shader.headerLines;
    int passLine(int n) const { return shader.passFirstLine + n - 1; }
    std::string translate(const std::string& log) const {
        return translateCompilerLog(shader, log, "/toys/common.glsl", "/toys/image.glsl");
    }
};
}  // namespace

TEST(ShaderAssembly, TranslateMesaLog) {
    LogFixture f;
    const std::string log = "0:" + std::to_string(f.passLine(4)) + "(12): error: `foo' undeclared\n" +
                            "0:" + std::to_string(f.h + 2) + "(7): warning: unused variable\n" +
                            "0:3(1): error: something in the header\n";
    EXPECT_EQ(f.translate(log),
              "/toys/image.glsl:4:12: error: `foo' undeclared\n"
              "/toys/common.glsl:2:7: warning: unused variable\n"
              "<toyhost header>:3:1: error: something in the header");
}

TEST(ShaderAssembly, TranslateAngleLog) {
    LogFixture f;
    const std::string log = "ERROR: 0:" + std::to_string(f.passLine(2)) + ": 'foo' : undeclared identifier\n" +
                            "WARNING: 0:" + std::to_string(f.h + 3) + ": 'bar' : unused\n" +
                            "ERROR: 2 compilation errors.  No code generated.\n";
    EXPECT_EQ(f.translate(log),
              "/toys/image.glsl:2: error: 'foo' : undeclared identifier\n"
              "/toys/common.glsl:3: warning: 'bar' : unused\n"
              "ERROR: 2 compilation errors.  No code generated.");
}

TEST(ShaderAssembly, TranslateNvidiaLog) {
    LogFixture f;
    const std::string log = "0(" + std::to_string(f.passLine(5)) + ") : error C1008: undefined variable \"foo\"\n" +
                            "0(" + std::to_string(f.h + 1) + ") : warning C7022: unrecognized profile specifier\n";
    EXPECT_EQ(f.translate(log),
              "/toys/image.glsl:5: error C1008: undefined variable \"foo\"\n"
              "/toys/common.glsl:1: warning C7022: unrecognized profile specifier");
}

TEST(ShaderAssembly, TranslateLeavesLinesWithoutLocationAndHandlesCrlf) {
    LogFixture f;
    const std::string log = "Compilation failed.\r\n\r\n0:" + std::to_string(f.passLine(1)) +
                            "(3): error: syntax error, unexpected IDENTIFIER\r\nlink: not attempted";
    EXPECT_EQ(f.translate(log),
              "Compilation failed.\n"
              "/toys/image.glsl:1:3: error: syntax error, unexpected IDENTIFIER\n"
              "link: not attempted");
    EXPECT_EQ(f.translate(""), "");
}

TEST(ShaderAssembly, TranslateWithoutCommon) {
    const AssembledShader s = assemble(PassId::BufferA);
    const std::string log = "0:" + std::to_string(s.headerLines + 3) + "(9): error: x\n0:" +
                            std::to_string(s.headerLines) + "(1): error: y";
    EXPECT_EQ(translateCompilerLog(s, log, "common.glsl", "buf.glsl"),
              "buf.glsl:3:9: error: x\n<toyhost header>:" + std::to_string(s.headerLines) + ":1: error: y");
}
