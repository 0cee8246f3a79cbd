// MediaResolver: turns a shader input's media id (a /media/a/... stock texture or a user file name)
// into pixels: a user override, a real file found in a search folder, or a stock stand-in.
// CPU only, no GL needed.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Result.h"
#include "image/Image.h"

namespace toyhost {

struct ResolvedMedia {
    Image8 image;          // RGBA8, rows bottom first
    bool standIn = false;  // true when the real file was not available
    // Set when standIn: a notice such as "stock texture 'Abstract 3' (/media/a/8979...jpg,
    // 1024x1024) is not available; using a deterministic stand-in. ..."
    Diagnostic notice;
    std::filesystem::path file;  // the real file decoded; empty for a stand-in
};

// How a user names a stock input on the command line: `--media-file "Abstract 3=<path>"` (the
// site's name, quoted when it holds a space; the name works as well as the hash).
std::string mediaFileOption(std::string_view name, std::string_view value = "<path>");

// Resolution order for an id: its override, then each search folder in the order added, then (for
// stock textures only) a stand-in of the real size. Nothing is cached: a caller that uses one id
// in several channels resolves it once and shares the result.
class MediaResolver {
public:
    // `ref` is any form findStockMedia or findStockInput accepts ("/media/a/<hash>.jpg", "<hash>",
    // "Abstract 3", "Forest"), normalised so that every form of the same stock texture, cubemap,
    // volume, video or music hits the override; any other string is matched as given.
    void setOverride(std::string ref, std::filesystem::path file);

    // A folder of real files, found by "<hash>.<ext>" or by site name ("Abstract 3.jpg",
    // "abstract_3.jpg"; case, '_' and '-' do not matter; .png/.jpg/.jpeg). Non-stock ids are
    // looked for by their file name.
    void addSearchFolder(std::filesystem::path folder);

    // Errors: an override or found file that cannot be decoded (named), or an id that is neither a
    // stock texture nor found anywhere.
    Result<ResolvedMedia> resolve(std::string_view ref) const;

    // The real file resolve() would decode for `ref` (its override, or the first match in the
    // search folders; a stock cubemap, volume, video or music by "<hash>.<ext>"), without decoding
    // it; nothing when a stand-in would be used.
    std::optional<std::filesystem::path> findFile(std::string_view ref) const;

private:
    std::map<std::string, std::filesystem::path> overrides_;
    std::vector<std::filesystem::path> searchFolders_;
};

}  // namespace toyhost
