// RAII owners for GL objects (textures, framebuffers, samplers, programs, vertex arrays, buffers,
// fences).
// Constructing or destroying one needs the context that owns it to be current.
#pragma once

#include <GLES3/gl3.h>
#include <utility>

namespace toyhost {

template <void (*Delete)(GLuint)>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint id) : id_(id) {}
    ~GlObject() { reset(); }
    GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Delete(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

namespace gl_detail {
inline void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
inline void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void deleteSampler(GLuint id) { glDeleteSamplers(1, &id); }
inline void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void deleteProgram(GLuint id) { glDeleteProgram(id); }
inline void deleteShader(GLuint id) { glDeleteShader(id); }
}  // namespace gl_detail

using GlTexture = GlObject<gl_detail::deleteTexture>;
using GlFramebuffer = GlObject<gl_detail::deleteFramebuffer>;
using GlSampler = GlObject<gl_detail::deleteSampler>;
using GlVertexArray = GlObject<gl_detail::deleteVertexArray>;
using GlBuffer = GlObject<gl_detail::deleteBuffer>;
using GlProgram = GlObject<gl_detail::deleteProgram>;
using GlShader = GlObject<gl_detail::deleteShader>;

// A fence sync object (glFenceSync), deleted with its owner.
class GlFence {
public:
    GlFence() = default;
    explicit GlFence(GLsync sync) : sync_(sync) {}
    ~GlFence() { reset(); }
    GlFence(GlFence&& other) noexcept : sync_(std::exchange(other.sync_, nullptr)) {}
    GlFence& operator=(GlFence&& other) noexcept {
        if (this != &other) {
            reset();
            sync_ = std::exchange(other.sync_, nullptr);
        }
        return *this;
    }
    GlFence(const GlFence&) = delete;
    GlFence& operator=(const GlFence&) = delete;

    GLsync get() const { return sync_; }
    explicit operator bool() const { return sync_ != nullptr; }
    void reset() {
        if (sync_) glDeleteSync(sync_);
        sync_ = nullptr;
    }

private:
    GLsync sync_ = nullptr;
};

inline GlTexture makeTexture() { GLuint id = 0; glGenTextures(1, &id); return GlTexture(id); }
inline GlFramebuffer makeFramebuffer() { GLuint id = 0; glGenFramebuffers(1, &id); return GlFramebuffer(id); }
inline GlSampler makeSampler() { GLuint id = 0; glGenSamplers(1, &id); return GlSampler(id); }
inline GlVertexArray makeVertexArray() { GLuint id = 0; glGenVertexArrays(1, &id); return GlVertexArray(id); }
inline GlBuffer makeBuffer() { GLuint id = 0; glGenBuffers(1, &id); return GlBuffer(id); }

}  // namespace toyhost
