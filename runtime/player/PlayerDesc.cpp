#include "player/PlayerDesc.h"

#include <future>
#include <optional>

#include <string>

#include "core/Defaults.h"
#include "shader/ChannelUse.h"
#include "shader/ExpressionDepth.h"
#include "shader/LoopCap.h"
#include "shader/SourceText.h"
#include "shader/TexelCornerReads.h"

namespace toyhost {

PlayerDesc withDefaults(PlayerDesc desc) {
    if (desc.width == 0) desc.width = defaults::kCanvasWidth;
    if (desc.height == 0) desc.height = defaults::kCanvasHeight;
    return desc;
}

Status checkCanvasSize(int width, int height) {
    if (width < 1 || height < 1 || width > defaults::kMaxCanvasSide || height > defaults::kMaxCanvasSide)
        return Error("canvas size " + std::to_string(width) + "x" + std::to_string(height) + " is not between 1x1 and " +
                         std::to_string(defaults::kMaxCanvasSide) + "x" + std::to_string(defaults::kMaxCanvasSide),
                     Code::UsageSize);
    return okStatus();
}

Result<PlayerPlan> planPlayer(ManifestDesc manifest, const MediaOptions& media, MacroDefines defines) {
    // Bytes GL would drop or misread: every pass and Common, all reported together.
    std::vector<Diagnostic> textProblems;
    if (manifest.commonSource) checkShaderText(manifest.commonCode, manifest.commonName, "Common", textProblems);
    for (PassDesc& pass : manifest.passes) checkShaderText(pass.code, pass.sourceName, passName(pass.id), textProblems);
    if (!textProblems.empty()) return Error(std::move(textProblems));
    // What the site refuses for its depth, refused here too; what it may refuse, a warning.
    std::vector<Diagnostic> refused, depthWarnings;
    for (Diagnostic& problem : siteDepthProblems(manifest))
        (problem.severity == Severity::Error ? refused : depthWarnings).push_back(std::move(problem));
    if (!refused.empty()) return Error(std::move(refused));
    // The shader texts first, each pass whose expansion needs a cpp child on its own thread, so
    // that those run while the media below load (a plan is made once per run or reload).
    const bool commonMacros = manifest.commonSource && definesFunctionMacro(manifest.commonCode);
    auto prepare = [&](const PassDesc& pass) -> std::future<PassSource> {
        const bool child = commonMacros || definesFunctionMacro(pass.code);
        return std::async(child ? std::launch::async : std::launch::deferred,
                          [&manifest, &pass, &defines] { return preparePassSource(manifest, pass, defines); });
    };
    std::vector<std::future<PassSource>> preparing;
    for (const PassDesc& pass : manifest.passes) preparing.push_back(prepare(pass));
    std::optional<std::future<PassSource>> preparingSound;
    if (manifest.sound) preparingSound = prepare(*manifest.sound);
    // Every child is waited for on every path out (a future from std::async waits when it goes).
    const MediaResolver resolver = makeMediaResolver(manifest, media);
    Result<ChannelMedia> images = ChannelMedia::load(manifest, resolver, media);
    if (!images) return images.error();
    PassGraph graph = buildPassGraph(manifest);
    std::vector<Diagnostic> notices = manifest.notices;
    notices.insert(notices.end(), images->notices().begin(), images->notices().end());
    for (Diagnostic& warning : unboundChannelWarnings(manifest)) notices.push_back(std::move(warning));
    for (Diagnostic& warning : depthWarnings) notices.push_back(std::move(warning));
    for (Diagnostic& warning : texelCornerWarnings(manifest)) notices.push_back(std::move(warning));
    for (Diagnostic& warning : loopCapWarnings(manifest)) notices.push_back(std::move(warning));
    std::vector<PassSource> sources;
    sources.reserve(preparing.size());
    for (std::future<PassSource>& source : preparing) sources.push_back(source.get());
    std::optional<PassSource> soundSource;
    if (preparingSound) soundSource = preparingSound->get();
    return PlayerPlan{std::move(manifest), std::move(graph), std::move(*images), std::move(notices), std::move(sources),
                      std::move(soundSource), std::move(defines)};
}

}  // namespace toyhost
