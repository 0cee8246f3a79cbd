// FontAtlas: the stand-in for the site's font texture ("Font 1"), with the layout shaders rely on:
// a 16 x 16 grid of cells, character code c in column c % 16 and row c / 16 counted from the
// image's top (so with the site's default vflip, row 0 is at t = 1); red holds the glyph's
// coverage (what most text shaders read, `.x`), alpha its signed distance (0.5 at the outline,
// below inside, in cell units: (a - 127/255) * cell size is the distance in pixels), green and
// blue the distance's gradient (x right, y down the image), biased by 127/255. Glyphs are DejaVu
// Sans Mono (Debian's fonts-dejavu-core) rasterised with FreeType. No GL needed.
#pragma once

#include <filesystem>
#include <optional>

#include "core/Result.h"
#include "image/Image.h"

namespace toyhost {

// The font the atlas is drawn from, if installed (DejaVu Sans Mono, else DejaVu Sans).
std::optional<std::filesystem::path> atlasFontFile();

// A width x height atlas (both multiples of 16), rows top first; an error when FreeType cannot
// read `font`.
Result<Image8> fontAtlas(int width, int height, const std::filesystem::path& font);

}  // namespace toyhost
