// Failure paths of the capture pipeline's plumbing: a failed rename says why, a folder is not read
// as an empty file, a folder in PATH is not taken for a program, the synchronous encoder path
// turns a closed pipe into an error instead of a fatal SIGPIPE. No GL needed.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <pthread.h>
#include <system_error>
#include <unistd.h>

#include "TestFolder.h"
#include "capture/EncoderPool.h"
#include "capture/FileSinks.h"
#include "core/AtomicFile.h"
#include "core/ChildProcess.h"
#include "core/FileDescriptor.h"

using namespace toyhost;
using toyhost::testing::TestFolder;
namespace fs = std::filesystem;

namespace {

class PipeSink final : public FrameSink {
public:
    explicit PipeSink(int fd) : fd_(fd) {}
    bool ordered() const override { return true; }
    Status write(const CapturedFrame& frame, EncodeScratch&) override {
        return writeAll(fd_, frame.pixels, "test pipe");
    }

private:
    int fd_;
};

}  // namespace

TEST(AtomicFile, AFailedRenameSaysWhyAndLeavesNoTemporaryFile) {
    TestFolder folder;
    const fs::path target = folder.path / "frame.png";
    folder.write("frame.png/occupied", "x");  // a non-empty folder where the file should go
    Status written = writeBytesAtomically(target, std::as_bytes(std::span("data", 4)));
    ASSERT_FALSE(written.ok());
    const std::string& message = written.error().text();
    EXPECT_NE(message.find(target.string()), std::string::npos) << message;
    EXPECT_NE(message.find(std::make_error_code(std::errc::is_a_directory).message()), std::string::npos) << message;
    EXPECT_EQ(message.find("Success"), std::string::npos) << message;
    EXPECT_EQ(folder.files(), (std::vector<std::string>{"occupied"}));
}

// An image sequence makes its folder for the first frame; a folder that then vanishes is an error
// for the next frame, not made again to hold only the later frames (the CLI's run of it:
// Adversarial.AnOutputFolderThatVanishesIsAnErrorWithNothingLeft).
TEST(ImageSequenceSink, MakesItsFolderOnceAndAVanishedFolderIsAnError) {
    TestFolder folder;
    const fs::path out = folder.path / "deep/out";
    Result<OutputPattern> pattern = OutputPattern::parse((out / "f_%02d.png").string());
    ASSERT_TRUE(pattern.ok());
    ImageSequenceSink sink(*pattern, 1);
    EncodeScratch scratch;
    CapturedFrame frame;
    frame.width = frame.height = 2;
    frame.pixels.assign(2 * 2 * 4, std::byte{200});
    ASSERT_TRUE(sink.write(frame, scratch).ok());
    EXPECT_TRUE(fs::is_regular_file(out / "f_00.png"));
    fs::rename(out, folder.path / "moved");
    frame.frame = 1;
    Status second = sink.write(frame, scratch);
    ASSERT_FALSE(second.ok());
    EXPECT_NE(second.error().text().find((out / "f_01.png").string()), std::string::npos) << second.error().text();
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(fs::is_regular_file(folder.path / "moved/f_00.png"));
}

TEST(AtomicFile, ReadingAFolderIsAnErrorNamingIt) {
    TestFolder folder;
    Result<std::string> text = readTextFile(folder.path);
    ASSERT_FALSE(text.ok());
    EXPECT_NE(text.error().text().find(folder.path.string()), std::string::npos) << text.error().text();
    EXPECT_NE(text.error().text().find("folder"), std::string::npos) << text.error().text();
}

TEST(ChildProcess, AFolderInPathIsNotTakenForTheProgram) {
    TestFolder folder;
    fs::create_directories(folder.path / "first" / "toyhost-test-prog");  // searchable, not runnable
    const fs::path real = folder.write("second/toyhost-test-prog", "#!/bin/sh\nexit 0\n");
    fs::permissions(real, fs::perms::owner_all);
    const char* oldPath = std::getenv("PATH");
    const std::string saved = oldPath ? oldPath : "";
    const std::string path = (folder.path / "first").string() + ":" + (folder.path / "second").string();
    ::setenv("PATH", path.c_str(), 1);
    const std::optional<fs::path> found = findExecutable("toyhost-test-prog");
    ::setenv("PATH", saved.c_str(), 1);
    ASSERT_TRUE(found);
    EXPECT_EQ(*found, real);
    EXPECT_FALSE(findExecutable((folder.path / "first" / "toyhost-test-prog").string()));
}

TEST(EncoderPoolDeathTest, SynchronousWriteIntoAClosedPipeIsAnErrorNotSigpipe) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    // In a child process with SIGPIPE at its default action (fatal), as in a program that embeds
    // the library without ignoring it.
    EXPECT_EXIT(
        {
            std::signal(SIGPIPE, SIG_DFL);
            int ends[2];
            if (::pipe(ends) != 0) std::_Exit(3);
            ::close(ends[0]);
            PipeSink sink(ends[1]);
            EncoderPool pool(sink, /*threads=*/0, 1024);
            Result<std::vector<std::byte>> buffer = pool.acquire(16);
            if (!buffer) std::_Exit(4);
            Status submitted = pool.submit(CapturedFrame{0, 2, 2, PixelFormat::Rgba8, std::move(*buffer)});
            if (submitted.ok() || submitted.error().text().find("broken pipe") == std::string::npos) std::_Exit(5);
            // The caller's signal mask is as it was.
            sigset_t mask;
            pthread_sigmask(SIG_BLOCK, nullptr, &mask);
            std::_Exit(sigismember(&mask, SIGPIPE) ? 6 : 0);
        },
        ::testing::ExitedWithCode(0), "");
}

