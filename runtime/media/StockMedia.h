// StockMedia: the table of Shadertoy's stock 2D textures (/media/a/<sha256>.<ext>) with their true
// size and channel count, and deterministic stand-ins for when the real file is not available.
// Pure data and CPU pixel generation, no GL needed.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "media/Image.h"

namespace toyhost {

enum class StockMediaKind {
    Noise,  // uniform random bytes (Gray/RGBA Noise): shaders use them as hash tables
    Photo,  // photographic or painted surface detail (Abstract, Organic, London, ...)
    Other,  // anything else: font atlas, Bayer matrix, Nyancat sprite sheet, blue noise
};

struct StockMediaInfo {
    std::string_view hash;       // sha256 as used in the path, lower-case hex
    std::string_view extension;  // "png" or "jpg", without the dot
    std::string_view name;       // the site's display name, e.g. "Abstract 3"
    int width;
    int height;
    int channels;  // channels in the real file: 1 grey, 3 RGB, 4 RGBA
    StockMediaKind kind;
};

// Every stock texture the host knows, in alphabetical order of name.
std::span<const StockMediaInfo> stockMediaTable();

// Looks a texture up by "/media/a/<hash>.<ext>", "<hash>.<ext>", "<hash>" or the site name (case
// does not matter: "Abstract 3", "abstract 3"). Returns nullptr when it is not a stock texture.
const StockMediaInfo* findStockMedia(std::string_view ref);

// The canonical reference "/media/a/<hash>.<ext>".
std::string stockMediaPath(const StockMediaInfo& info);

// A stand-in of the real texture's exact size: the same bytes on every run and machine (integer
// arithmetic only, seeded from the hash). Noise textures are uniform random bytes (grey noise: one
// byte per pixel in R=G=B, A=255; RGBA noise: four independent bytes); photos are tileable
// multi-octave value noise through a colour ramp, so they have detail at every mip level; the
// others get a pattern of the same nature (Bayer matrix, glyph grid, sprite frames, blue noise).
// Alpha is 255 wherever the real file has no alpha channel.
Image8 makeStandIn(const StockMediaInfo& info);

}  // namespace toyhost
