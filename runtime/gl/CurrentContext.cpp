#include "gl/CurrentContext.h"

#include <EGL/egl.h>
#include <GLES3/gl3.h>

#include <cstring>
#include <string>

namespace toyhost {

namespace {
class AdoptedContext final : public GlContext {
public:
    Status makeCurrent() override { return okStatus(); }  // the caller keeps it current
    void* procAddress(const char* name) const override { return reinterpret_cast<void*>(eglGetProcAddress(name)); }
    std::string describe() const override {
        const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
        const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        return std::string("the caller's context; ") + (version ? version : "?") + "; " + (renderer ? renderer : "?");
    }
};
}  // namespace

Result<std::shared_ptr<GlContext>> adoptCurrentContext() {
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    if (!version) return Error("no GL context is current on this thread", Code::GlEgl);
    int major = 0;
    if (std::strncmp(version, "OpenGL ES ", 10) != 0 || std::sscanf(version + 10, "%d", &major) != 1 || major < 3)
        return Error(std::string("toyhost renders with OpenGL ES 3; the current context is ") + version, Code::GlFeature);
    if (Status features = checkRequiredGlFeatures(); !features) return features.error();
    return std::shared_ptr<GlContext>(std::make_shared<AdoptedContext>());
}

}  // namespace toyhost
