// StockMedia: the table of Shadertoy's stock 2D textures (/media/a/<sha256>.<ext>) with their true
// size and channel count, which manifests and exports name by id or by the site's name. Pure data;
// the stand-ins for files toyhost does not have are made in media/StandIns.h. No GL needed.
#pragma once

#include <span>
#include <string>
#include <string_view>


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

// A stock texture that `ref` ("/media/a/<hash>.<ext>", "<hash>" or a name) is a near miss of:
// a hash within a few edited characters, or a name within closestMatch's distance. nullptr when
// `ref` is an exact stock reference or close to none (a genuine id the table does not know).
const StockMediaInfo* nearStockMedia(std::string_view ref);

// The canonical reference "/media/a/<hash>.<ext>".
std::string stockMediaPath(const StockMediaInfo& info);

// The site's stock inputs that are not 2D textures: cubemaps (six files: the id's and `_1`..`_5`),
// volumes (.bin), videos and music. Sizes are the real files' where known; a stand-in is made at
// that size (cubemaps, volumes) or at a fixed size (videos).
enum class StockInputForm { Cubemap, Volume, Video, Music };
struct StockInputInfo {
    std::string_view hash;
    std::string_view extension;
    std::string_view name;
    StockInputForm form;
    int size;      // volume side; 0 where it does not apply or is not known (cubemap faces)
    int channels;  // volumes: 1 or 4; cubemaps 3 or 4
};
std::span<const StockInputInfo> stockInputTable();
// By "/media/a/<hash>.<ext>", "<hash>.<ext>", "<hash>" or name; nullptr when not a stock input.
const StockInputInfo* findStockInput(std::string_view ref);
std::string stockInputPath(const StockInputInfo& info);
const char* stockInputFormName(StockInputForm form);  // "cubemap", "volume", "video", "music"



}  // namespace toyhost
