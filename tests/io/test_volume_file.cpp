// VolumeFile: reading Shadertoy's volume `.bin` files (20-byte header, then x-fastest voxels)
// and the deterministic noise stand-ins for the stock volumes.
#include <gtest/gtest.h>

#include <cstring>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "TestFolder.h"
#include "media/VolumeFile.h"

using namespace toyhost;
using toyhost::testing::TestFolder;

namespace {
// A header written byte by byte (independently of encodeVolumeFile), then `data`.
std::string volumeBytes(std::uint32_t x, std::uint32_t y, std::uint32_t z, unsigned channels,
                        const std::string& data, std::uint16_t format = 0, std::uint32_t signature = 0x004e4942) {
    std::string out;
    for (std::uint32_t v : {signature, x, y, z})
        for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<char>((v >> shift) & 0xFF));
    out.push_back(static_cast<char>(channels));
    out.push_back(0);  // layout
    out.push_back(static_cast<char>(format & 0xFF));
    out.push_back(static_cast<char>(format >> 8));
    return out + data;
}

std::string voxelsOf(std::size_t count) {
    std::string data;
    for (std::size_t i = 0; i < count; ++i) data.push_back(static_cast<char>((i * 7 + 3) & 0xFF));
    return data;
}

void expectRejected(const TestFolder& folder, const std::string& bytes, const std::string& fragment) {
    const auto path = folder.write("bad.bin", bytes);
    Result<Volume8> volume = readVolumeFile(path);
    ASSERT_FALSE(volume.ok()) << "accepted: " << fragment;
    EXPECT_EQ(volume.error().first().code, Code::VolumeDecode);
    EXPECT_EQ(volume.error().first().file, path.string());
    EXPECT_NE(volume.error().text().find(fragment), std::string::npos) << volume.error().text();
}
}  // namespace

TEST(VolumeFile, ReadsTheVoxelsXFastestThenYThenZ) {
    TestFolder folder;
    // 3x2x4, two channels: channel 0 = x + 4y + 16z, channel 1 = 200 + x.
    std::string data;
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) {
                data.push_back(static_cast<char>(x + 4 * y + 16 * z));
                data.push_back(static_cast<char>(200 + x));
            }
    const auto path = folder.write("v.bin", volumeBytes(3, 2, 4, 2, data));
    Result<Volume8> volume = readVolumeFile(path);
    ASSERT_TRUE(volume.ok()) << volume.error().text();
    EXPECT_EQ(volume->width, 3);
    EXPECT_EQ(volume->height, 2);
    EXPECT_EQ(volume->depth, 4);
    EXPECT_EQ(volume->channels, 2);
    ASSERT_EQ(volume->voxels.size(), 3u * 2 * 4 * 2);
    auto at = [&](int x, int y, int z, int c) {
        return volume->voxels[static_cast<std::size_t>(((z * 2 + y) * 3 + x) * 2 + c)];
    };
    EXPECT_EQ(at(0, 0, 0, 0), 0);
    EXPECT_EQ(at(2, 0, 0, 0), 2);
    EXPECT_EQ(at(1, 1, 0, 0), 5);
    EXPECT_EQ(at(2, 1, 3, 0), 2 + 4 + 48);
    EXPECT_EQ(at(2, 1, 3, 1), 202);
}

TEST(VolumeFile, EncodeThenReadGivesTheSameVolume) {
    TestFolder folder;
    const Volume8 original = volumeStandIn(8, 4, 7);
    const std::vector<std::uint8_t> bytes = encodeVolumeFile(original);
    ASSERT_EQ(bytes.size(), kVolumeHeaderBytes + 8u * 8 * 8 * 4);
    const auto path = folder.write("rgba.bin", std::string(bytes.begin(), bytes.end()));
    Result<Volume8> read = readVolumeFile(path);
    ASSERT_TRUE(read.ok()) << read.error().text();
    EXPECT_EQ(read->width, 8);
    EXPECT_EQ(read->height, 8);
    EXPECT_EQ(read->depth, 8);
    EXPECT_EQ(read->channels, 4);
    EXPECT_EQ(read->voxels, original.voxels);
}

TEST(VolumeFile, AnySignatureIsAcceptedAsTheSiteNeverChecksIt) {
    TestFolder folder;
    for (std::uint32_t signature : {0u, 0x004e4942u, 0xFFFFFFFFu}) {
        const auto path = folder.write("s.bin", volumeBytes(2, 2, 2, 1, voxelsOf(8), 0, signature));
        EXPECT_TRUE(readVolumeFile(path).ok()) << signature;
    }
}

TEST(VolumeFile, AFileShorterThanTheHeaderIsRejected) {
    TestFolder folder;
    expectRejected(folder, "", "shorter than the 20-byte header");
    expectRejected(folder, volumeBytes(2, 2, 2, 1, "").substr(0, 19), "19 bytes, shorter than the 20-byte header");
}

TEST(VolumeFile, TruncatedVoxelDataIsRejected) {
    TestFolder folder;
    expectRejected(folder, volumeBytes(4, 4, 4, 1, voxelsOf(63)), "but the file has 63 (truncated)");
    expectRejected(folder, volumeBytes(4, 4, 4, 4, ""), "256 bytes of voxels, but the file has 0");
}

TEST(VolumeFile, TrailingDataIsRejected) {
    TestFolder folder;
    expectRejected(folder, volumeBytes(4, 4, 4, 1, voxelsOf(65)), "but the file has 65 (trailing data)");
}

