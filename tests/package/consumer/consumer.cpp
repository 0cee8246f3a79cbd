// A consumer of the installed library (built by check_consumer.sh with CMake or pkg-config):
// renders FRAMES frames of SHADERTOY headless at WxH, 30 fps, a fixed date, and writes them to OUT
// as the CLI's `--out -` does (RGBA8, rows top first, no header). Fails when the library's version
// differs from the header's or the last frame is one flat colour.
// Usage: consumer SHADERTOY WxH FRAMES OUT
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

#include <toyhost/Session.h>
#include <toyhost/Version.h>

int main(int argc, char** argv) {
    if (argc != 5) return std::fprintf(stderr, "usage: consumer SHADERTOY WxH FRAMES OUT\n"), 2;
    if (std::strcmp(toyhost::versionString(), TOYHOST_VERSION_STRING) != 0)
        return std::fprintf(stderr, "library %s, header %s\n", toyhost::versionString(), TOYHOST_VERSION_STRING), 1;
    int width = 0, height = 0;
    if (std::sscanf(argv[2], "%dx%d", &width, &height) != 2) return 2;
    toyhost::SessionSettings settings;
    settings.width = width;
    settings.height = height;
    settings.fps = 30;
    settings.date = "2026-01-01T00:00:00";
    const int frames = std::atoi(argv[3]);
    auto shadertoy = toyhost::Shadertoy::load(argv[1]);
    if (!shadertoy) return std::fprintf(stderr, "%s\n", shadertoy.error().text().c_str()), 1;
    std::ofstream out(argv[4], std::ios::binary);
    std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
    int status = 0;
    toyhost::runOnGlThread([&] {
        auto session = toyhost::Session::createHeadless(*shadertoy, settings);
        if (!session) return status = 1, (void)std::fprintf(stderr, "%s\n", session.error().text().c_str());
        for (int i = 0; i < frames; ++i) {
            toyhost::Status done = (*session)->step();
            if (done) done = (*session)->read("Image", rgba, toyhost::RowOrder::TopFirst);
            if (!done) return status = 1, (void)std::fprintf(stderr, "%s\n", done.error().text().c_str());
            out.write(reinterpret_cast<const char*>(rgba.data()), std::streamsize(rgba.size()));
        }
    });
    bool flat = true;
    for (std::size_t i = 4; i < rgba.size() && flat; ++i) flat = rgba[i] == rgba[i % 4];
    if (status == 0 && flat) return std::fprintf(stderr, "the last frame is one flat colour\n"), 1;
    std::printf("consumer: %d frames of %s with toyhost %s\n", frames, argv[1], toyhost::versionString());
    return status;
}
