// ArrayTextures: the 2D textures holding the pixel arrays a program shows in channels
// (Session::setChannel): one texture per (pass, channel), re-made only when the array's size,
// type, component count or mipmapping changes, otherwise overwritten in place. The texture's
// format follows the array: R8/RGB8/RGBA8 for uint8, R32F/RGB32F/RGBA32F for float32 (a one-
// component array samples as (r, 0, 0, 1), as the site's one-channel textures do). Needs a current
// GL context.
#pragma once

#include <map>
#include <utility>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "image/PixelArray.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

class ArrayTextures {
public:
    struct Entry {
        GlTexture texture;
        int width = 0;
        int height = 0;
        int components = 0;
        PixelType type = PixelType::UInt8;
        SamplerDesc sampler;
    };
    using Key = std::pair<PassId, int>;  // pass, channel

    // Uploads `pixels` (checked beforehand: checkPixelArray) as channel `key`'s texture; mip
    // levels are generated when `sampler` filters with mipmaps (uint8 arrays only: float
    // textures cannot have their mipmaps generated on every GLES 3 device). GL errors are returned.
    Result<const Entry*> upload(const Key& key, const PixelArray& pixels, const SamplerDesc& sampler);
    void erase(const Key& key) { entries_.erase(key); }
    const std::map<Key, Entry>& entries() const { return entries_; }

private:
    std::map<Key, Entry> entries_;
};

}  // namespace toyhost
