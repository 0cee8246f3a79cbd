// ChannelKinds: every kind of input a channel can bind, in one table: its name, how a manifest and
// a Shadertoy export write it, the GLSL sampler it is declared as, its default sampler settings,
// whether vflip applies, whether it changes with time, whether the Sound pass can read it, and
// where its texture comes from (ChannelSource), which is all the loader (media/ChannelMedia.h) and
// the binding code (render/ChannelBindings.h) look at. Adding a kind is a row here, plus its loader
// when no existing ChannelSource fits. Pure data, no GL needed.
#pragma once

#include <span>
#include <string_view>

namespace toyhost {

// What a channel binds. ImageFile/StockMedia are 2D pictures; Cubemap, Volume, Video and Music
// come from a stock id (`media`) or the user's own file (`file`, when set); Webcam and Mic from a
// device given on the command line, else a stand-in; CubeBuffer is the Cube A pass's output.
enum class ChannelKind {
    None, Buffer, ImageFile, StockMedia, Keyboard, CubeBuffer, Cubemap, Volume, Video, Music, Webcam, Mic
};
// The GLSL sampler type of an iChannel uniform.
enum class SamplerType { Sampler2D, SamplerCube, Sampler3D };
enum class Filter { Nearest, Linear, Mipmap };
enum class Wrap { Clamp, Repeat };

struct SamplerDesc {
    Filter filter = Filter::Linear;
    Wrap wrap = Wrap::Clamp;
    bool vflip = false;  // only meaningful for kinds that take it (ChannelKindInfo::vflip)
};

// Where a channel's texture comes from: how it is loaded before GL and how it binds.
enum class ChannelSource {
    Unbound,     // nothing (iChannelResolution 0)
    Buffer,      // a buffer's ping-pong texture; the pass graph picks the slot each frame
    CubeBuffer,  // Cube A's cubemap, the same way
    Keyboard,    // the 256x3 key-state texture
    Picture,     // a 2D image decoded before GL (RGBA8, CPU mip chain)
    Cubemap,     // six faces decoded before GL
    Volume,      // voxels read before GL (a 3D texture)
    Video,       // frames of a video file or camera (media/VideoStream.h), or the moving stand-in
    Audio,       // the site's 512x2 analyser texture of an audio file, a live source, or the stand-in
};

// How a manifest's channel object names the input: {"buffer": "A"}, {"texture": "file.png"},
// {"media": "Abstract 3"}, {"webcam": true}.
enum class ManifestValue { None, BufferName, File, StockId, True };

struct ChannelKindInfo {
    ChannelKind kind;
    const char* name;          // in messages: "buffer", "texture file", "cubemap", ...
    const char* manifestKey;   // the manifest's key (several kinds may share one: "buffer"); "" for None
    ManifestValue value;
    const char* mediaKind;     // with {"media": ID, "kind": K}: this K (stock inputs); "" when none
    const char* exportTypes;   // the site's ctype values that mean this kind, space separated
    SamplerType samplerType;
    SamplerDesc sampler;       // the site's defaults when such an input is added
    bool fixedSampler;         // its filter and wrap cannot be set (the keyboard: nearest/clamp)
    bool vflip;                // `vflip` applies (uploaded flipped or not)
    bool timed;                // changes with time; iChannelTime is its playback time
    bool soundReads;           // the Sound pass (rendered before any frame) can read it
    ChannelSource source;
};

// Every kind, in ChannelKind order.
std::span<const ChannelKindInfo> channelKinds();
const ChannelKindInfo& channelKindInfo(ChannelKind kind);
// The kind a site export's ctype means ("musicstream" -> Music); nullptr when none.
const ChannelKindInfo* channelKindOfExportType(std::string_view type);
// The kind {"media": ID, "kind": K} means ("texture" -> StockMedia); nullptr when none.
const ChannelKindInfo* channelKindOfMediaKind(std::string_view mediaKind);

// Shorthands for the table's columns.
inline const char* channelKindName(ChannelKind kind) { return channelKindInfo(kind).name; }
inline SamplerType samplerTypeOf(ChannelKind kind) { return channelKindInfo(kind).samplerType; }
inline SamplerDesc defaultSampler(ChannelKind kind) { return channelKindInfo(kind).sampler; }
inline bool takesVflip(ChannelKind kind) { return channelKindInfo(kind).vflip; }
inline bool isTimedMedia(ChannelKind kind) { return channelKindInfo(kind).timed; }
inline ChannelSource channelSource(ChannelKind kind) { return channelKindInfo(kind).source; }
// A source loaded from media before GL (pictures, cubemaps, volumes, videos, audio).
inline bool isMediaSource(ChannelSource source) {
    return source == ChannelSource::Picture || source == ChannelSource::Cubemap || source == ChannelSource::Volume ||
           source == ChannelSource::Video || source == ChannelSource::Audio;
}

}  // namespace toyhost
