#include "media/MediaResolver.h"

#include <algorithm>
#include <cctype>
#include <optional>

#include "image/ImageFile.h"
#include "manifest/StockMedia.h"
#include "media/StandIns.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {
std::string overrideKey(std::string_view ref) {
    if (const StockMediaInfo* info = findStockMedia(ref)) return std::string(info->hash);
    if (const StockInputInfo* input = findStockInput(ref)) return std::string(input->hash);
    return std::string(ref);
}

bool hasImageExtension(const fs::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg";
}

// A stock texture by "<hash>.<ext>" first, then any image file whose name findStockMedia maps to
// the same texture (hash with another extension, "Abstract 3.jpg", "abstract_3.png"). Candidates
// are taken in file-name order so the choice does not depend on the directory's listing order.
std::optional<fs::path> findStockFile(const fs::path& folder, const StockMediaInfo& info) {
    std::error_code ec;
    const fs::path exact = folder / (std::string(info.hash) + "." + std::string(info.extension));
    if (fs::is_regular_file(exact, ec)) return exact;

    std::vector<fs::path> matches;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path& file = it->path();
        if (it->is_regular_file(ec) && hasImageExtension(file) &&
            findStockMedia(file.filename().string()) == &info)
            matches.push_back(file);
    }
    if (matches.empty()) return std::nullopt;
    return *std::min_element(matches.begin(), matches.end());
}

// Any other id ("/media/user/foo.png", "foo.png") by its file name.
std::optional<fs::path> findPlainFile(const fs::path& folder, std::string_view ref) {
    const fs::path name = fs::path(std::string(ref)).filename();
    if (name.empty()) return std::nullopt;
    std::error_code ec;
    const fs::path candidate = folder / name;
    if (fs::is_regular_file(candidate, ec)) return candidate;
    return std::nullopt;
}

Result<ResolvedMedia> loadReal(const fs::path& file) {
    Result<Image8> image = loadImageFile(file);
    if (!image) return image.error();
    return ResolvedMedia{std::move(image).value(), false, {}, file};
}
}  // namespace

std::string mediaFileOption(std::string_view name, std::string_view value) {
    const std::string argument = std::string(name) + "=" + std::string(value);
    const bool plain = std::all_of(name.begin(), name.end(), [](unsigned char c) {
        return std::isalnum(c) || c == '/' || c == '.' || c == '_' || c == '-';
    });
    return "--media-file " + (plain ? argument : "\"" + argument + "\"");
}

void MediaResolver::setOverride(std::string ref, fs::path file) {
    overrides_[overrideKey(ref)] = std::move(file);
}

void MediaResolver::addSearchFolder(fs::path folder) {
    searchFolders_.push_back(std::move(folder));
}

std::optional<fs::path> MediaResolver::findFile(std::string_view ref) const {
    if (const auto it = overrides_.find(overrideKey(ref)); it != overrides_.end()) return it->second;
    const StockMediaInfo* info = findStockMedia(ref);
    // A stock cubemap, volume, video or music named by its site name is looked for by its file name.
    const StockInputInfo* input = info ? nullptr : findStockInput(ref);
    const std::string inputPath = input ? stockInputPath(*input) : std::string();
    for (const fs::path& folder : searchFolders_)
        if (std::optional<fs::path> file = info ? findStockFile(folder, *info)
                                                : findPlainFile(folder, input ? std::string_view(inputPath) : ref))
            return file;
    return std::nullopt;
}

Result<ResolvedMedia> MediaResolver::resolve(std::string_view ref) const {
    const StockMediaInfo* info = findStockMedia(ref);

    if (const auto it = overrides_.find(overrideKey(ref)); it != overrides_.end()) {
        Result<ResolvedMedia> loaded = loadReal(it->second);
        if (!loaded) {
            Error error = loaded.error();
            for (Diagnostic& d : error.diagnostics) d.message = "media override for '" + std::string(ref) + "': " + d.message;
            return error;
        }
        return loaded;
    }

    for (const fs::path& folder : searchFolders_) {
        const std::optional<fs::path> file =
            info ? findStockFile(folder, *info) : findPlainFile(folder, ref);
        if (file) return loadReal(*file);
    }

    if (!info && ref.rfind("/media/a/", 0) == 0) {
        // A stock texture the table does not know: its size is unknown, so the stand-in is a
        // 512x512 RGB photo-like image (the most common stock size), flagged in the notice.
        const std::string hash(ref.substr(9, ref.find('.', 9) == std::string_view::npos ? std::string_view::npos
                                                                                         : ref.find('.', 9) - 9));
        const StockMediaInfo unknown{hash, "", "unknown stock texture", 512, 512, 3, StockMediaKind::Photo};
        ResolvedMedia standIn{makeStandIn(unknown), true, {}, {}};
        // A warning, not a notice: the size is a guess, and shaders that use the size (hash
        // tables, atlases) will differ from the site until the real file is supplied.
        standIn.notice.severity = Severity::Warning;
        standIn.notice.code = Code::MediaUnknownStandIn;
        standIn.notice.message = "stock texture " + std::string(ref) +
                                 " is not in toyhost's table; using a stand-in whose size, 512x512 RGB, is a guess. "
                                 "Supply the real file with " + mediaFileOption(hash) + " or --media DIR "
                                 "(`toyhost media` lists the known ids).";
        return standIn;
    }
    if (!info) {
        return Error("media '" + std::string(ref) +
                         "' is not a Shadertoy stock texture and was found in no override or media folder",
                     Code::MediaNotFound);
    }

    const std::string path = stockMediaPath(*info);
    ResolvedMedia standIn{makeStandIn(*info), true, {}, {}};
    standIn.notice.severity = Severity::Notice;
    standIn.notice.code = Code::MediaStandIn;
    standIn.notice.message = "stock texture '" + std::string(info->name) + "' (" + path + ", " +
                             std::to_string(info->width) + "x" + std::to_string(info->height) +
                             ") is not available; using a deterministic stand-in. Supply the real file with " +
                             mediaFileOption(info->name) + " or --media DIR.";
    return standIn;
}

}  // namespace toyhost
