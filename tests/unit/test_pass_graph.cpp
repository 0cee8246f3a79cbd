// PassGraph: which output (this frame's or the previous frame's) every buffer channel sees, which
// buffers need mipmaps, and the ping-pong slot arithmetic, from hand-built ManifestDesc values.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "graph/PassGraph.h"

using namespace toyhost;

namespace {

const PassId kAllPasses[] = {PassId::BufferA, PassId::BufferB, PassId::BufferC, PassId::BufferD, PassId::Image};

ChannelDesc bufferChannel(int buffer, Filter filter = Filter::Linear) {
    ChannelDesc c;
    c.kind = ChannelKind::Buffer;
    c.buffer = buffer;
    c.sampler = defaultSampler(ChannelKind::Buffer);
    c.sampler.filter = filter;
    return c;
}

ChannelDesc textureChannel(Filter filter) {
    ChannelDesc c;
    c.kind = ChannelKind::ImageFile;
    c.file = "/tmp/tex.png";
    c.sampler = defaultSampler(ChannelKind::ImageFile);
    c.sampler.filter = filter;
    return c;
}

// A manifest with the buffers whose bit is set in `bufferMask` (bit 0 = A), plus Image, in render
// order; channels empty.
ManifestDesc manifestWith(unsigned bufferMask) {
    ManifestDesc m;
    m.name = "hand-built";
    for (int b = 0; b < kBufferCount; ++b)
        if (bufferMask & (1u << b)) m.passes.push_back(PassDesc{bufferPass(b), {}, {}, {}});
    m.passes.push_back(PassDesc{PassId::Image, {}, {}, {}});
    return m;
}

PassDesc& pass(ManifestDesc& m, PassId id) {
    for (PassDesc& p : m.passes)
        if (p.id == id) return p;
    ADD_FAILURE() << passName(id) << " not in the manifest";
    return m.passes.back();
}

const PassPlan* plan(const PassGraph& g, PassId id) {
    for (const PassPlan& p : g.passes)
        if (p.id == id) return &p;
    return nullptr;
}

std::string describe(PassId reader, int buffer) {
    return std::string(passName(reader)) + " reading " + passName(bufferPass(buffer));
}

const char* ageName(FrameAge a) { return a == FrameAge::Current ? "Current" : "Previous"; }

}  // namespace

// Every (reader, buffer) pair, for every subset of buffers present: the age is Current iff the
// buffer runs earlier in the frame than the reader; reading itself is Previous.
TEST(PassGraph, AgeIsCurrentExactlyWhenTheBufferRunsEarlier) {
    int checked = 0;
    for (unsigned mask = 0; mask < 16; ++mask) {
        ManifestDesc m = manifestWith(mask);
        // Every pass reads every present buffer: iChannel<b> reads buffer b.
        for (PassDesc& p : m.passes)
            for (int b = 0; b < kBufferCount; ++b)
                if (mask & (1u << b)) p.channels[b] = bufferChannel(b);
        const PassGraph g = buildPassGraph(m);
        ASSERT_EQ(g.passes.size(), m.passes.size());
        for (const PassPlan& reader : g.passes) {
            for (int b = 0; b < kBufferCount; ++b) {
                const ChannelPlan& ch = reader.channels[b];
                if (!(mask & (1u << b))) {
                    EXPECT_EQ(ch.kind, ChannelKind::None);
                    continue;
                }
                const bool runsEarlier = static_cast<int>(bufferPass(b)) < static_cast<int>(reader.id);
                const FrameAge expected = runsEarlier ? FrameAge::Current : FrameAge::Previous;
                EXPECT_EQ(ch.kind, ChannelKind::Buffer);
                EXPECT_EQ(ch.buffer, b);
                EXPECT_EQ(ch.age, expected) << describe(reader.id, b) << " (buffer mask " << mask
                                            << "): got " << ageName(ch.age);
                if (reader.id == bufferPass(b)) {
                    EXPECT_EQ(ch.age, FrameAge::Previous) << "self-read";
                }
                ++checked;
            }
        }
    }
    // sum over masks of popcount(mask) * (popcount(mask) + 1) readings
    EXPECT_EQ(checked, 4 * 2 + 6 * 6 + 4 * 12 + 1 * 20);
}

