#include "shader/ShaderAssembly.h"

#include <algorithm>
#include <sstream>

namespace toyhost {

namespace {

const char* samplerKeyword(SamplerType type) {
    switch (type) {
        case SamplerType::SamplerCube: return "samplerCube";
        case SamplerType::Sampler3D: return "sampler3D";
        case SamplerType::Sampler2D: break;
    }
    return "sampler2D";
}

// The header shadertoy.com's player (WebGL2) prepends to a pass, in its order.
std::string makeHeader(const ShaderInputs& in) {
    const bool image = in.pass == PassId::Image;
    std::ostringstream h;
    h << "#version 300 es\n"
         "#line " << kHeaderLineBase + 2 << "\n"
         "precision highp float;\n"
         "precision highp int;\n"
         "precision mediump sampler3D;\n"
         // Desktop GPUs, where shadertoys are written and checked, compute lowp and mediump in
         // 32 bits; Mesa (llvmpipe included) lowers them to 16 bits, which breaks simulations
         // that read float buffers through the default lowp sampler2D. Promote them.
         "precision highp sampler2D; precision highp samplerCube; precision highp sampler3D;\n"
         "#define lowp highp\n"
         "#define mediump highp\n"
         "#define HW_PERFORMANCE 1\n"
         "uniform vec3      iResolution;\n"
         "uniform float     iTime;\n"
         "uniform float     iChannelTime[4];\n"
         "uniform vec4      iMouse;\n"
         "uniform vec4      iDate;\n"
         "uniform float     iSampleRate;\n"
         "uniform vec3      iChannelResolution[4];\n"
         "uniform int       iFrame;\n"
         "uniform float     iTimeDelta;\n"
         "uniform float     iFrameRate;\n";
    for (int i = 0; i < kChannelCount; ++i) {
        const char* sampler = samplerKeyword(in.samplers[i]);
        h << "uniform " << sampler << " iChannel" << i << ";\n";
        if (image)  // the newer per-channel struct API exists only in the Image pass
            h << "uniform struct {\n  " << sampler
              << " sampler;\n  vec3  size;\n  float time;\n  int   loaded;\n}iCh" << i << ";\n";
    }
    h << "void mainImage( out vec4 c, in vec2 f );\n";
    if (image) {
        h << "void st_assert( bool cond );\n"
             "void st_assert( bool cond, int v );\n"
             "\nout vec4 shadertoy_out_color;\n"
             "void st_assert( bool cond, int v ) {if(!cond){if(v==0)shadertoy_out_color.x=-1.0;"
             "else if(v==1)shadertoy_out_color.y=-1.0;else if(v==2)shadertoy_out_color.z=-1.0;"
             "else shadertoy_out_color.w=-1.0;}}\n"
             "void st_assert( bool cond        ) {if(!cond)shadertoy_out_color.x=-1.0;}\n"
             "void main( void ){"
             "shadertoy_out_color = vec4(1.0,1.0,1.0,1.0);"
             "vec4 color = vec4(0.0,0.0,0.0,1.0);"
             "mainImage( color, gl_FragCoord.xy );"
             "if(shadertoy_out_color.x<0.0) color=vec4(1.0,0.0,0.0,1.0);"
             "if(shadertoy_out_color.y<0.0) color=vec4(0.0,1.0,0.0,1.0);"
             "if(shadertoy_out_color.z<0.0) color=vec4(0.0,0.0,1.0,1.0);"
             "if(shadertoy_out_color.w<0.0) color=vec4(1.0,1.0,0.0,1.0);"
             "shadertoy_out_color = vec4(color.xyz,1.0);}\n";
    } else {
        // Buffers keep the alpha mainImage wrote.
        h << "\nout vec4 outColor;\n"
             "\nvoid main( void )\n"
             "{vec4 color = vec4(0.0,0.0,0.0,1.0);mainImage( color, gl_FragCoord.xy );"
             "outColor = color; }\n";
    }
    return h.str();
}

}  // namespace

AssembledShader assembleFragmentShader(const ShaderInputs& inputs) {
    AssembledShader out;
    out.text = makeHeader(inputs);
    if (inputs.common) {
        // Common is pasted followed by a newline.
        out.hasCommon = true;
        out.text += "#line " + std::to_string(kCommonLineBase + 1) + "\n";
        out.text += *inputs.common;
        out.text += '\n';
    }
    out.text += "#line 1\n";
    out.text += inputs.code;
    return out;
}

const char* fullscreenVertexShader() {
    return "#version 300 es\n"
           "void main() {\n"
           "    vec2 corner = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1));\n"
           "    gl_Position = vec4(corner - 1.0, 0.0, 1.0);\n"
           "}\n";
}

SourceLine mapGeneratedLine(int line) {
    if (line > kHeaderLineBase) return {SourceLine::Part::Header, line - kHeaderLineBase};
    if (line > kCommonLineBase) return {SourceLine::Part::Common, line - kCommonLineBase};
    return {SourceLine::Part::Pass, line};
}

}  // namespace toyhost
