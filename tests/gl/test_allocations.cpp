// "Nothing per frame that need not be": once running, the Player's frame (input events, uniforms,
// every pass, the keyboard upload) makes no heap allocation. Counted by replacing the global
// operator new in this test executable (Mesa's own allocations use malloc and are not counted).
#include "GlTestSupport.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace toyhost::testing {
namespace {

class Allocations : public GlTest {};

TEST_F(Allocations, APlayerFrameAllocatesNothing) {
    TOYHOST_REQUIRE_SHARED("shadertoys/7tSSDD");
    // Mountains & Lakes: Common, four buffers with feedback, the keyboard, mipmapped buffers.
    auto toy = loadSession(context_, sourceDir() / "shadertoys/mountains-lakes", 64, 36);
    ASSERT_TRUE(toy);
    std::vector<InputEvent> events;
    events.reserve(8);
    for (int i = 0; i < 3; ++i) stepAt(*toy);  // warm-up: first uses of every program
    allocations = 0;
    counting = true;
    for (int i = 0; i < 20; ++i) {
        events.clear();
        if (i % 4 == 0) events.push_back(InputEvent::mouseDown(10.0f + i, 20.0f));
        if (i % 4 == 2) events.push_back(InputEvent::mouseUp());
        if (i % 5 == 0) events.push_back(InputEvent::keyDown(32));
        if (i % 5 == 3) events.push_back(InputEvent::keyUp(32));
        stepAt(*toy, events);
    }
    counting = false;
    toy->player().finish();
    EXPECT_EQ(allocations.load(), 0) << "heap allocations in 20 frames";
}

}  // namespace
}  // namespace toyhost::testing