// The exact 5x4 table with all buffers present.
TEST(PassGraph, AllBuffersPresentAgeTable) {
    ManifestDesc m = manifestWith(0xF);
    for (PassDesc& p : m.passes)
        for (int b = 0; b < kBufferCount; ++b) p.channels[b] = bufferChannel(b);
    const PassGraph g = buildPassGraph(m);
    const FrameAge C = FrameAge::Current, P = FrameAge::Previous;
    //                       reads A  B  C  D
    const FrameAge table[5][4] = {{P, P, P, P},   // Buffer A
                                  {C, P, P, P},   // Buffer B
                                  {C, C, P, P},   // Buffer C
                                  {C, C, C, P},   // Buffer D
                                  {C, C, C, C}};  // Image
    ASSERT_EQ(g.passes.size(), 5u);
    for (int r = 0; r < 5; ++r) {
        EXPECT_EQ(g.passes[r].id, kAllPasses[r]);
        for (int b = 0; b < 4; ++b)
            EXPECT_EQ(g.passes[r].channels[b].age, table[r][b]) << describe(kAllPasses[r], b);
    }
}

TEST(PassGraph, ExecutionOrderTargetsAndAbsentBuffers) {
    const ManifestDesc m = manifestWith(0b1010);  // Buffer B and Buffer D
    const PassGraph g = buildPassGraph(m);
    ASSERT_EQ(g.passes.size(), 3u);
    EXPECT_EQ(g.passes[0].id, PassId::BufferB);
    EXPECT_EQ(g.passes[0].targetBuffer, 1);
    EXPECT_EQ(g.passes[1].id, PassId::BufferD);
    EXPECT_EQ(g.passes[1].targetBuffer, 3);
    EXPECT_EQ(g.passes[2].id, PassId::Image);
    EXPECT_EQ(g.passes[2].targetBuffer, -1);
    EXPECT_EQ(g.bufferUsed, (std::array<bool, 4>{false, true, false, true}));
    EXPECT_EQ(g.bufferMipmapped, (std::array<bool, 4>{false, false, false, false}));

    const PassGraph imageOnly = buildPassGraph(manifestWith(0));
    ASSERT_EQ(imageOnly.passes.size(), 1u);
    EXPECT_EQ(imageOnly.passes[0].id, PassId::Image);
    EXPECT_EQ(imageOnly.bufferUsed, (std::array<bool, 4>{false, false, false, false}));
    for (const ChannelPlan& c : imageOnly.passes[0].channels) {
        EXPECT_EQ(c.kind, ChannelKind::None);
        EXPECT_EQ(c.buffer, -1);
    }
}

TEST(PassGraph, NonBufferChannelsKeepKindAndSampler) {
    ManifestDesc m = manifestWith(0b0001);
    PassDesc& image = pass(m, PassId::Image);
    image.channels[0] = textureChannel(Filter::Nearest);
    image.channels[1].kind = ChannelKind::Keyboard;
    image.channels[1].sampler = defaultSampler(ChannelKind::Keyboard);
    image.channels[2].kind = ChannelKind::StockMedia;
    image.channels[2].media = "Abstract 3";
    image.channels[2].sampler = {Filter::Linear, Wrap::Repeat, false};
    image.channels[3] = bufferChannel(0, Filter::Nearest);
    image.channels[3].sampler.wrap = Wrap::Repeat;
    const PassGraph g = buildPassGraph(m);
    const PassPlan* p = plan(g, PassId::Image);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->channels[0].kind, ChannelKind::ImageFile);
    EXPECT_EQ(p->channels[0].buffer, -1);
    EXPECT_EQ(p->channels[0].sampler.filter, Filter::Nearest);
    EXPECT_EQ(p->channels[0].sampler.wrap, Wrap::Repeat);
    EXPECT_TRUE(p->channels[0].sampler.vflip);
    EXPECT_EQ(p->channels[1].kind, ChannelKind::Keyboard);
    EXPECT_EQ(p->channels[1].sampler.filter, Filter::Nearest);
    EXPECT_EQ(p->channels[2].kind, ChannelKind::StockMedia);
    EXPECT_EQ(p->channels[2].sampler.filter, Filter::Linear);
    EXPECT_EQ(p->channels[2].sampler.wrap, Wrap::Repeat);
    EXPECT_FALSE(p->channels[2].sampler.vflip);
    EXPECT_EQ(p->channels[3].kind, ChannelKind::Buffer);
    EXPECT_EQ(p->channels[3].buffer, 0);
    EXPECT_EQ(p->channels[3].sampler.filter, Filter::Nearest);
    EXPECT_EQ(p->channels[3].sampler.wrap, Wrap::Repeat);
}