TEST(VolumeFile, ZeroAndAbsurdSizesAreRejected) {
    TestFolder folder;
    expectRejected(folder, volumeBytes(0, 4, 4, 1, ""), "0x4x4 (a side is 0)");
    expectRejected(folder, volumeBytes(4, 4, 0, 1, ""), "a side is 0");
    expectRejected(folder, volumeBytes(1025, 1, 1, 1, voxelsOf(1025)), "larger than the 1024 a side");
    expectRejected(folder, volumeBytes(4, 0xFFFFFFFFu, 4, 1, ""), "larger than the 1024 a side");
    // Every side within the limit but 1024^3 x 4 bytes is 4 GiB.
    expectRejected(folder, volumeBytes(1024, 1024, 1024, 4, ""), "more than the limit");
}

TEST(VolumeFile, ChannelCountsOutside1To4AreRejected) {
    TestFolder folder;
    expectRejected(folder, volumeBytes(2, 2, 2, 0, ""), "0 channels (1 to 4 are valid)");
    expectRejected(folder, volumeBytes(2, 2, 2, 5, voxelsOf(40)), "5 channels");
}

TEST(VolumeFile, FloatVolumesAreReadAndUnknownFormatsRejected) {
    TestFolder folder;
    // Format 10: 32-bit floats, 4 bytes a value (the site reads them as C1F32..C4F32).
    std::string floats;
    for (int i = 0; i < 8; ++i) {
        const float value = 0.25f * static_cast<float>(i) - 0.5f;
        floats.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    const auto path = folder.write("f.bin", volumeBytes(2, 2, 2, 1, floats, 10));
    Result<Volume8> volume = readVolumeFile(path);
    ASSERT_TRUE(volume.ok()) << volume.error().text();
    EXPECT_TRUE(volume->floats);
    ASSERT_EQ(volume->voxels.size(), 32u);
    float third = 0;
    std::memcpy(&third, volume->voxels.data() + 3 * sizeof(float), sizeof third);
    EXPECT_EQ(third, 0.25f);
    const std::string same = volumeBytes(2, 2, 2, 1, floats, 10, 0);  // encodeVolumeFile writes signature 0
    EXPECT_EQ(encodeVolumeFile(*volume), std::vector<std::uint8_t>(same.begin(), same.end()));
    // 8 values of 4 bytes: 8 bytes are short.
    expectRejected(folder, volumeBytes(2, 2, 2, 1, voxelsOf(8), 10), "32 bytes of voxels, but the file has 8 (truncated)");
    expectRejected(folder, volumeBytes(2, 2, 2, 1, voxelsOf(8), 3), "unknown voxel format 3");
}

TEST(VolumeFile, AMissingFileOrAFolderGetsTheIoError) {
    TestFolder folder;
    Result<Volume8> missing = readVolumeFile(folder.path / "nope.bin");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().text().find("nope.bin"), std::string::npos);
    EXPECT_FALSE(readVolumeFile(folder.path).ok());
}

TEST(VolumeStandIn, IsDeterministicPerSeedAndShapedLikeTheStockVolumes) {
    const Volume8 grey = volumeStandIn(32, 1, 1);
    EXPECT_EQ(grey.width, 32);
    EXPECT_EQ(grey.height, 32);
    EXPECT_EQ(grey.depth, 32);
    EXPECT_EQ(grey.channels, 1);
    EXPECT_EQ(grey.voxels.size(), 32u * 32 * 32);
    EXPECT_EQ(volumeStandIn(32, 1, 1).voxels, grey.voxels);
    EXPECT_NE(volumeStandIn(32, 1, 2).voxels, grey.voxels);

    const Volume8 rgba = volumeStandIn(32, 4, 1);
    EXPECT_EQ(rgba.channels, 4);
    EXPECT_EQ(rgba.voxels.size(), 32u * 32 * 32 * 4);

    const Volume8 clamped = volumeStandIn(0, 9, 1);
    EXPECT_EQ(clamped.width, 1);
    EXPECT_EQ(clamped.channels, 4);
}

TEST(VolumeStandIn, BytesAreUniform) {
    const Volume8 rgba = volumeStandIn(32, 4, 12345);
    std::array<int, 256> histogram{};
    double sum = 0;
    for (std::uint8_t b : rgba.voxels) {
        ++histogram[b];
        sum += b;
    }
    const double count = static_cast<double>(rgba.voxels.size());
    // Mean of uniform bytes is 127.5 with a standard error of 73.9/sqrt(131072) = 0.2.
    EXPECT_NEAR(sum / count, 127.5, 1.5);
    // Every value appears about 512 times; none is missing or doubled.
    for (int v = 0; v < 256; ++v) {
        EXPECT_GT(histogram[static_cast<std::size_t>(v)], 400) << v;
        EXPECT_LT(histogram[static_cast<std::size_t>(v)], 640) << v;
    }
    // Channels are independent: R of one voxel does not predict its G.
    double r = 0, g = 0, rg = 0, rr = 0, gg = 0;
    const std::size_t voxels = rgba.voxels.size() / 4;
    for (std::size_t i = 0; i < voxels; ++i) {
        const double a = rgba.voxels[4 * i], b = rgba.voxels[4 * i + 1];
        r += a, g += b, rg += a * b, rr += a * a, gg += b * b;
    }
    const double n = static_cast<double>(voxels);
    const double correlation = (rg / n - r / n * g / n) /
                               std::sqrt((rr / n - r / n * r / n) * (gg / n - g / n * g / n));
    EXPECT_LT(std::abs(correlation), 0.03);
}
