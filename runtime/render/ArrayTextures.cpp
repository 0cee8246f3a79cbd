#include "render/ArrayTextures.h"

#include <algorithm>
#include <string>

#include "gl/GlContext.h"

namespace toyhost {

namespace {

struct GlFormat {
    GLenum internal;
    GLenum format;
    GLenum type;
};

GlFormat glFormatOf(const PixelArray& pixels) {
    const GLenum format = pixels.components == 1 ? GL_RED : pixels.components == 3 ? GL_RGB : GL_RGBA;
    if (pixels.type == PixelType::UInt8)
        return {pixels.components == 1 ? GLenum(GL_R8) : pixels.components == 3 ? GLenum(GL_RGB8) : GLenum(GL_RGBA8),
                format, GL_UNSIGNED_BYTE};
    return {pixels.components == 1 ? GLenum(GL_R32F) : pixels.components == 3 ? GLenum(GL_RGB32F) : GLenum(GL_RGBA32F),
            format, GL_FLOAT};
}

int levelCount(int width, int height) {
    int levels = 1;
    for (int side = std::max(width, height); side > 1; side /= 2) ++levels;
    return levels;
}

}  // namespace

Result<const ArrayTextures::Entry*> ArrayTextures::upload(const Key& key, const PixelArray& pixels,
                                                            const SamplerDesc& sampler) {
    const bool mipmapped = sampler.filter == Filter::Mipmap;
    Entry& entry = entries_[key];
    const bool sameStorage = entry.texture && entry.width == pixels.width && entry.height == pixels.height &&
                             entry.components == pixels.components && entry.type == pixels.type &&
                             (entry.sampler.filter == Filter::Mipmap) == mipmapped;
    const GlFormat gl = glFormatOf(pixels);
    while (glGetError() != GL_NO_ERROR) {
    }
    if (!sameStorage) {
        // Immutable storage of the array's shape: a new shape is a new texture.
        entry.texture = makeTexture();
        glBindTexture(GL_TEXTURE_2D, entry.texture.id());
        const int levels = mipmapped ? levelCount(pixels.width, pixels.height) : 1;
        glTexStorage2D(GL_TEXTURE_2D, levels, gl.internal, pixels.width, pixels.height);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    } else {
        glBindTexture(GL_TEXTURE_2D, entry.texture.id());
    }
    entry.width = pixels.width;
    entry.height = pixels.height;
    entry.components = pixels.components;
    entry.type = pixels.type;
    entry.sampler = sampler;

    // Straight from the caller's memory: GL's row 0 is t = 0, so an array whose row 0 is its top
    // goes up a row at a time from the last texture row down (no flipped copy).
    // The rest of the unpack state is put back afterwards: a caller's context (GlStateGuard keeps
    // the buffer binding and alignment) may have its own.
    GLint rowLength = 0, skipRows = 0, skipPixels = 0;
    glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
    glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
    glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    const auto* bytes = static_cast<const unsigned char*>(pixels.data);
    if (!pixels.topRowFirst) {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, pixels.width, pixels.height, gl.format, gl.type, bytes);
    } else {
        const std::size_t row = rowBytes(pixels);
        for (int y = 0; y < pixels.height; ++y)
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, pixels.height - 1 - y, pixels.width, 1, gl.format, gl.type,
                            bytes + row * static_cast<std::size_t>(y));
    }
    if (mipmapped) glGenerateMipmap(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, skipRows);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, skipPixels);
    // On an error the texture stays bound where it was (its content undefined); the caller
    // reports it.
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error(std::string("GL: uploading the array ") + describePixelArray(pixels) + " failed: " +
                         glErrorName(error),
                     Code::GlSetup);
    return &entry;
}

}  // namespace toyhost
