// `toyhost new` and `toyhost import` end with the command that runs what they wrote, and that
// command works as printed, from where the user is: `toyhost` only when that name on $PATH is this
// very program, else the program's path (relative below the working directory, e.g.
// build/tools/toyhost), and without a display an --out, since a headless run without --out writes
// nothing. Each case runs the printed command in a shell and checks the frame it wrote.
#include "GlTestSupport.h"

#include <sys/stat.h>

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

// Runs `command` with sh in `dir`, with exactly `path` as $PATH and DISPLAY set to `display` (or
// unset when empty).
CommandResult shellIn(const fs::path& dir, const std::string& path, const std::string& display, const std::string& command) {
    const std::string line = "cd '" + dir.string() + "' && env -u DISPLAY -u WAYLAND_DISPLAY PATH='" + path + "'" +
                             (display.empty() ? "" : " DISPLAY=" + display) + " sh -c \"$TOYHOST_NEXT\" 2>&1";
    ::setenv("TOYHOST_NEXT", command.c_str(), 1);
    CommandResult result;
    FILE* pipe = popen(line.c_str(), "r");
    if (!pipe) return result;
    char chunk[4096];
    std::size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, pipe)) > 0) result.output.append(chunk, n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// The command after "toyhost: run it with: ", or "" when there is none.
std::string suggested(const std::string& output) {
    const std::string marker = "toyhost: run it with: ";
    const std::size_t at = output.find(marker);
    if (at == std::string::npos) return "";
    const std::size_t start = at + marker.size();
    return output.substr(start, output.find('\n', start) - start);
}

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

const std::string kSystemPath = "/usr/local/bin:/usr/bin:/bin";

class NextCommand : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = freshOutputDir(std::string("next-command/") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    // Runs what `made` suggests, in dir_, and checks that it wrote `frame` there.
    void runSuggestion(const CommandResult& made, const std::string& expected, const std::string& frame,
                       const std::string& path = kSystemPath) {
        ASSERT_EQ(made.exitCode, 0) << made.output;
        const std::string command = suggested(made.output);
        EXPECT_EQ(command, expected) << made.output;
        const CommandResult ran = shellIn(dir_, path, "", command);
        EXPECT_EQ(ran.exitCode, 0) << command << "\n" << ran.output;
        EXPECT_TRUE(fs::is_regular_file(dir_ / frame)) << command << "\n" << ran.output;
    }
    fs::path dir_;
};

// Not on $PATH (a build tree): the program's own path, and an --out that writes the frame.
TEST_F(NextCommand, NewNamesTheProgramsPathWhenToyhostIsNotOnPath) {
    const fs::path self = fs::canonical(toyhostBinary());
    const CommandResult made = shellIn(dir_, kSystemPath, "", quoted(self) + " new my-port");
    runSuggestion(made, self.string() + " run my-port --out my-port.png", "my-port.png");
}

// The same for an import, from a real export's shape (one Image pass).
TEST_F(NextCommand, ImportSaysHowToRunTheFolderItWrote) {
    writeFile(dir_ / "export.json",
              R"({"Shader": {"info": {"id": "x", "name": "toy"}, "renderpass": [{"inputs": [], "outputs": [{"id": 37, "channel": 0}],)"
              R"( "type": "image", "name": "Image", "code": "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5); }\n"}]}})");
    const fs::path self = fs::canonical(toyhostBinary());
    const CommandResult made = shellIn(dir_, kSystemPath, "", quoted(self) + " import export.json ported/");
    runSuggestion(made, self.string() + " run ported/ --out ported.png", "ported.png");
}

// `toyhost` on $PATH is this program (a symbolic link to it counts): the short name.
TEST_F(NextCommand, ToyhostOnPathIsUsedWhenItIsThisProgram) {
    fs::create_directories(dir_ / "bin");
    fs::create_symlink(fs::canonical(toyhostBinary()), dir_ / "bin/toyhost");
    const std::string path = (dir_ / "bin").string() + ":" + kSystemPath;
    const CommandResult made = shellIn(dir_, path, "", "toyhost new 'my port'");
    runSuggestion(made, "toyhost run 'my port' --out 'my port.png'", "my port.png", path);
}

// Another program called toyhost on $PATH (an older install): not the one that wrote the folder.
TEST_F(NextCommand, AnotherToyhostOnPathIsNotSuggested) {
    fs::create_directories(dir_ / "bin");
    writeFile(dir_ / "bin/toyhost", "#!/bin/sh\necho 'an older toyhost'\nexit 3\n");
    fs::permissions(dir_ / "bin/toyhost", fs::perms::owner_all);
    const fs::path self = fs::canonical(toyhostBinary());
    const std::string path = (dir_ / "bin").string() + ":" + kSystemPath;
    const CommandResult made = shellIn(dir_, path, "", quoted(self) + " new mine");
    runSuggestion(made, self.string() + " run mine --out mine.png", "mine.png", path);
}

// The program below the working directory (the README's build/tools/toyhost): a relative path.
TEST_F(NextCommand, AProgramBelowTheWorkingDirectoryIsNamedRelatively) {
    fs::create_directories(dir_ / "build/tools");
    fs::copy_file(toyhostBinary(), dir_ / "build/tools/toyhost");
    fs::permissions(dir_ / "build/tools/toyhost", fs::perms::owner_all);
    const CommandResult made = shellIn(dir_, kSystemPath, "", "build/tools/toyhost new fresh");
    runSuggestion(made, "build/tools/toyhost run fresh --out fresh.png", "fresh.png");
}

// With a display the run opens a window: no --out needed (the command is not run here: window
// mode has its own tests).
TEST_F(NextCommand, WithADisplayTheCommandOpensAWindow) {
    const fs::path self = fs::canonical(toyhostBinary());
    const CommandResult made = shellIn(dir_, kSystemPath, ":99", quoted(self) + " new shown");
    ASSERT_EQ(made.exitCode, 0) << made.output;
    EXPECT_EQ(suggested(made.output), self.string() + " run shown") << made.output;
}

}  // namespace
}  // namespace toyhost::testing
