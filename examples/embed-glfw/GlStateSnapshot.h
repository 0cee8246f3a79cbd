// GlStateSnapshot: the GL state an application keeps between its own draws (bindings, viewport,
// blending, tests, masks, pixel store), captured as named numbers so that two snapshots can be
// compared. embed-glfw --check takes one before and one after every toyhost step. Needs a current
// OpenGL ES 3 context.
#pragma once

#include <GLES3/gl3.h>

#include <string>
#include <utility>
#include <vector>

struct GlStateSnapshot {
    std::vector<std::pair<std::string, long long>> values;

    static GlStateSnapshot capture() {
        GlStateSnapshot s;
        auto integers = [&](const char* name, GLenum e, int count) {
            GLint v[4] = {};
            glGetIntegerv(e, v);
            for (int i = 0; i < count; ++i) s.values.emplace_back(std::string(name) + "[" + std::to_string(i) + "]", v[i]);
        };
        auto enabled = [&](const char* name, GLenum e) { s.values.emplace_back(name, glIsEnabled(e)); };
        auto floats = [&](const char* name, GLenum e, int count) {
            GLfloat v[4] = {};
            glGetFloatv(e, v);
            for (int i = 0; i < count; ++i)
                s.values.emplace_back(std::string(name) + "[" + std::to_string(i) + "]", static_cast<long long>(v[i] * 1e6));
        };
        integers("DRAW_FRAMEBUFFER_BINDING", GL_DRAW_FRAMEBUFFER_BINDING, 1);
        integers("READ_FRAMEBUFFER_BINDING", GL_READ_FRAMEBUFFER_BINDING, 1);
        integers("RENDERBUFFER_BINDING", GL_RENDERBUFFER_BINDING, 1);
        integers("CURRENT_PROGRAM", GL_CURRENT_PROGRAM, 1);
        integers("VERTEX_ARRAY_BINDING", GL_VERTEX_ARRAY_BINDING, 1);
        integers("ARRAY_BUFFER_BINDING", GL_ARRAY_BUFFER_BINDING, 1);
        integers("ELEMENT_ARRAY_BUFFER_BINDING", GL_ELEMENT_ARRAY_BUFFER_BINDING, 1);
        integers("UNIFORM_BUFFER_BINDING", GL_UNIFORM_BUFFER_BINDING, 1);
        integers("PIXEL_PACK_BUFFER_BINDING", GL_PIXEL_PACK_BUFFER_BINDING, 1);
        integers("PIXEL_UNPACK_BUFFER_BINDING", GL_PIXEL_UNPACK_BUFFER_BINDING, 1);
        integers("VIEWPORT", GL_VIEWPORT, 4);
        integers("SCISSOR_BOX", GL_SCISSOR_BOX, 4);
        integers("ACTIVE_TEXTURE", GL_ACTIVE_TEXTURE, 1);
        GLint active = 0;
        glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
        for (int unit = 0; unit < 4; ++unit) {
            glActiveTexture(GL_TEXTURE0 + unit);
            const std::string u = "unit" + std::to_string(unit) + ".";
            integers((u + "TEXTURE_BINDING_2D").c_str(), GL_TEXTURE_BINDING_2D, 1);
            integers((u + "TEXTURE_BINDING_CUBE_MAP").c_str(), GL_TEXTURE_BINDING_CUBE_MAP, 1);
            integers((u + "TEXTURE_BINDING_3D").c_str(), GL_TEXTURE_BINDING_3D, 1);
            integers((u + "SAMPLER_BINDING").c_str(), GL_SAMPLER_BINDING, 1);
        }
        glActiveTexture(static_cast<GLenum>(active));
        enabled("BLEND", GL_BLEND);
        integers("BLEND_SRC_RGB", GL_BLEND_SRC_RGB, 1);
        integers("BLEND_DST_RGB", GL_BLEND_DST_RGB, 1);
        integers("BLEND_SRC_ALPHA", GL_BLEND_SRC_ALPHA, 1);
        integers("BLEND_DST_ALPHA", GL_BLEND_DST_ALPHA, 1);
        integers("BLEND_EQUATION_RGB", GL_BLEND_EQUATION_RGB, 1);
        floats("BLEND_COLOR", GL_BLEND_COLOR, 4);
        enabled("DEPTH_TEST", GL_DEPTH_TEST);
        enabled("SCISSOR_TEST", GL_SCISSOR_TEST);
        enabled("CULL_FACE", GL_CULL_FACE);
        enabled("STENCIL_TEST", GL_STENCIL_TEST);
        enabled("DITHER", GL_DITHER);
        enabled("POLYGON_OFFSET_FILL", GL_POLYGON_OFFSET_FILL);
        enabled("RASTERIZER_DISCARD", GL_RASTERIZER_DISCARD);
        integers("COLOR_WRITEMASK", GL_COLOR_WRITEMASK, 4);
        integers("DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, 1);
        integers("FRONT_FACE", GL_FRONT_FACE, 1);
        floats("COLOR_CLEAR_VALUE", GL_COLOR_CLEAR_VALUE, 4);
        integers("PACK_ALIGNMENT", GL_PACK_ALIGNMENT, 1);
        integers("UNPACK_ALIGNMENT", GL_UNPACK_ALIGNMENT, 1);
        integers("UNPACK_ROW_LENGTH", GL_UNPACK_ROW_LENGTH, 1);
        integers("PACK_ROW_LENGTH", GL_PACK_ROW_LENGTH, 1);
        return s;
    }

    // "NAME: before -> after" for every value that differs; empty when none does.
    std::string differencesTo(const GlStateSnapshot& after) const {
        std::string text;
        for (std::size_t i = 0; i < values.size() && i < after.values.size(); ++i)
            if (values[i].second != after.values[i].second)
                text += values[i].first + ": " + std::to_string(values[i].second) + " -> " +
                        std::to_string(after.values[i].second) + "\n";
        return text;
    }
};
