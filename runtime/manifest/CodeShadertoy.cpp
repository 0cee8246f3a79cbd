#include "manifest/CodeShadertoy.h"

namespace toyhost {

ManifestDesc imageOnlyShadertoy(std::string name, std::filesystem::path place, PassCode image,
                                std::optional<PassCode> common) {
    ManifestDesc desc;
    desc.name = std::move(name);
    desc.manifestPath = std::move(place);
    if (common) {
        desc.commonSource = std::move(common->source);
        desc.commonName = std::move(common->sourceName);
        desc.commonCode = std::move(common->code);
    }
    PassDesc pass;
    pass.id = PassId::Image;
    pass.source = std::move(image.source);
    pass.sourceName = std::move(image.sourceName);
    pass.code = std::move(image.code);
    desc.passes.push_back(std::move(pass));
    return desc;
}

}  // namespace toyhost