TEST(PassGraph, BufferMipmappedOnlyWhenSomeChannelSamplesItWithMipmap) {
    for (int target = 0; target < kBufferCount; ++target) {
        ManifestDesc m = manifestWith(0xF);
        // Every buffer is read with nearest and linear somewhere, and textures use mipmap: none of
        // that makes a buffer mipmapped.
        for (int b = 0; b < kBufferCount; ++b) {
            pass(m, PassId::Image).channels[b] = bufferChannel(b, Filter::Linear);
            pass(m, bufferPass(b)).channels[0] = bufferChannel(b, Filter::Nearest);
            pass(m, bufferPass(b)).channels[1] = textureChannel(Filter::Mipmap);
        }
        // Only `target` is read with mipmap, by one channel of a pass other than the Image.
        const PassId reader = bufferPass((target + 1) % kBufferCount);
        pass(m, reader).channels[2] = bufferChannel(target, Filter::Mipmap);
        const PassGraph g = buildPassGraph(m);
        for (int b = 0; b < kBufferCount; ++b)
            EXPECT_EQ(g.bufferMipmapped[b], b == target) << "mipmap read of " << passName(bufferPass(target))
                                                         << ", checking " << passName(bufferPass(b));
        EXPECT_EQ(g.bufferUsed, (std::array<bool, 4>{true, true, true, true}));
    }
    // A self-read with mipmap counts too.
    ManifestDesc self = manifestWith(0b0100);
    pass(self, PassId::BufferC).channels[3] = bufferChannel(2, Filter::Mipmap);
    EXPECT_EQ(buildPassGraph(self).bufferMipmapped, (std::array<bool, 4>{false, false, true, false}));
}

TEST(PassGraph, SlotArithmeticOverFrames) {
    // Frame n writes slot n % 2; consecutive frames alternate.
    const int written[] = {0, 1, 0, 1};
    for (int frame = 0; frame < 4; ++frame) {
        EXPECT_EQ(slotWritten(frame), written[frame]) << "frame " << frame;
        // A Current read sees the slot written this frame.
        EXPECT_EQ(slotRead(FrameAge::Current, frame), slotWritten(frame)) << "frame " << frame;
        // A Previous read sees the other slot: the one written last frame.
        EXPECT_NE(slotRead(FrameAge::Previous, frame), slotWritten(frame)) << "frame " << frame;
        if (frame > 0) {
            EXPECT_EQ(slotRead(FrameAge::Previous, frame), slotWritten(frame - 1)) << "frame " << frame;
            EXPECT_NE(slotWritten(frame), slotWritten(frame - 1)) << "frame " << frame;
        }
    }
    // Frame 0's previous read is the slot nothing wrote yet: slot 1, cleared at start.
    EXPECT_EQ(slotRead(FrameAge::Previous, 0), 1);
    EXPECT_EQ(slotRead(FrameAge::Current, 0), 0);
    EXPECT_EQ(slotRead(FrameAge::Previous, 1), 0);
    EXPECT_EQ(slotRead(FrameAge::Current, 1), 1);
    EXPECT_EQ(slotRead(FrameAge::Previous, 2), 1);
    EXPECT_EQ(slotRead(FrameAge::Current, 3), 1);
}

