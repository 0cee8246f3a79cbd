// The library's render() (Session::render, Session::Rendering): the frames the CLI's
// --capture-every would take, equal to read() of each; a frame handed over before the later
// frames render; a stop from the callback or from another thread; and a session used from another
// thread than its own refused with a usage error that says so.
#include "GlTestSupport.h"

#include <thread>

#include <toyhost/Session.h>

namespace toyhost::testing {
namespace {

SessionSettings small() {
    SessionSettings settings;
    settings.width = 16;
    settings.height = 8;
    settings.date = "2026-01-01T00:00:00";
    return settings;
}

Result<Shadertoy> probe() { return Shadertoy::load(sourceDir() / "shadertoys/pingpong-probe"); }

TEST(LibraryRender, HandsOverTheCapturedFramesEachEqualToRead) {
    Result<Shadertoy> shadertoy = probe();
    ASSERT_TRUE(shadertoy.ok()) << shadertoy.error().text();
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> reference = Session::createHeadless(*shadertoy, small());
        Result<std::unique_ptr<Session>> rendering = Session::createHeadless(*shadertoy, small());
        ASSERT_TRUE(reference.ok() && rendering.ok());
        const std::size_t values = 16 * 8 * 4;
        std::vector<std::vector<std::uint8_t>> expected;
        std::vector<std::vector<float>> expectedBuffer;
        for (int f = 0; f < 10; ++f) {
            ASSERT_TRUE((*reference)->step().ok());
            expected.emplace_back(values);
            expectedBuffer.emplace_back(values);
            ASSERT_TRUE((*reference)->read("Image", expected.back()).ok());
            ASSERT_TRUE((*reference)->read("Buffer A", expectedBuffer.back()).ok());
        }
        std::vector<int> handed;
        Session::RenderRequest request;
        request.frames = 10;
        request.every = 4;
        Status done = (*rendering)->render(request, [&](const Session::RenderedFrame& frame) {
            handed.push_back(frame.frame);
            std::vector<std::uint8_t> pixels(values);
            EXPECT_TRUE(frame.read(pixels).ok());
            EXPECT_EQ(pixels, expected[static_cast<std::size_t>(frame.frame)]) << "frame " << frame.frame;
            std::vector<std::uint8_t> wrong(3);
            EXPECT_FALSE(frame.read(wrong).ok());
            return true;
        });
        ASSERT_TRUE(done.ok()) << done.error().text();
        EXPECT_EQ(handed, (std::vector<int>{0, 4, 8, 9})) << "0, every 4th, and the last";
        EXPECT_EQ((*rendering)->frame(), 10);

        // A buffer as floats, frames 10 and 11 (iFrame goes on).
        request = Session::RenderRequest{};
        request.frames = 2;
        request.pass = "Buffer A";
        std::vector<int> more;
        ASSERT_TRUE((*reference)->step().ok());
        ASSERT_TRUE((*reference)->step().ok());
        std::vector<float> last(values);
        ASSERT_TRUE((*reference)->read("Buffer A", last).ok());
        done = (*rendering)->render(request, [&](const Session::RenderedFrame& frame) {
            more.push_back(frame.frame);
            std::vector<float> floats(values);
            EXPECT_TRUE(frame.read(floats).ok());
            if (frame.frame == 11) EXPECT_EQ(floats, last);
            return true;
        });
        ASSERT_TRUE(done.ok()) << done.error().text();
        EXPECT_EQ(more, (std::vector<int>{10, 11}));

        request.pass = "Buffer C";
        EXPECT_FALSE((*rendering)->render(request, [](const Session::RenderedFrame&) { return true; }).ok());
        request.pass = "Image";
        request.every = 0;
        EXPECT_FALSE((*rendering)->render(request, [](const Session::RenderedFrame&) { return true; }).ok());
        EXPECT_EQ((*rendering)->frame(), 12) << "nothing rendered for a bad request";
    });
}

