#include "shader/PassSource.h"

#include <cctype>

#include "shader/BrowserPreprocess.h"
#include "shader/ShaderAssembly.h"

namespace toyhost {

bool definesFunctionMacro(std::string_view code) {
    std::size_t lineStart = 0;
    while (lineStart < code.size()) {
        std::size_t lineEnd = code.find('\n', lineStart);
        if (lineEnd == std::string_view::npos) lineEnd = code.size();
        std::string_view line = code.substr(lineStart, lineEnd - lineStart);
        lineStart = lineEnd + 1;
        auto skipSpaces = [&] {
            while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
        };
        skipSpaces();
        if (line.empty() || line.front() != '#') continue;
        line.remove_prefix(1);
        skipSpaces();
        if (!line.starts_with("define")) continue;
        line.remove_prefix(6);
        if (line.empty() || (line.front() != ' ' && line.front() != '\t')) continue;
        skipSpaces();
        std::size_t name = 0;
        while (name < line.size() && (std::isalnum(static_cast<unsigned char>(line[name])) || line[name] == '_')) ++name;
        // A function-like macro's parenthesis follows its name directly (C and GLSL alike).
        if (name > 0 && name < line.size() && line[name] == '(') return true;
    }
    return false;
}

PassSource preparePassSource(const ManifestDesc& manifest, const PassDesc& pass, std::span<const MacroDefine> defines) {
    ShaderInputs inputs;
    inputs.pass = pass.id;
    inputs.sound = pass.id == PassId::Sound;
    for (int c = 0; c < kChannelCount; ++c) inputs.samplers[c] = pass.channels[c].samplerType;
    inputs.common = manifest.commonSource ? &manifest.commonCode : nullptr;
    inputs.code = pass.code;
    inputs.defines = defines;
    AssembledShader fragment = assembleFragmentShader(inputs);
    PassSource source;
    source.text = std::move(fragment.text);
    source.plainText = std::move(fragment.plainText);
    source.parts = std::move(fragment.parts);
    if (definesFunctionMacro(pass.code) || (manifest.commonSource && definesFunctionMacro(manifest.commonCode))) {
        // A failure here only means there is no fallback: the driver's own messages stand.
        if (Result<std::string> expanded = preprocessLikeBrowsers(source.text)) source.browserText = std::move(*expanded);
        if (source.plainText == source.text) source.browserPlainText = source.browserText;
        else if (Result<std::string> expanded = preprocessLikeBrowsers(source.plainText))
            source.browserPlainText = std::move(*expanded);
    }
    return source;
}

}  // namespace toyhost
