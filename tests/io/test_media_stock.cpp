// StockMedia: the stock texture table, its lookup forms, and the deterministic stand-ins.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "manifest/StockMedia.h"
#include "media/StandIns.h"

using namespace toyhost;

namespace {
std::uint64_t fnv1a(const std::vector<std::uint8_t>& bytes) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (std::uint8_t b : bytes) h = (h ^ b) * 0x100000001b3ULL;
    return h;
}

const StockMediaInfo& stock(std::string_view name) {
    const StockMediaInfo* info = findStockMedia(name);
    if (!info) throw std::runtime_error("no stock texture " + std::string(name));
    return *info;
}

// The pixels with the top row first, as a file holds them.
std::vector<std::uint8_t> topFirst(const Image8& image) {
    std::vector<std::uint8_t> out;
    copyFlipped(std::span<const std::uint8_t>(image.rgba), image.width, image.height, out);
    return out;
}

// Channel c of every pixel.
std::vector<int> channel(const Image8& image, int c) {
    std::vector<int> values;
    for (std::size_t i = static_cast<std::size_t>(c); i < image.rgba.size(); i += 4)
        values.push_back(image.rgba[i]);
    return values;
}

double mean(const std::vector<int>& v) {
    double sum = 0;
    for (int x : v) sum += x;
    return sum / static_cast<double>(v.size());
}

double stddev(const std::vector<double>& v) {
    double m = 0, s = 0;
    for (double x : v) m += x;
    m /= static_cast<double>(v.size());
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size()));
}

// The entries of shared/corpus/stock_media.tsv (the corpus this host must run).
constexpr std::array<std::pair<const char*, const char*>, 15> kCorpusMedia{{
    {"/media/a/8de3a3924cb95bd0e95a443fff0326c869f9d4979cd1d5b6e94e2a01f5be53e9.jpg", "London"},
    {"/media/a/cb49c003b454385aa9975733aff4571c62182ccdda480aaba9a8d250014f00ec.png", "Blue Noise"},
    {"/media/a/0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5.png",
     "Gray Noise Medium"},
    {"/media/a/52d2a8f514c4fd2d9866587f4d7b2a5bfa1a11a0e772077d7682deb8b3b517e5.jpg", "Abstract 1"},
    {"/media/a/08b42b43ae9d3c0605da11d0eac86618ea888e62cdd9518ee8b9097488b31560.png", "Font 1"},
    {"/media/a/f735bee5b64ef98879dc618b016ecf7939a5756040c2cde21ccb15e69a6e1cfb.png",
     "RGBA Noise Medium"},
    {"/media/a/fb918796edc3d2221218db0811e240e72e340350008338b0c07a52bd353666a6.jpg", "Lichen"},
    {"/media/a/10eb4fe0ac8a7dc348a2cc282ca5df1759ab8bf680117e4047728100969e7b43.jpg", "Rock Tiles"},
    {"/media/a/3083c722c0c738cad0f468383167a0d246f91af2bfa373e9c5c094fb8c8413e0.png",
     "RGBA Noise Small"},
    {"/media/a/3871e838723dd6b166e490664eead8ec60aedd6b8d95bc8e2fe3f882f0fd90f0.jpg", "Organic 4"},
    {"/media/a/85a6d68622b36995ccb98a89bbb119edf167c914660e4450d313de049320005c.png", "Bayer"},
    {"/media/a/95b90082f799f48677b4f206d856ad572f1d178c676269eac6347631d4447258.jpg",
     "Rusty Metal"},
    {"/media/a/ad56fba948dfba9ae698198c109e71f118a54d209c0ea50d77ea546abad89c57.png", "Pebbles"},
    {"/media/a/cbcbb5a6cfb55c36f8f021fbb0e3f69ac96339a39fa85cd96f2017a2192821b5.png", "Nyancat"},
    {"/media/a/e6e5631ce1237ae4c05b3563eda686400a401df4548d0f9fad40ecac1659c46c.jpg", "Stars"},
}};
}  // namespace

TEST(MediaStockTable, HoldsEveryCorpusTextureUnderItsPathAndName) {
    for (const auto& [path, name] : kCorpusMedia) {
        const StockMediaInfo* info = findStockMedia(path);
        ASSERT_NE(info, nullptr) << path;
        EXPECT_EQ(info->name, name);
        EXPECT_EQ(stockMediaPath(*info), path);
    }
}