// render(301, every = 100) handed frame 0 over only once frame 100 was read: now it comes at the
// first frame boundary after its read completes.
TEST(LibraryRender, AFrameIsHandedOverBeforeTheNextCapturedOneRenders) {
    Result<Shadertoy> shadertoy = probe();
    ASSERT_TRUE(shadertoy.ok()) << shadertoy.error().text();
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*shadertoy, small());
        ASSERT_TRUE(session.ok());
        std::vector<std::pair<int, int>> handedAt;  // (frame, the session's next iFrame then)
        Session::RenderRequest request;
        request.frames = 301;
        request.every = 100;
        ASSERT_TRUE((*session)
                        ->render(request,
                                 [&](const Session::RenderedFrame& frame) {
                                     handedAt.emplace_back(frame.frame, (*session)->frame());
                                     return true;
                                 })
                        .ok());
        ASSERT_EQ(handedAt.size(), 4u);
        for (const auto& [frame, renderedThen] : handedAt)
            EXPECT_LT(renderedThen, frame + 100) << "frame " << frame << " waited for the next captured frame";
        EXPECT_LE(handedAt[0].second, 1 + Session::kRenderReadsInFlight) << "frame 0 was handed over late";
    });
}

TEST(LibraryRender, StopsWhenTheCallbackSaysOrWhenAskedFromAnotherThread) {
    Result<Shadertoy> shadertoy = probe();
    ASSERT_TRUE(shadertoy.ok()) << shadertoy.error().text();
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*shadertoy, small());
        ASSERT_TRUE(session.ok());
        Session::RenderRequest request;
        request.frames = 1000;
        int calls = 0;
        ASSERT_TRUE((*session)->render(request, [&](const Session::RenderedFrame&) { return ++calls < 3; }).ok());
        EXPECT_EQ(calls, 3) << "no frame handed over after the callback said stop";
        EXPECT_LE((*session)->frame(), 3 + Session::kRenderReadsInFlight + 1);

        // stop() from another thread, seen before the next frame.
        const int before = (*session)->frame();
        request.every = 1000;  // nothing handed over after frame 0: only stop() ends it
        Result<std::unique_ptr<Session::Rendering>> rendering = (*session)->startRendering(request);
        ASSERT_TRUE(rendering.ok());
        auto ignore = [](const Session::RenderedFrame&) { return true; };
        for (int i = 0; i < 5; ++i) ASSERT_TRUE(*(*rendering)->advance(ignore));
        std::thread([&] { (*rendering)->stop(); }).join();
        Result<bool> more = (*rendering)->advance(ignore);
        ASSERT_TRUE(more.ok());
        EXPECT_FALSE(*more);
        EXPECT_EQ((*session)->frame(), before + 5) << "no frame rendered after stop()";
        EXPECT_EQ((*rendering)->readsInFlight(), 0) << "reads dropped";
        rendering = Error("done", Code::Internal);
        ASSERT_TRUE((*session)->step().ok()) << "the session goes on";
    });
}

TEST(LibraryRender, ASessionUsedOffItsThreadIsAUsageErrorThatSaysSo) {
    Result<Shadertoy> shadertoy = probe();
    ASSERT_TRUE(shadertoy.ok()) << shadertoy.error().text();
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> made = Session::createHeadless(*shadertoy, small());
        ASSERT_TRUE(made.ok());
        Session& session = **made;
        ASSERT_TRUE(session.step().ok());
        std::vector<Status> answers;
        std::vector<std::uint8_t> pixels(16 * 8 * 4);
        std::thread([&] {
            answers.push_back(session.step());
            answers.push_back(session.read("Image", pixels));
            answers.push_back(session.resize(8, 8));
            Result<std::unique_ptr<Session::Rendering>> rendering = session.startRendering({});
            answers.push_back(rendering ? okStatus() : Status(rendering.error()));
            Result<std::vector<float>> sound = session.renderSound(0.1);
            answers.push_back(sound ? okStatus() : Status(sound.error()));
            session.restart();  // does nothing there
        }).join();
        for (const Status& answer : answers) {
            ASSERT_FALSE(answer.ok());
            EXPECT_EQ(answer.error().first().code, Code::Usage);
            EXPECT_NE(answer.error().text().find("a session is used on the thread that created it"), std::string::npos)
                << answer.error().text();
        }
        EXPECT_NE(answers[0].error().text().find("step()"), std::string::npos) << "names the call";
        EXPECT_EQ(session.frame(), 1) << "nothing was done off the session's thread";
        EXPECT_EQ(session.width(), 16);
        ASSERT_TRUE(session.step().ok()) << "on its own thread the session goes on";
        EXPECT_EQ(session.frame(), 2);
    });
}

}  // namespace
}  // namespace toyhost::testing
