#include "image/MipChain.h"

#include <algorithm>

namespace toyhost {

std::vector<MipLevel> boxMipChain(std::span<const std::uint8_t> rgba, int width, int height) {
    std::vector<MipLevel> levels;
    std::span<const std::uint8_t> source = rgba;
    int w = width, h = height;
    while (w > 1 || h > 1) {
        MipLevel level;
        level.width = std::max(1, w / 2);
        level.height = std::max(1, h / 2);
        level.rgba.resize(static_cast<std::size_t>(level.width) * level.height * 4);
        const int stepX = w > 1 ? 2 : 1, stepY = h > 1 ? 2 : 1;
        const int count = stepX * stepY;
        for (int y = 0; y < level.height; ++y)
            for (int x = 0; x < level.width; ++x)
                for (int c = 0; c < 4; ++c) {
                    int sum = 0;
                    for (int dy = 0; dy < stepY; ++dy)
                        for (int dx = 0; dx < stepX; ++dx)
                            sum += source[(static_cast<std::size_t>(y * stepY + dy) * w + (x * stepX + dx)) * 4 + c];
                    level.rgba[(static_cast<std::size_t>(y) * level.width + x) * 4 + c] =
                        static_cast<std::uint8_t>((sum + count / 2) / count);
                }
        levels.push_back(std::move(level));
        source = levels.back().rgba;
        w = levels.back().width;
        h = levels.back().height;
    }
    return levels;
}

}  // namespace toyhost