TEST(MediaStockTable, KnowsTheSizesAndChannelsTheHostDependsOn) {
    struct Expected {
        const char* name;
        int width, height, channels;
        StockMediaKind kind;
    };
    const Expected expected[] = {
        {"Gray Noise Small", 64, 64, 1, StockMediaKind::Noise},
        {"Gray Noise Medium", 256, 256, 1, StockMediaKind::Noise},
        {"RGBA Noise Small", 64, 64, 4, StockMediaKind::Noise},
        {"RGBA Noise Medium", 256, 256, 4, StockMediaKind::Noise},
        {"Abstract 3", 1024, 1024, 3, StockMediaKind::Photo},
        {"London", 512, 512, 3, StockMediaKind::Photo},
        {"Pebbles", 512, 512, 1, StockMediaKind::Photo},
        {"Bayer", 8, 8, 1, StockMediaKind::Other},
        {"Nyancat", 256, 32, 4, StockMediaKind::Other},
        {"Font 1", 1024, 1024, 4, StockMediaKind::Other},
    };
    for (const Expected& e : expected) {
        const StockMediaInfo& info = stock(e.name);
        EXPECT_EQ(info.width, e.width) << e.name;
        EXPECT_EQ(info.height, e.height) << e.name;
        EXPECT_EQ(info.channels, e.channels) << e.name;
        EXPECT_EQ(info.kind, e.kind) << e.name;
    }
    EXPECT_EQ(stock("Abstract 3").hash,
              "8979352a182bde7c3c651ba2b2f4e0615de819585cc37b7175bcefbca15a6683");
    EXPECT_EQ(stock("Abstract 3").extension, "jpg");
}

TEST(MediaStockTable, EntriesAreWellFormedAndUnique) {
    std::set<std::string_view> hashes, names;
    for (const StockMediaInfo& info : stockMediaTable()) {
        EXPECT_EQ(info.hash.size(), 64u) << info.name;
        EXPECT_TRUE(std::all_of(info.hash.begin(), info.hash.end(), [](char c) {
            return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
        })) << info.name;
        EXPECT_TRUE(info.extension == "png" || info.extension == "jpg") << info.name;
        EXPECT_TRUE(info.channels == 1 || info.channels == 3 || info.channels == 4) << info.name;
        EXPECT_GT(info.width, 0);
        EXPECT_GT(info.height, 0);
        EXPECT_TRUE(hashes.insert(info.hash).second) << info.name;
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
    }
}

TEST(MediaStockLookup, AcceptsEveryReferenceForm) {
    const StockMediaInfo* expected = &stock("Abstract 3");
    const std::string hash(expected->hash);
    EXPECT_EQ(findStockMedia("/media/a/" + hash + ".jpg"), expected);
    EXPECT_EQ(findStockMedia(hash + ".jpg"), expected);
    EXPECT_EQ(findStockMedia(hash), expected);
    EXPECT_EQ(findStockMedia("Abstract 3"), expected);
    EXPECT_EQ(findStockMedia("abstract 3"), expected);
    EXPECT_EQ(findStockMedia("ABSTRACT 3"), expected);
    EXPECT_EQ(findStockMedia("abstract_3"), expected);
    EXPECT_EQ(findStockMedia("Abstract 3.jpg"), expected);
    std::string upperHash = hash;
    std::transform(upperHash.begin(), upperHash.end(), upperHash.begin(),
                   [](char c) { return static_cast<char>(std::toupper(c)); });
    EXPECT_EQ(findStockMedia(upperHash), expected);
}

TEST(MediaStockLookup, RejectsWhatIsNotStock) {
    EXPECT_EQ(findStockMedia(""), nullptr);
    EXPECT_EQ(findStockMedia("Abstract 9"), nullptr);
    EXPECT_EQ(findStockMedia(
                  "/media/a/0000000000000000000000000000000000000000000000000000000000000000.png"),
              nullptr);
    EXPECT_EQ(findStockMedia("8979352a182bde7c3c651ba2b2f4e0615de819585cc37b7175bcefbca15a668"),
              nullptr);  // one short
    EXPECT_EQ(findStockMedia("/media/previz/buffer00.png"), nullptr);
    EXPECT_EQ(findStockMedia("Abstract 3.txt"), nullptr);
}

