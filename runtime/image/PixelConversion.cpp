#include "image/PixelConversion.h"

namespace toyhost {

void toUnorm8(std::span<const float> values, std::vector<std::uint8_t>& out) {
    out.resize(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = unorm8(values[i]);
}

}  // namespace toyhost
