// TestPictures: named RGBA8 pictures made from a function of (x, y, channel), rows top first, for
// the PNG encoder tests. CPU only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace toyhost::testing {

struct Picture {
    std::string name;
    int width, height;
    std::vector<std::uint8_t> rgba;  // rows top first
};

// `byte(x, y, c)` for every pixel (x, y from the top-left) and channel c = 0..3.
template <class F>
Picture makePicture(std::string name, int width, int height, F&& byte) {
    Picture p{std::move(name), width, height, {}};
    p.rgba.reserve(static_cast<std::size_t>(width) * height * 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 4; ++c) p.rgba.push_back(static_cast<std::uint8_t>(byte(x, y, c)));
    return p;
}

}  // namespace toyhost::testing