TEST(StandIn, MatchesTheRealSizeAndChannelLayoutForEveryEntry) {
    for (const StockMediaInfo& info : stockMediaTable()) {
        const Image8 image = makeStandIn(info);
        ASSERT_EQ(image.width, info.width) << info.name;
        ASSERT_EQ(image.height, info.height) << info.name;
        ASSERT_EQ(image.rgba.size(), static_cast<std::size_t>(info.width * info.height * 4))
            << info.name;
        std::size_t notGrey = 0, notOpaque = 0;
        for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
            notGrey += image.rgba[i + 1] != image.rgba[i] || image.rgba[i + 2] != image.rgba[i];
            notOpaque += image.rgba[i + 3] != 255;
        }
        if (info.channels == 1) {
            EXPECT_EQ(notGrey, 0u) << info.name << ": grey files give R=G=B";
        }
        if (info.channels != 4) {
            EXPECT_EQ(notOpaque, 0u) << info.name << ": no alpha in the file gives A=255";
        }
    }
}

TEST(StandIn, IsDeterministicAndPinnedForTheSmallNoise) {
    for (const char* name : {"Gray Noise Small", "RGBA Noise Medium", "London", "Pebbles", "Bayer",
                             "Font 1", "Nyancat", "Blue Noise"}) {
        EXPECT_EQ(fnv1a(makeStandIn(stock(name)).rgba), fnv1a(makeStandIn(stock(name)).rgba))
            << name;
    }
    // Pinned values: a change here changes what every shader using these textures renders. The
    // generator is integer-only, so these hold on every compiler and CPU. They are hashes of the
    // picture in file order (top row first); in memory the rows are bottom first.
    EXPECT_EQ(fnv1a(topFirst(makeStandIn(stock("Gray Noise Small")))), 0x57c7f064e89ca7a2ULL);
    EXPECT_EQ(fnv1a(topFirst(makeStandIn(stock("RGBA Noise Small")))), 0xd5da97d9ca6e3457ULL);
}

TEST(StandIn, GrayNoiseIsUniformBytes) {
    const Image8 noise = makeStandIn(stock("Gray Noise Medium"));
    const std::vector<int> red = channel(noise, 0);
    EXPECT_NEAR(mean(red), 127.5, 1.5);
    EXPECT_EQ(std::set<int>(red.begin(), red.end()).size(), 256u);
}

TEST(StandIn, RgbaNoiseHasFourIndependentUniformChannels) {
    const Image8 noise = makeStandIn(stock("RGBA Noise Medium"));
    for (int c = 0; c < 4; ++c) {
        const std::vector<int> values = channel(noise, c);
        EXPECT_NEAR(mean(values), 127.5, 1.5) << c;
        EXPECT_EQ(std::set<int>(values.begin(), values.end()).size(), 256u) << c;
    }
    const std::vector<int> r = channel(noise, 0), g = channel(noise, 1);
    std::size_t equal = 0;
    for (std::size_t i = 0; i < r.size(); ++i) equal += r[i] == g[i];
    EXPECT_LT(equal, r.size() / 100);  // 1/256 expected for independent bytes
}

TEST(StandIn, PhotoHasDetailAtEveryMipLevel) {
    const StockMediaInfo& info = stock("Abstract 3");
    const Image8 photo = makeStandIn(info);
    std::vector<double> level(static_cast<std::size_t>(info.width * info.height));
    for (std::size_t i = 0; i < level.size(); ++i)
        level[i] = (photo.rgba[i * 4] + photo.rgba[i * 4 + 1] + photo.rgba[i * 4 + 2]) / 3.0;
    std::size_t changes = 0;
    for (std::size_t i = 1; i < level.size(); ++i) changes += level[i] != level[i - 1];
    EXPECT_GT(changes, level.size() / 2) << "neighbouring pixels should differ";
    for (int size = info.width; size >= 4; size /= 2) {
        EXPECT_GT(stddev(level), 2.0) << "flat at mip size " << size;
        std::vector<double> next(static_cast<std::size_t>(size / 2 * size / 2));
        for (int y = 0; y < size / 2; ++y)
            for (int x = 0; x < size / 2; ++x) {
                auto at = [&](int xx, int yy) {
                    return level[static_cast<std::size_t>(yy * size + xx)];
                };
                next[static_cast<std::size_t>(y * (size / 2) + x)] =
                    (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) +
                     at(2 * x + 1, 2 * y + 1)) /
                    4;
            }
        level = std::move(next);
    }
    EXPECT_NE(fnv1a(photo.rgba), fnv1a(makeStandIn(stock("Organic 1")).rgba));
}

