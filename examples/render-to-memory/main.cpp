// render-to-memory: loads a shadertoy (folder, manifest or export), renders FRAMES frames headless
// at 320x180 and 60 fps into memory and prints each frame's mean RGBA (8-bit levels).
// Usage: render-to-memory SHADERTOY [FRAMES]
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <toyhost/Session.h>
#include <toyhost/Version.h>

int main(int argc, char** argv) {
    if (argc < 2) return std::fprintf(stderr, "usage: %s SHADERTOY [FRAMES]\n", argv[0]), 2;
    const int frames = argc > 2 ? std::atoi(argv[2]) : 3;
    toyhost::Result<toyhost::Shadertoy> shadertoy = toyhost::Shadertoy::load(argv[1]);
    if (!shadertoy) return std::fprintf(stderr, "%s\n", shadertoy.error().text().c_str()), 1;
    int status = 0;
    toyhost::runOnGlThread([&] {  // Mesa's compiler wants a large stack: create and use it there
        toyhost::SessionSettings settings;
        settings.width = 320, settings.height = 180, settings.date = "2026-01-01T00:00:00";
        auto session = toyhost::Session::createHeadless(*shadertoy, settings);
        if (!session) return status = 1, (void)std::fprintf(stderr, "%s\n", session.error().text().c_str());
        std::vector<std::uint8_t> rgba(320 * 180 * 4);  // rows top first
        for (int frame = 0; frame < frames; ++frame) {
            toyhost::Status stepped = (*session)->step();
            if (stepped.ok()) stepped = (*session)->read("Image", rgba);
            if (!stepped) return status = 1, (void)std::fprintf(stderr, "%s\n", stepped.error().text().c_str());
            double sum[4] = {0, 0, 0, 0};
            for (std::size_t i = 0; i < rgba.size(); ++i) sum[i % 4] += rgba[i];
            const double n = 320.0 * 180.0;
            std::printf("frame %d: mean %.3f %.3f %.3f %.3f\n", frame, sum[0] / n, sum[1] / n, sum[2] / n, sum[3] / n);
        }
    });
    std::fprintf(stderr, "toyhost %s\n", toyhost::versionString());
    return status;
}
