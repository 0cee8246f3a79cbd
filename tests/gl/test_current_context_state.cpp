// A session on the caller's context (Session::createOnCurrentContext) restores the caller's
// bindings, except bindings of toyhost's own objects that toyhost deleted meanwhile: those read 0,
// as GL's deletion leaves them, and the freed name is not made into a new object by the restore.
// (examples/embed-glfw --check covers the rest of the state in a real window.)
#include "GlTestSupport.h"

#include <GLES3/gl3.h>

#include <toyhost/Session.h>

namespace toyhost::testing {
namespace {

class CurrentContextState : public GlTest {};

TEST_F(CurrentContextState, TheImageTextureBoundWhenTheSessionGoesIsNotRecreated) {
    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "tests/gl/compare/base");
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    ASSERT_TRUE(context_->makeCurrent().ok());
    SessionSettings settings;
    settings.width = 8;
    settings.height = 4;
    Result<std::unique_ptr<Session>> session = Session::createOnCurrentContext(*probe, settings);
    ASSERT_TRUE(session.ok()) << session.error().text();
    ASSERT_TRUE((*session)->step().ok());
    // The caller draws toyhost's Image texture from unit 2, as embed-glfw does, and keeps it bound.
    const GLuint image = (*session)->imageTexture();
    ASSERT_NE(image, 0u);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, image);
    ASSERT_TRUE((*session)->step().ok());
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    EXPECT_EQ(static_cast<GLuint>(bound), image) << "a step keeps the caller's binding";

    session = Error("done", Code::Internal);  // the session and its textures go
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    EXPECT_EQ(bound, 0) << "the deleted texture is unbound, as glDeleteTextures leaves it";
    EXPECT_FALSE(glIsTexture(image)) << "restoring the binding made a new texture of the freed name";
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    EXPECT_EQ(active, GL_TEXTURE2);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace
}  // namespace toyhost::testing