TEST(StandIn, OtherTexturesHaveTheirOwnPatterns) {
    const Image8 bayerImage = makeStandIn(stock("Bayer"));
    const std::vector<int> bayer = channel(bayerImage, 0);
    EXPECT_EQ(std::set<int>(bayer.begin(), bayer.end()).size(), 64u);
    EXPECT_EQ(topFirst(bayerImage)[0], 0) << "the Bayer matrix starts with 0 at the top-left";

    const std::vector<int> alpha = channel(makeStandIn(stock("Nyancat")), 3);
    EXPECT_TRUE(std::count(alpha.begin(), alpha.end(), 0) > 0 &&
                std::count(alpha.begin(), alpha.end(), 255) > 0);

    // Blue noise: a flat histogram, and neighbours anti-correlated (white noise would give ~0).
    const Image8 blue = makeStandIn(stock("Blue Noise"));
    const std::vector<int> values = channel(blue, 0);
    std::vector<int> histogram(256, 0);
    for (int v : values) ++histogram[static_cast<std::size_t>(v)];
    EXPECT_EQ(*std::min_element(histogram.begin(), histogram.end()),
              static_cast<int>(values.size() / 256));
    double m = mean(values), covariance = 0, variance = 0;
    for (std::size_t i = 0; i + 1 < values.size(); ++i) {
        covariance += (values[i] - m) * (values[i + 1] - m);
        variance += (values[i] - m) * (values[i] - m);
    }
    EXPECT_LT(covariance / variance, -0.05);
}

namespace {
// The coverage (red) of character `code`'s cell in the font stand-in, rows top first, and where
// its ink lies.
struct Cell {
    double ink = 0;            // sum of red / 255
    double centreColumns = 0;  // share of the ink in the middle fifth of the columns
    double centreRows = 0;     // share in the middle fifth of the rows
    double lowerHalf = 0;      // share in the lower half
};
Cell fontCell(const Image8& atlas, int code) {
    const int cw = atlas.width / 16, ch = atlas.height / 16, x0 = (code % 16) * cw, y0 = (code / 16) * ch;
    Cell cell;
    double columns = 0, rows = 0, lower = 0;
    for (int y = 0; y < ch; ++y)
        for (int x = 0; x < cw; ++x) {
            const double ink = atlas.rgba[(static_cast<std::size_t>(y0 + y) * atlas.width + x0 + x) * 4] / 255.0;
            cell.ink += ink;
            if (std::abs(2 * x - cw) < cw / 5) columns += ink;
            if (std::abs(2 * y - ch) < ch / 5) rows += ink;
            if (y >= ch / 2) lower += ink;
        }
    if (cell.ink > 0) {
        cell.centreColumns = columns / cell.ink;
        cell.centreRows = rows / cell.ink;
        cell.lowerHalf = lower / cell.ink;
    }
    return cell;
}
}  // namespace

// Font 1's stand-in has the site's layout (16 x 16 cells, code c at column c % 16, row c / 16 from
// the top), real glyphs in red (a bar is a bar, a dash a dash, a full stop sits low, a space is
// empty, letters differ) and a signed distance in alpha that agrees with them (below 127 inside).
TEST(StandIn, FontHasTheSitesLayoutAndLegibleGlyphs) {
    const Image8 made = makeStandIn(stock("Font 1"));
    ASSERT_EQ(made.width, 1024);
    const Image8 atlas{made.width, made.height, topFirst(made)};
    EXPECT_EQ(fontCell(atlas, ' ').ink, 0.0) << "a space is empty";
    const Cell bar = fontCell(atlas, '|'), dash = fontCell(atlas, '-'), stop = fontCell(atlas, '.');
    EXPECT_GT(bar.ink, 50.0);
    EXPECT_GT(bar.centreColumns, 0.9) << "'|' is a vertical bar in the middle of its cell";
    EXPECT_GT(dash.centreRows, 0.9) << "'-' is a horizontal bar at mid height";
    EXPECT_GT(stop.lowerHalf, 0.95) << "'.' sits on the baseline, in the lower half";
    EXPECT_LT(stop.ink, bar.ink);
    const Cell h = fontCell(atlas, 'H'), i = fontCell(atlas, 'I'), w = fontCell(atlas, 'W');
    EXPECT_GT(w.ink, i.ink) << "a W has more ink than an I";
    EXPECT_LT(h.centreColumns, i.centreColumns) << "H's ink is in its two stems, I's in the middle";
    std::size_t agree = 0, inked = 0;
    for (std::size_t p = 0; p < atlas.rgba.size() / 4; ++p) {
        const int red = atlas.rgba[p * 4], alpha = atlas.rgba[p * 4 + 3];
        if (red >= 250) {
            ++inked;
            agree += alpha < 127;
        }
    }
    ASSERT_GT(inked, 1000u);
    EXPECT_EQ(agree, inked) << "the distance is negative (alpha below 127/255) inside every glyph";
}
