// EmptyArguments: an empty argument on the command line (`--size ""`, `run ""`, `--out=`) is
// never meant (a shell variable that was not set, a quoting slip); CLI11 drops some of them and
// prints others invisibly. Found before parsing, and said with the option or position it was in.
#pragma once

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace toyhost::cli {

// The usage message for the first empty argument in argv, or nothing.
std::optional<std::string> emptyArgumentProblem(CLI::App& app, int argc, char** argv);

}  // namespace toyhost::cli
