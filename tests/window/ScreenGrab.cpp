#include "ScreenGrab.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <bit>
#include <memory>

namespace toyhost::testing {

namespace {

// One 0..255 channel of `pixel` under `mask` (a TrueColor visual's channel mask).
std::uint8_t channel(unsigned long pixel, unsigned long mask) {
    if (mask == 0) return 0;
    const int shift = std::countr_zero(mask);
    const unsigned long max = mask >> shift;
    return static_cast<std::uint8_t>(((pixel & mask) >> shift) * 255 / max);
}

}  // namespace

Image8 grabWindow(const std::string& window) {
    std::unique_ptr<Display, int (*)(Display*)> display(XOpenDisplay(nullptr), XCloseDisplay);
    if (!display) return {};
    const Window id = std::stoul(window);
    XWindowAttributes attributes{};
    if (!XGetWindowAttributes(display.get(), id, &attributes)) return {};
    auto destroy = [](XImage* i) { XDestroyImage(i); };  // a macro in Xutil.h
    std::unique_ptr<XImage, decltype(destroy)> image(
        XGetImage(display.get(), id, 0, 0, attributes.width, attributes.height, AllPlanes, ZPixmap), destroy);
    if (!image) return {};
    Image8 out;
    out.width = attributes.width;
    out.height = attributes.height;
    out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const unsigned long pixel = XGetPixel(image.get(), x, y);
            std::uint8_t* p = &out.rgba[(static_cast<std::size_t>(out.height - 1 - y) * out.width + x) * 4];
            p[0] = channel(pixel, image->red_mask);
            p[1] = channel(pixel, image->green_mask);
            p[2] = channel(pixel, image->blue_mask);
            p[3] = 255;
        }
    return out;
}

}  // namespace toyhost::testing
