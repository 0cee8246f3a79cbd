// The gallery's goldens catch what matters (issue 20): each mutation below, a small wrong edit of
// a port that an earlier tolerance let through, is applied to a copy of the port and rendered as
// its golden case; the comparison must FAIL. Also the physical invariants that are exact numbers
// (flat water's caustic is 1 in ripple-pool). The list is mirrored in tests/README.md.
#include "GalleryRender.h"
#include "GlTestSupport.h"
#include "Golden.h"

#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

struct Mutation {
    const char* name;
    const char* goldenCase;  // a case of galleryCases()
    SourceEdit edit;
    friend void PrintTo(const Mutation& m, std::ostream* os) { *os << m.name; }
};

const Mutation kMutations[] = {
    {"exp_sine_fresnel_f0_002", "exp_sine_ocean_t3",
     {"image.glsl", "float Fk = 0.04 + 0.96 * pow(", "float Fk = 0.02 + 0.98 * pow("}},
    {"exp_sine_black_block_10x10", "exp_sine_ocean_t3",
     {"image.glsl", "fragColor = vec4(pow(col, vec3(1.0 / 2.2)) + ditherNoise(fragCoord), 1.0);",
      "fragColor = vec4(pow(col, vec3(1.0 / 2.2)) + ditherNoise(fragCoord), 1.0);\n"
      "    if (all(lessThan(abs(fragCoord - vec2(100.0, 40.0)), vec2(5.0)))) fragColor = vec4(0.0, 0.0, 0.0, 1.0);"}},
    {"raymarched_sea_shade_octaves_5", "raymarched_sea_down",
     {"image.glsl", "const int   SHADE_OCTAVES = 6;", "const int   SHADE_OCTAVES = 5;"}},
    // (was: the Fresnel cap removed; since issue 29 the four-normal Fresnel average stays under
    // the cap almost everywhere, 50-52 dB, so the mutation moved to what the average weighs)
    {"raymarched_sea_fresnel_f0_004", "raymarched_sea_t4",
     {"image.glsl", "float Fk = 0.02 + 0.98 * pow(1.0 - cosV, 5.0);", "float Fk = 0.04 + 0.96 * pow(1.0 - cosV, 5.0);"}},
    {"raymarched_sea_visible_area_ignored", "raymarched_sea_t4",
     {"image.glsl", "float seen = cosV / nk.y;", "float seen = 1.0;"}},
    {"raymarched_sea_mouse_ignored", "raymarched_sea_mouse",
     {"image.glsl", "    if (iMouse.z > 0.0) {\n        vec2 m", "    if (iMouse.z > 1e9) {\n        vec2 m"}},
    {"raymarched_sea_mouse_yaw_halved", "raymarched_sea_mouse",
     {"image.glsl", "yaw += m.x * 3.0;", "yaw += m.x * 1.5;"}},
    {"lake_optics_k_red_040", "lake_optics_t2",
     {"image.glsl", "K = vec3(0.46, 0.09, 0.06); b = 0.11;", "K = vec3(0.40, 0.09, 0.06); b = 0.11;"}},
    {"lake_optics_b_008", "lake_optics_t2",
     {"image.glsl", "K = vec3(0.46, 0.09, 0.06); b = 0.11;", "K = vec3(0.46, 0.09, 0.06); b = 0.08;"}},
    {"lake_optics_mouse_ignored", "lake_optics_mouse",
     {"image.glsl", "if (iMouse.z > 0.0) yaw = (iMouse.x / iResolution.x - 0.5) * 1.2;",
      "if (iMouse.z > 1e9) yaw = (iMouse.x / iResolution.x - 0.5) * 1.2;"}},
    {"lake_optics_mouse_sign", "lake_optics_mouse",
     {"image.glsl", "if (iMouse.z > 0.0) yaw = (iMouse.x / iResolution.x - 0.5) * 1.2;",
      "if (iMouse.z > 0.0) yaw = (0.5 - iMouse.x / iResolution.x) * 1.2;"}},
    {"caustics_pool_mouse_ignored", "caustics_pool_mouse",
     {"image.glsl", "if (iMouse.z > 0.0) yaw", "if (iMouse.z > 1e9) yaw"}},
    {"ripple_pool_fresnel_constant", "ripple_pool_drag_f90",
     {"image.glsl", "float F = 0.02 + 0.98 * pow(1.0 - cosi, 5.0);", "float F = 0.02;"}},
    {"ripple_pool_3d_fresnel_constant", "ripple_pool_3d_drag_f90",
     {"image.glsl", "float F = 0.02 + 0.98 * pow(1.0 - cosi, 5.0);", "float F = 0.02;"}},
    {"coastal_foam_mouse_ignored", "coastal_foam_mouse",
     {"image.glsl", "if (iMouse.z > 0.0) yaw", "if (iMouse.z > 1e9) yaw"}},
};

class GalleryMutation : public ::testing::TestWithParam<Mutation> {};

TEST_P(GalleryMutation, FailsItsGolden) {
    const Mutation& m = GetParam();
    const GalleryCase c = galleryCase(m.goldenCase);
    const fs::path dir = freshOutputDir(std::string("golden/mutations/") + m.name);
    const auto frame = renderGalleryCase(c, dir, {m.edit});
    ASSERT_TRUE(frame);
    auto expected = loadImageFile(sourceDir() / "tests/golden/gallery" / (std::string(c.name) + ".png"));
    ASSERT_TRUE(expected.ok()) << expected.error().text();
    auto actual = loadImageFile(*frame);
    ASSERT_TRUE(actual.ok()) << actual.error().text();
    const GoldenVerdict verdict = compareWithGolden(*expected, *actual);
    std::printf("%s against %s: %s\n", m.name, c.name, verdict.text().c_str());
    EXPECT_FALSE(verdict.pass()) << m.name << " passes the golden " << c.name << ": " << verdict.text();
}

INSTANTIATE_TEST_SUITE_P(Gallery, GalleryMutation, ::testing::ValuesIn(kMutations),
                         [](const auto& info) { return std::string(info.param.name); });

// ripple-pool's caustic is normalised once: on flat water (the calm pool) it is exactly 1, so
// replacing it by the constant 1 leaves every pixel of the frame unchanged, from above and in the
// 3-D view (where the floor's and the sphere's caustics both use it).
TEST(GalleryInvariants, RipplePoolFlatWaterCausticIsOne) {
    for (const char* name : {"ripple_pool_calm", "ripple_pool_3d_calm"}) {
        SCOPED_TRACE(name);
        const GalleryCase calm = galleryCase(name);
        const std::string out = std::string("golden/invariants/") + name;
        const auto asIs = renderGalleryCase(calm, freshOutputDir(out + "_caustic_as_is"));
        const auto one = renderGalleryCase(calm, freshOutputDir(out + "_caustic_one"),
                                           {{"image.glsl", "float caustic = (1.0 + 0.12) / (abs(det) + 0.12);",
                                             "float caustic = 1.0;"}});
        ASSERT_TRUE(asIs && one);
        auto a = loadImageFile(*asIs);
        auto b = loadImageFile(*one);
        ASSERT_TRUE(a.ok() && b.ok());
        EXPECT_EQ(maxAbsError(*a, *b), 0) << "flat water's caustic is not 1";
    }
}

}  // namespace
}  // namespace toyhost::testing
