// Out of memory while reading inputs: a picture, cube faces or a volume whose buffers cannot be had
// is an Error naming the file and the size asked for, never std::bad_alloc (which aborted the CLI
// with exit 134). Each case runs in a forked child whose address space (RLIMIT_AS) is its current
// size plus less than the input needs.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <new>
#include <string>
#include <vector>

#include "TestFolder.h"
#include "UniformPng.h"
#include "image/ImageFile.h"
#include "media/CubemapFaces.h"
#include "media/VolumeFile.h"

using namespace toyhost;
namespace fs = std::filesystem;

namespace {
using TempFolder = toyhost::testing::TestFolder;

// This process's address space in bytes (VmSize), or 0.
std::uint64_t addressSpace() {
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("VmSize:", 0) == 0) return std::stoull(line.substr(7)) * 1024;
    return 0;
}

// Runs `body` in a child limited to its address space plus `headroom` bytes and returns what the
// body returned, "bad_alloc escaped" when it threw that, or why the child did not answer.
std::string inChildWithLittleMemory(std::uint64_t headroom, const std::function<std::string()>& body) {
    int fds[2];
    if (::pipe(fds) != 0) return "no pipe";
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        std::string answer;
        const std::uint64_t size = addressSpace();
        const rlimit limit{size + headroom, size + headroom};
        if (size == 0 || ::setrlimit(RLIMIT_AS, &limit) != 0) answer = "cannot lower RLIMIT_AS";
        else {
            try {
                answer = body();
            } catch (const std::bad_alloc&) {
                answer = "bad_alloc escaped";
            } catch (...) {
                answer = "an exception escaped";
            }
        }
        const ssize_t written = ::write(fds[1], answer.data(), answer.size());
        ::_exit(written == static_cast<ssize_t>(answer.size()) ? 0 : 1);
    }
    ::close(fds[1]);
    std::string answer;
    char chunk[4096];
    for (ssize_t n; (n = ::read(fds[0], chunk, sizeof chunk)) > 0;) answer.append(chunk, static_cast<std::size_t>(n));
    ::close(fds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return "the child died (status " + std::to_string(status) + "): " + answer;
    return answer;
}

// The first diagnostic's code name and the error's text, or "decoded".
template <class T>
std::string outcome(const Result<T>& result) {
    if (result) return "decoded";
    return std::string(codeName(result.error().first().code)) + ": " + result.error().text();
}

constexpr std::uint64_t kMiB = std::uint64_t(1) << 20;

}  // namespace

// A valid 8192x8192 PNG (256 MiB decoded) with 64 MiB to spare.
TEST(ImageMemory, APngTooLargeForTheMemoryLeftIsAnErrorNamingTheFileAndTheSize) {
    TempFolder folder;
    const fs::path file = folder.path / "large.png";
    ASSERT_TRUE(toyhost::testing::writeUniformPng(file, 8192, 8192, {40, 90, 200, 255}));
    const std::string answer = inChildWithLittleMemory(64 * kMiB, [&] { return outcome(loadImageFile(file)); });
    EXPECT_EQ(answer.rfind("image.too-large: ", 0), 0u) << answer;
    EXPECT_NE(answer.find(file.string()), std::string::npos) << answer;
    EXPECT_NE(answer.find("not enough memory: decoding the PNG needs 256.0 MiB for 8192x8192 RGBA"), std::string::npos)
        << answer;
}

// A valid 8192x8192 grey JPEG (every block coded in 2 bits: 256 KiB) with 64 MiB to spare.
TEST(ImageMemory, AJpegTooLargeForTheMemoryLeftIsAnErrorNamingTheFileAndTheSize) {
    TempFolder folder;
    const fs::path file = folder.path / "large.jpg";
    std::string bytes = std::string("\xFF\xD8\xFF\xDB\x00\x43\x00", 7) + std::string(64, '\x01');
    bytes += std::string("\xFF\xC0\x00\x0B\x08\x20\x00\x20\x00\x01\x01\x11\x00", 13);
    for (char table : {'\x00', '\x10'}) bytes += std::string("\xFF\xC4\x00\x14", 4) + table + '\x01' + std::string(16, '\0');
    bytes += std::string("\xFF\xDA\x00\x08\x01\x01\x00\x00\x3F\x00", 10) + std::string(1024 * 1024 * 2 / 8, '\0') + "\xFF\xD9";
    std::ofstream(file, std::ios::binary) << bytes;
    const std::string answer = inChildWithLittleMemory(64 * kMiB, [&] { return outcome(loadImageFile(file)); });
    EXPECT_EQ(answer.rfind("image.too-large: ", 0), 0u) << answer;
    EXPECT_NE(answer.find(file.string()), std::string::npos) << answer;
    EXPECT_NE(answer.find("not enough memory: decoding the JPEG needs 256.0 MiB for 8192x8192 RGBA"), std::string::npos)
        << answer;
}

// A horizontal strip of six 2048x2048 faces, cut into faces (96 MiB) with 32 MiB to spare.
TEST(ImageMemory, CubeFacesTooLargeForTheMemoryLeftAreAnErrorWithTheSize) {
    Image8 strip;
    strip.width = 6 * 2048;
    strip.height = 2048;
    strip.rgba.assign(std::size_t(strip.width) * strip.height * 4, 100);
    const std::string answer = inChildWithLittleMemory(32 * kMiB, [&] { return outcome(cubemapFromCross(strip)); });
    EXPECT_EQ(answer.rfind("image.too-large: ", 0), 0u) << answer;
    EXPECT_NE(answer.find("not enough memory: cutting the cubemap image into faces needs 96.0 MiB for 6 faces of "
                          "2048x2048 RGBA"),
              std::string::npos)
        << answer;
}

// A 512x512x256 one-channel volume file (64 MiB of voxels) with 8 MiB to spare. Large next to what
// the earlier tests of this process leave freed but mapped (a 256^3 volume, 16 MiB, fitted in that
// once in a full run and was decoded).
TEST(ImageMemory, AVolumeTooLargeForTheMemoryLeftIsAnErrorNamingTheFile) {
    TempFolder folder;
    const fs::path file = folder.path / "large.bin";
    Volume8 volume;
    volume.width = volume.height = 512;
    volume.depth = 256;
    volume.channels = 1;
    volume.voxels.assign(std::size_t(512) * 512 * 256, 7);
    const std::vector<std::uint8_t> bytes = encodeVolumeFile(volume);
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    volume.voxels = {};
    const std::string answer = inChildWithLittleMemory(8 * kMiB, [&] { return outcome(readVolumeFile(file)); });
    EXPECT_EQ(answer.rfind("image.too-large: ", 0), 0u) << answer;
    EXPECT_NE(answer.find(file.string()), std::string::npos) << answer;
    EXPECT_NE(answer.find("not enough memory"), std::string::npos) << answer;
}