// Replays Shadertoy's rule literally (each buffer samples its "last rendered" texture; a pass
// renders into the other one) and checks that the graph's age plus slotRead name the same slot,
// for every reader/buffer pair over frames 0..3.
TEST(PassGraph, AgesAndSlotsMatchALiteralPingPongReplay) {
    ManifestDesc m = manifestWith(0xF);
    for (PassDesc& p : m.passes)
        for (int b = 0; b < kBufferCount; ++b) p.channels[b] = bufferChannel(b);
    const PassGraph g = buildPassGraph(m);
    std::array<int, kBufferCount> lastRendered;
    lastRendered.fill(1);  // before frame 0, "last rendered" is the cleared slot that frame 0 does not write
    for (int frame = 0; frame < 4; ++frame) {
        for (const PassPlan& p : g.passes) {
            for (int c = 0; c < kChannelCount; ++c) {
                const ChannelPlan& ch = p.channels[c];
                EXPECT_EQ(slotRead(ch.age, frame), lastRendered[ch.buffer])
                    << describe(p.id, ch.buffer) << " at frame " << frame;
            }
            if (p.targetBuffer >= 0) {
                const int into = 1 - lastRendered[p.targetBuffer];
                EXPECT_EQ(slotWritten(frame), into) << passName(p.id) << " at frame " << frame;
                lastRendered[p.targetBuffer] = into;
            }
        }
    }
}

// Mountains & Lakes (7tSSDD), wired as in ../shared/shadertoys/README.md.
TEST(PassGraph, MountainsAndLakesWiring) {
    ManifestDesc m = manifestWith(0xF);
    auto wire = [&](PassId id, int ch0, int ch1) {
        pass(m, id).channels[0] = bufferChannel(ch0);
        if (ch1 >= 0) pass(m, id).channels[1] = bufferChannel(ch1);
    };
    wire(PassId::BufferA, 2, 3);
    wire(PassId::BufferB, 0, 3);
    wire(PassId::BufferC, 0, 1);
    wire(PassId::BufferD, 2, 1);
    wire(PassId::Image, 2, -1);
    ChannelDesc& abstract3 = pass(m, PassId::Image).channels[1];
    abstract3.kind = ChannelKind::StockMedia;
    abstract3.media = "/media/a/8979352a182bde7c3c651ba2b2f4e0615de819585cc37b7175bcefbca15a6683.jpg";
    abstract3.sampler = {Filter::Mipmap, Wrap::Repeat, true};

    const PassGraph g = buildPassGraph(m);
    const FrameAge C = FrameAge::Current, P = FrameAge::Previous;
    struct Row {
        PassId pass;
        FrameAge ch0, ch1;
    };
    // README: A reads C (previous), D (previous); B reads A (this), D (previous); C reads A (this),
    // B (this); D reads C (this), B (this); Image reads C (this).
    const Row rows[] = {{PassId::BufferA, P, P}, {PassId::BufferB, C, P}, {PassId::BufferC, C, C},
                        {PassId::BufferD, C, C}, {PassId::Image, C, C}};
    for (const Row& row : rows) {
        const PassPlan* p = plan(g, row.pass);
        ASSERT_NE(p, nullptr);
        EXPECT_EQ(p->channels[0].age, row.ch0) << passName(row.pass) << " iChannel0";
        if (row.pass != PassId::Image) {
            EXPECT_EQ(p->channels[1].age, row.ch1) << passName(row.pass) << " iChannel1";
        }
    }
    EXPECT_EQ(plan(g, PassId::Image)->channels[1].kind, ChannelKind::StockMedia);
    EXPECT_EQ(plan(g, PassId::Image)->channels[1].sampler.filter, Filter::Mipmap);
    // The Mipmap texture does not make any buffer mipmapped; buffers are read linear.
    EXPECT_EQ(g.bufferMipmapped, (std::array<bool, 4>{false, false, false, false}));
    EXPECT_EQ(g.bufferUsed, (std::array<bool, 4>{true, true, true, true}));

    // Frame 0: Buffer A reads C and D from the cleared slot 1; B, C, D and Image see slot 0.
    EXPECT_EQ(slotRead(plan(g, PassId::BufferA)->channels[0].age, 0), 1);
    EXPECT_EQ(slotRead(plan(g, PassId::BufferB)->channels[1].age, 0), 1);
    EXPECT_EQ(slotRead(plan(g, PassId::BufferC)->channels[0].age, 0), 0);
    EXPECT_EQ(slotRead(plan(g, PassId::Image)->channels[0].age, 0), 0);
}
