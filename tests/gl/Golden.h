// Golden frames: a rendered PNG against a checked-in one under tests/golden/, with the tolerance
// every golden test uses: PSNR >= 40 dB over RGB and mean absolute error <= 1 level (llvmpipe is
// deterministic on one machine; the margin absorbs LLVM code generation differences between CPUs,
// such as fused multiply-adds, which move a few edge pixels). On failure the actual frame, the
// expected one and an 8x diff are left beside the actual frame. TOYHOST_UPDATE_GOLDENS=1 refreshes
// the golden on purpose (and skips the test). CPU only.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "ImageCompare.h"
#include "image/ImageFile.h"
#include "image/ImageWriters.h"

namespace toyhost::testing {

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

    const double psnr = psnrRgb(*expected, *actual);
    const double mae = meanAbsError(*expected, *actual);
    std::printf("%s: PSNR %.2f dB, mean abs error %.4f, max %d\n", stem.c_str(), psnr, mae,
                maxAbsError(*expected, *actual));
    if (psnr < 40.0 || mae > 1.0) {
        Image8 diff = makeDiffImage(*expected, *actual, 8);
        (void)writePng(dir / (stem + ".diff.png"), diff.width, diff.height, diff.rgba);
        fs::copy_file(goldenPath, dir / (stem + ".expected.png"), fs::copy_options::overwrite_existing);
        ADD_FAILURE() << stem << ": PSNR " << psnr << " dB (need >= 40), mean abs error " << mae
                      << " (need <= 1); actual, expected and diff are in " << dir;
    }
}

}  // namespace toyhost::testing
