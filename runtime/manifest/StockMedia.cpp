#include "manifest/StockMedia.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <cstdint>
#include <string>
#include <vector>

#include "core/Suggest.h"

namespace toyhost {

namespace {
constexpr auto Noise = StockMediaKind::Noise;
constexpr auto Photo = StockMediaKind::Photo;
constexpr auto Other = StockMediaKind::Other;

// Sizes and channel counts. Sources (facts only, read in public repositories):
//  [DS]  GabeRundlett/desktop-shadertoy src/ui/components/buffer_panel_input_window.rml: the
//        site's input picker labels per /media/a file, "W x H" and "N ch, uint8".
//  [QT]  jherico/qtvr app/resources/qml/shadertoy/Shadertoy.qml: the old site's preset tooltips
//        ("Resolution: W x H, Format: r/rgb/rgba") for /presets/texNN, mapped to the /media/a
//        hashes by beautypi/shadertoy-iOS-v2 shadertoy/ShaderInput.m (texNN <-> hash table).
//  [LEN] hbatagelo/shaderbg src/shadertoy/importer.rs: the byte length of every file. The noise
//        PNGs are incompressible, so their lengths pin size x channels: 4241 B = 64*64*1,
//        16558 B = 64*64*4, 67474 B = 256*256*1, 264082 B = 256*256*4, Blue Noise 4202841 B =
//        1024*1024*4 (each plus PNG overhead).
//  [NYAN] reindernijhoff/shadertoy nyan/Image.glsl: samples Nyancat's .w as the sprite mask and
//        steps 40-pixel frames across the 256-wide sheet, so the file has alpha.
// Where [DS] and [QT] disagree it is noted on the entry.
constexpr std::array<StockMediaInfo, 22> kStockMedia{{
    // [DS][QT] 1024x1024 rgb
    {"52d2a8f514c4fd2d9866587f4d7b2a5bfa1a11a0e772077d7682deb8b3b517e5",
     "jpg", "Abstract 1", 1024, 1024, 3, Photo},
    // [DS][QT] 512x512 rgb
    {"bd6464771e47eed832c5eb2cd85cdc0bfc697786b903bfd30f890f9d4fc36657",
     "jpg", "Abstract 2", 512, 512, 3, Photo},
    // [DS][QT] 1024x1024 rgb
    {"8979352a182bde7c3c651ba2b2f4e0615de819585cc37b7175bcefbca15a6683",
     "jpg", "Abstract 3", 1024, 1024, 3, Photo},
    // [DS][QT] 8x8, one channel
    {"85a6d68622b36995ccb98a89bbb119edf167c914660e4450d313de049320005c",
     "png", "Bayer", 8, 8, 1, Other},
    // [DS] 1024x1024 4 ch; [LEN] agrees. Blue, not white, noise: kept out of Noise.
    {"cb49c003b454385aa9975733aff4571c62182ccdda480aaba9a8d250014f00ec",
     "png", "Blue Noise", 1024, 1024, 4, Other},
    // [DS] 1024x1024 4 ch (a distance-field glyph atlas by otaviogood)
    {"08b42b43ae9d3c0605da11d0eac86618ea888e62cdd9518ee8b9097488b31560",
     "png", "Font 1", 1024, 1024, 4, Other},
    // [DS][QT][LEN] 256x256, one channel
    {"0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5",
     "png", "Gray Noise Medium", 256, 256, 1, Noise},
    // [DS][QT][LEN] 64x64, one channel
    {"0a40562379b63dfb89227e6d172f39fdce9022cba76623f1054a2c83d6c0ba5d",
     "png", "Gray Noise Small", 64, 64, 1, Noise},
    // [DS][QT] 1024x1024 rgb
    {"fb918796edc3d2221218db0811e240e72e340350008338b0c07a52bd353666a6",
     "jpg", "Lichen", 1024, 1024, 3, Photo},
    // [DS][QT] 512x512 rgb
    {"8de3a3924cb95bd0e95a443fff0326c869f9d4979cd1d5b6e94e2a01f5be53e9",
     "jpg", "London", 512, 512, 3, Photo},
    // [DS][QT] 256x32; [DS] 4 ch, [QT] says rgb, [NYAN] shows the alpha is used: 4.
    {"cbcbb5a6cfb55c36f8f021fbb0e3f69ac96339a39fa85cd96f2017a2192821b5",
     "png", "Nyancat", 256, 32, 4, Other},
    // Organic 1-4: [DS][QT] 1024x1024 rgb
    {"cd4c518bc6ef165c39d4405b347b51ba40f8d7a065ab0e8d2e4f422cbc1e8a43",
     "jpg", "Organic 1", 1024, 1024, 3, Photo},
    {"92d7758c402f0927011ca8d0a7e40251439fba3a1dac26f5b8b62026323501aa",
     "jpg", "Organic 2", 1024, 1024, 3, Photo},
    {"79520a3d3a0f4d3caa440802ef4362e99d54e12b1392973e4ea321840970a88a",
     "jpg", "Organic 3", 1024, 1024, 3, Photo},
    {"3871e838723dd6b166e490664eead8ec60aedd6b8d95bc8e2fe3f882f0fd90f0",
     "jpg", "Organic 4", 1024, 1024, 3, Photo},
    // [DS][QT] 512x512, one channel (a grey photo)
    {"ad56fba948dfba9ae698198c109e71f118a54d209c0ea50d77ea546abad89c57",
     "png", "Pebbles", 512, 512, 1, Photo},
    // [DS][QT][LEN] 256x256 rgba
    {"f735bee5b64ef98879dc618b016ecf7939a5756040c2cde21ccb15e69a6e1cfb",
     "png", "RGBA Noise Medium", 256, 256, 4, Noise},
    // [DS][QT][LEN] 64x64 rgba
    {"3083c722c0c738cad0f468383167a0d246f91af2bfa373e9c5c094fb8c8413e0",
     "png", "RGBA Noise Small", 64, 64, 4, Noise},
    // Rock Tiles, Rusty Metal, Stars: [DS][QT] 512x512 rgb
    {"10eb4fe0ac8a7dc348a2cc282ca5df1759ab8bf680117e4047728100969e7b43",
     "jpg", "Rock Tiles", 512, 512, 3, Photo},
    {"95b90082f799f48677b4f206d856ad572f1d178c676269eac6347631d4447258",
     "jpg", "Rusty Metal", 512, 512, 3, Photo},
    {"e6e5631ce1237ae4c05b3563eda686400a401df4548d0f9fad40ecac1659c46c",
     "jpg", "Stars", 512, 512, 3, Photo},
    // [DS][QT] 1024x1024; [DS] 1 ch, [QT] rgb: unresolved, the newer [DS] label is used.
    {"1f7dca9c22f324751f2a5a59c9b181dfe3b5564a04b724c657732d0bf09c99db",
     "jpg", "Wood", 1024, 1024, 1, Photo},
}};
}  // namespace

std::span<const StockMediaInfo> stockMediaTable() { return kStockMedia; }

namespace {
char lowerAscii(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

// Case-insensitive, with '_' and '-' read as spaces, so file stems like "abstract_3" match too.
bool sameName(std::string_view a, std::string_view b) {
    auto fold = [](char c) { return (c == '_' || c == '-') ? ' ' : lowerAscii(c); };
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                              [&](char x, char y) { return fold(x) == fold(y); });
}

bool isImageExtension(std::string_view ext) {
    return sameName(ext, "png") || sameName(ext, "jpg") || sameName(ext, "jpeg");
}
}  // namespace

const StockMediaInfo* findStockMedia(std::string_view ref) {
    // "/media/a/<hash>.<ext>" and "<hash>.<ext>" reduce to "<hash>"; "Abstract 3.jpg" to the name.
    if (const auto slash = ref.rfind('/'); slash != std::string_view::npos)
        ref.remove_prefix(slash + 1);
    if (const auto dot = ref.rfind('.');
        dot != std::string_view::npos && isImageExtension(ref.substr(dot + 1)))
        ref.remove_suffix(ref.size() - dot);
    for (const StockMediaInfo& info : kStockMedia)
        if (sameName(ref, info.hash) || sameName(ref, info.name)) return &info;
    return nullptr;
}

const StockMediaInfo* nearStockMedia(std::string_view ref) {
    if (findStockMedia(ref)) return nullptr;
    if (const auto slash = ref.rfind('/'); slash != std::string_view::npos) ref.remove_prefix(slash + 1);
    if (const auto dot = ref.rfind('.'); dot != std::string_view::npos) ref.remove_suffix(ref.size() - dot);
    // A hash is 64 hex digits: a typo changes a few, a different texture changes most of them.
    constexpr std::size_t kHashTypos = 3;
    std::string lowered(ref);
    for (char& c : lowered) c = lowerAscii(c);  // hashes match whatever their case, as in findStockMedia
    for (const StockMediaInfo& info : kStockMedia)
        if (lowered.size() + kHashTypos >= info.hash.size() && editDistance(lowered, info.hash) <= kHashTypos)
            return &info;
    std::vector<std::string> names;
    for (const StockMediaInfo& info : kStockMedia) names.emplace_back(info.name);
    if (std::optional<std::string> name = closestMatch(ref, names)) return findStockMedia(*name);
    return nullptr;
}

namespace {
// The stock inputs of the site's media browser, as public media lists of the site name them (the
// ids of cubemaps, volumes, videos and music are the site's, checked against public mirrors of its
// media list). Cubemap names follow the site's order cube00..cube05; video and music names are
// not known for certain and are given by kind and the first hash digits. The cubemaps' face sizes
// are not known (0): their stand-ins use defaults::kCubemapStandInSize.
constexpr std::array<StockInputInfo, 19> kStockInputs{{
    {"585f9546c092f53ded45332b343144396c0b2d70d9965f585ebc172080d8aa58", "jpg", "Uffizi Gallery",
     StockInputForm::Cubemap, 0, 3},
    {"793a105653fbdadabdc1325ca08675e1ce48ae5f12e37973829c87bea4be3232", "png", "Uffizi Gallery Blurred",
     StockInputForm::Cubemap, 0, 4},
    {"488bd40303a2e2b9a71987e48c66ef41f5e937174bf316d3ed0e86410784b919", "jpg", "St Peter's Basilica",
     StockInputForm::Cubemap, 0, 3},
    {"550a8cce1bf403869fde66dddf6028dd171f1852f4a704a465e1b80d23955663", "png", "St Peter's Basilica Blurred",
     StockInputForm::Cubemap, 0, 4},
    {"94284d43be78f00eb6b298e6d78656a1b34e2b91b34940d02f1ca8b22310e8a0", "png", "Forest",
     StockInputForm::Cubemap, 0, 4},
    {"0681c014f6c88c356cf9c0394ffe015acc94ec1474924855f45d22c3e70b5785", "png", "Forest Blurred",
     StockInputForm::Cubemap, 0, 4},
    {"27012b4eadd0c3ce12498b867058e4f717ce79e10a99568cca461682d84a4b04", "bin", "Grey Noise3D",
     StockInputForm::Volume, 32, 1},
    {"aea6b99da1d53055107966b59ac5444fc8bc7b3ce2d0bbb6a4a3cbae1d97f3aa", "bin", "RGBA Noise3D",
     StockInputForm::Volume, 32, 4},
    {"3405e48f74815c7baa49133bdc835142948381fbe003ad2f12f5087715731153", "ogv", "Video 3405e4",
     StockInputForm::Video, 0, 3},
    {"35c87bcb8d7af24c54d41122dadb619dd920646a0bd0e477e7bdc6d12876df17", "webm", "Video 35c87b",
     StockInputForm::Video, 0, 3},
    {"c3a071ecf273428bc72fc72b2dd972671de8da420a2d4f917b75d20e1c24b34c", "ogv", "Video c3a071",
     StockInputForm::Video, 0, 3},
    {"e81e818ac76a8983d746784b423178ee9f6cdcdf7f8e8d719341a6fe2d2ab303", "webm", "Video e81e81",
     StockInputForm::Video, 0, 3},
    {"a6a1cf7a09adfed8c362492c88c30d74fb3d2f4f7ba180ba34b98556660fada1", "mp3", "Music a6a1cf",
     StockInputForm::Music, 0, 1},
    {"3c33c415862bb7964d256f4749408247da6596f2167dca2c86cc38f83c244aa6", "mp3", "Music 3c33c4",
     StockInputForm::Music, 0, 1},
    {"29de534ed5e4a6a224d2dfffab240f2e19a9d95f5e39de8898e850efdb2a99de", "mp3", "Music 29de53",
     StockInputForm::Music, 0, 1},
    {"48e2d9ef22ca6673330b8c38a260c87694d2bbc94c19fec9dfa4a1222c364a99", "mp3", "Music 48e2d9",
     StockInputForm::Music, 0, 1},
    {"d96b229eeb7a08d53adfcf1ff89e54c9ffeebed193d317d1a01cc8125c0f5cca", "mp3", "Music d96b22",
     StockInputForm::Music, 0, 1},
    {"894a09f482fb9b2822c093630fc37f0ce6cfec02b652e4e341323e4b6e4a4543", "mp3", "Music 894a09",
     StockInputForm::Music, 0, 1},
    {"ec8a6ea755d34600547a5353f21f0a453f9f55ff95514383b2d80b8d71283eda", "mp3", "Music ec8a6e",
     StockInputForm::Music, 0, 1},
}};
}  // namespace

std::span<const StockInputInfo> stockInputTable() { return kStockInputs; }

const StockInputInfo* findStockInput(std::string_view ref) {
    if (const auto slash = ref.rfind('/'); slash != std::string_view::npos) ref.remove_prefix(slash + 1);
    const std::string_view whole = ref;
    if (const auto dot = ref.rfind('.'); dot != std::string_view::npos) ref.remove_suffix(ref.size() - dot);
    for (const StockInputInfo& info : kStockInputs)
        if (sameName(ref, info.hash) || sameName(whole, info.name) || sameName(ref, info.name)) return &info;
    return nullptr;
}

std::string stockInputPath(const StockInputInfo& info) {
    return "/media/a/" + std::string(info.hash) + "." + std::string(info.extension);
}

const char* stockInputFormName(StockInputForm form) {
    switch (form) {
        case StockInputForm::Cubemap: return "cubemap";
        case StockInputForm::Volume: return "volume";
        case StockInputForm::Video: return "video";
        case StockInputForm::Music: return "music";
    }
    return "?";
}

std::string stockMediaPath(const StockMediaInfo& info) {
    return "/media/a/" + std::string(info.hash) + "." + std::string(info.extension);
}

}  // namespace toyhost
