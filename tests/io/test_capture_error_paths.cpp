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

