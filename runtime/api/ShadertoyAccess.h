// api/ShadertoyAccess.h: the runtime's way into a public Shadertoy (its ManifestDesc, and making
// one from a loaded description), kept out of include/toyhost so embedders never see it. No GL needed.
#pragma once

#include <memory>
#include <utility>

#include <toyhost/Shadertoy.h>

#include "manifest/ManifestDesc.h"

namespace toyhost {

// A friend of Shadertoy; inline, so it adds no exported symbol to libtoyhost.so.
struct ShadertoyAccess {
    static const ManifestDesc& desc(const Shadertoy& shadertoy) { return *shadertoy.desc_; }
    static Shadertoy make(ManifestDesc desc) {
        return Shadertoy(std::make_shared<const ManifestDesc>(std::move(desc)));
    }
};

}  // namespace toyhost
