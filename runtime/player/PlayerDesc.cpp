#include "player/PlayerDesc.h"

#include <string>

#include "core/Defaults.h"
#include "shader/ChannelUse.h"
#include "shader/SourceText.h"

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

Result<PlayerPlan> planPlayer(ManifestDesc manifest, const MediaOptions& media) {
    // Bytes GL would drop or misread: every pass and Common, all reported together.
    std::vector<Diagnostic> textProblems;
    if (manifest.commonSource) checkShaderText(manifest.commonCode, manifest.commonName, "Common", textProblems);
    for (PassDesc& pass : manifest.passes) checkShaderText(pass.code, pass.sourceName, passName(pass.id), textProblems);
    if (!textProblems.empty()) return Error(std::move(textProblems));
    const MediaResolver resolver = makeMediaResolver(manifest, media);
    Result<ChannelMedia> images = ChannelMedia::load(manifest, resolver, media);
    if (!images) return images.error();
    PassGraph graph = buildPassGraph(manifest);
    std::vector<Diagnostic> notices = manifest.notices;
    notices.insert(notices.end(), images->notices().begin(), images->notices().end());
    for (Diagnostic& warning : unboundChannelWarnings(manifest)) notices.push_back(std::move(warning));
    std::vector<PassSource> sources;
    sources.reserve(manifest.passes.size());
    for (const PassDesc& pass : manifest.passes) sources.push_back(preparePassSource(manifest, pass));
    std::optional<PassSource> soundSource;
    if (manifest.sound) soundSource = preparePassSource(manifest, *manifest.sound);
    return PlayerPlan{std::move(manifest), std::move(graph), std::move(*images), std::move(notices), std::move(sources),
                      std::move(soundSource)};
}

}  // namespace toyhost
