// The gallery's golden cases (shadertoys/<name>/ at 320x180 through the CLI): what a case renders
// (time, scripted input, an optional edit of its source such as a #define variant or a mutation)
// and the helper that renders it to a PNG. Shared by test_gallery.cpp (goldens, variants) and
// test_gallery_mutations.cpp (each mutation must fail its golden). Needs the toyhost binary.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "GlTestSupport.h"
#include "core/AtomicFile.h"

namespace toyhost::testing {

// Replaces `find` (which must occur exactly once) by `replace` in the shadertoy's `file`.
struct SourceEdit {
    const char* file = nullptr;
    const char* find = nullptr;
    const char* replace = nullptr;
};

struct GalleryCase {
    const char* name;       // golden file tests/golden/gallery/<name>.png
    const char* shadertoy;  // folder under shadertoys/
    const char* options;    // time, inputs
    int frame = 0;          // the frame compared (the run renders frames 0..frame)
    std::vector<SourceEdit> edits = {};  // applied to a copy of the folder (variants)
    friend void PrintTo(const GalleryCase& c, std::ostream* os) { *os << c.name; }
};

inline std::string shellQuoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

// A copy of shadertoys/<shadertoy> in `dir` with `edits` applied; an empty path (and a test
// failure) when an edit's text is not found exactly once, so edits cannot silently go stale.
inline std::filesystem::path editedShadertoy(const std::string& shadertoy, const std::vector<SourceEdit>& edits,
                                             const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    const fs::path folder = sourceDir() / "shadertoys" / shadertoy;
    if (edits.empty()) return folder;
    const fs::path copy = dir / "source" / shadertoy;
    fs::remove_all(copy);
    fs::create_directories(copy.parent_path());
    fs::copy(folder, copy, fs::copy_options::recursive);
    for (const SourceEdit& edit : edits) {
        auto text = readTextFile(copy / edit.file);
        if (!text.ok()) {
            ADD_FAILURE() << text.error().text();
            return {};
        }
        const auto at = text->find(edit.find);
        if (at == std::string::npos || text->find(edit.find, at + 1) != std::string::npos) {
            ADD_FAILURE() << shadertoy << "/" << edit.file << ": the edit's text is not there exactly once: " << edit.find;
            return {};
        }
        text->replace(at, std::string(edit.find).size(), edit.replace);
        writeFile(copy / edit.file, *text);
    }
    return copy;
}

// Renders case `c` (with `extraEdits` after its own) into `dir`; the path of the compared frame,
// or nothing (and a test failure) when the run fails.
inline std::optional<std::filesystem::path> renderGalleryCase(const GalleryCase& c, const std::filesystem::path& dir,
                                                              const std::vector<SourceEdit>& extraEdits = {}) {
    std::vector<SourceEdit> edits = c.edits;
    edits.insert(edits.end(), extraEdits.begin(), extraEdits.end());
    const std::filesystem::path folder = editedShadertoy(c.shadertoy, edits, dir);
    if (folder.empty()) return std::nullopt;
    std::string options = c.options;
    // Input scripts are named relative to the shadertoy's folder.
    for (const char* flag : {"--mouse-script ", "--key-script "})
        if (const auto at = options.find(flag); at != std::string::npos)
            options.insert(at + std::string(flag).size(), folder.string() + "/");
    auto run = runToyhost("run " + shellQuoted(folder) + " --size 320x180 --quiet --frames " +
                          std::to_string(c.frame + 1) + " --capture-every " + std::to_string(std::max(c.frame, 1)) +
                          " " + options + " --out " + shellQuoted(dir / (std::string(c.name) + "_%04d.png")));
    if (run.exitCode != 0) {
        ADD_FAILURE() << run.output;
        return std::nullopt;
    }
    char file[96];
    std::snprintf(file, sizeof file, "%s_%04d.png", c.name, c.frame);
    return dir / file;
}

// Every golden case of the gallery: fixed times, every mouse path, every #define variant.
inline std::vector<GalleryCase> galleryCases() {
    return {
        {"raymarched_sea_t4", "raymarched-sea", "--start-time 4"},
        {"raymarched_sea_t20", "raymarched-sea", "--start-time 20"},
        {"raymarched_sea_mouse", "raymarched-sea", "--start-time 4 --mouse 240,60"},
        // looking down at the near water, where all 6 shading octaves are finer than a pixel's footprint
        {"raymarched_sea_down", "raymarched-sea", "--start-time 4 --mouse 160,5"},
        {"raymarched_sea_supersample", "raymarched-sea", "--start-time 4", 0,
         {{"image.glsl", "#define SUPERSAMPLE 2", "#define SUPERSAMPLE 1"}}},
        {"raymarched_sea_one_sample", "raymarched-sea", "--start-time 4", 0,
         {{"image.glsl", "#define SUPERSAMPLE 2", "#define SUPERSAMPLE 0"}}},
        {"exp_sine_ocean_t3", "exp-sine-ocean", "--start-time 3"},
        {"exp_sine_ocean_t10", "exp-sine-ocean", "--start-time 10"},
        {"exp_sine_ocean_mouse", "exp-sine-ocean", "--start-time 10 --mouse 112,72"},
        {"lake_optics_t2", "lake-optics", "--start-time 2"},
        {"lake_optics_t7_5", "lake-optics", "--start-time 7.5"},
        {"lake_optics_mouse", "lake-optics", "--start-time 2 --mouse 250,90"},
        {"lake_optics_muddy", "lake-optics", "--start-time 2 --key-script keys-muddy.json", 3},
        {"lake_optics_tannin", "lake-optics", "--start-time 2 --key-script keys-tannin.json", 3},
        {"caustics_pool_t2", "caustics-pool", "--start-time 2"},
        {"caustics_pool_t6_5", "caustics-pool", "--start-time 6.5"},
        {"caustics_pool_mouse", "caustics-pool", "--start-time 2 --mouse 240,90"},
        {"caustics_pool_flow_map", "caustics-pool", "--start-time 2", 0,
         {{"image.glsl", "// #define FLOW_MAP", "#define FLOW_MAP"}}},
        {"coastal_foam_t2", "coastal-foam", "--start-time 2"},
        {"coastal_foam_t5_5", "coastal-foam", "--start-time 5.5"},
        {"coastal_foam_mouse", "coastal-foam", "--start-time 2 --mouse 80,90"},
        {"coastal_foam_lake", "coastal-foam", "--start-time 2", 0, {{"image.glsl", "// #define LAKE", "#define LAKE"}}},
        // ripple-pool straight from above (--define TOP_VIEW: pixel p is cell p, so the mouse
        // script's points are the water's), then the default angled 3-D view with its sphere
        {"ripple_pool_calm", "ripple-pool", "--define TOP_VIEW"},
        {"ripple_pool_drag_f30", "ripple-pool", "--define TOP_VIEW --mouse-script drag.json", 30},
        {"ripple_pool_drag_f90", "ripple-pool", "--define TOP_VIEW --mouse-script drag.json", 90},
        {"ripple_pool_rain", "ripple-pool", "--define TOP_VIEW", 80,
         {{"common.glsl", "// #define RAIN", "#define RAIN"}}},
        {"ripple_pool_3d_calm", "ripple-pool", ""},
        {"ripple_pool_3d_drag_f90", "ripple-pool", "--mouse-script drag.json", 90},
    };
}

inline GalleryCase galleryCase(const std::string& name) {
    for (const GalleryCase& c : galleryCases())
        if (name == c.name) return c;
    ADD_FAILURE() << "no gallery case " << name;
    return {"", "", ""};
}

}  // namespace toyhost::testing
