// Golden frames: a rendered PNG against a checked-in one under tests/golden/, with the tolerance
// every golden test uses: PSNR >= 40 dB over RGB and mean absolute error <= 1 level (llvmpipe is
// deterministic on one machine; the margin absorbs LLVM code generation differences between CPUs,
// such as fused multiply-adds, which move a few edge pixels), and two checks those averages miss
// (issue 20): no 8x8 square off by more than kMaxBlockError levels on average (a local defect),
// and no cell of a 4x4 grid shifted by more than kMaxRegionBias levels in one channel (a changed
// constant: noise has no sign, a mutation does). On failure the actual frame, the expected one
// and an 8x diff are left beside the actual frame. TOYHOST_UPDATE_GOLDENS=1 refreshes the golden
// on purpose (and skips the test). CPU only.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "ImageCompare.h"
#include "image/ImageFile.h"
#include "image/ImageWriters.h"

namespace toyhost::testing {

constexpr double kMinPsnr = 40.0, kMaxMeanError = 1.0, kMaxBlockError = 6.0, kMaxRegionBias = 0.4;

struct GoldenVerdict {
    bool loaded = false;  // both images read and of the same size
    double psnr = 0, meanError = 0, blockError = 0, regionBias = 0;
    int maxError = 0;
    bool pass() const {
        return loaded && psnr >= kMinPsnr && meanError <= kMaxMeanError && blockError <= kMaxBlockError &&
               regionBias <= kMaxRegionBias;
    }
    std::string text() const {
        std::ostringstream out;
        out << "PSNR " << psnr << " dB (need >= " << kMinPsnr << "), mean abs error " << meanError << " (<= "
            << kMaxMeanError << "), worst 8x8 block " << blockError << " (<= " << kMaxBlockError
            << "), worst region bias " << regionBias << " (<= " << kMaxRegionBias << "), max " << maxError;
        return out.str();
    }
};

inline GoldenVerdict compareWithGolden(const Image8& expected, const Image8& actual) {
    GoldenVerdict v;
    v.loaded = sameSize(expected, actual);
    if (!v.loaded) return v;
    v.psnr = psnrRgb(expected, actual);
    v.meanError = meanAbsError(expected, actual);
    v.blockError = maxBlockMeanError(expected, actual);
    v.regionBias = maxRegionBias(expected, actual);
    v.maxError = maxAbsError(expected, actual);
    return v;
}

// `golden` is relative to tests/golden/ (e.g. "ocean_t4.png"); `actualPath` the frame to check.
inline void expectMatchesGolden(const std::filesystem::path& sourceRoot, const std::string& golden,
                                const std::filesystem::path& actualPath) {
    namespace fs = std::filesystem;
    const fs::path goldenPath = sourceRoot / "tests/golden" / golden;
    const std::string stem = fs::path(golden).stem().string();
    const fs::path dir = actualPath.parent_path();
    if (const char* update = std::getenv("TOYHOST_UPDATE_GOLDENS"); update && std::string(update) == "1") {
        fs::create_directories(goldenPath.parent_path());
        fs::copy_file(actualPath, goldenPath, fs::copy_options::overwrite_existing);
        GTEST_SKIP() << "golden refreshed: " << goldenPath;
    }
    auto expected = loadImageFile(goldenPath);
    ASSERT_TRUE(expected.ok()) << expected.error().text() << " (refresh with TOYHOST_UPDATE_GOLDENS=1)";
    auto actual = loadImageFile(actualPath);
    ASSERT_TRUE(actual.ok()) << actual.error().text();
    ASSERT_TRUE(sameSize(*expected, *actual)) << actualPath << " is " << actual->width << "x" << actual->height;

    const GoldenVerdict verdict = compareWithGolden(*expected, *actual);
    std::printf("%s: %s\n", stem.c_str(), verdict.text().c_str());
    if (!verdict.pass()) {
        Image8 diff = makeDiffImage(*expected, *actual, 8);
        (void)writePng(dir / (stem + ".diff.png"), diff.width, diff.height, diff.rgba);
        fs::copy_file(goldenPath, dir / (stem + ".expected.png"), fs::copy_options::overwrite_existing);
        ADD_FAILURE() << stem << ": " << verdict.text() << "; actual, expected and diff are in " << dir;
    }
}

}  // namespace toyhost::testing
