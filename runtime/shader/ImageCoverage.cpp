#include "shader/ImageCoverage.h"

#include "shader/GlslTokens.h"

namespace toyhost {

namespace {

bool mentionsDiscard(std::string_view code) {
    for (const GlslToken& t : tokenizeGlsl(code))
        if (t.kind == GlslToken::Kind::Identifier && t.text == "discard") return true;
    return false;
}

}  // namespace

bool imageMayKeepPixels(const ManifestDesc& manifest) {
    const PassDesc* image = manifest.find(PassId::Image);
    if (!image) return false;
    return mentionsDiscard(image->code) || (manifest.commonSource && mentionsDiscard(manifest.commonCode));
}

}  // namespace toyhost
