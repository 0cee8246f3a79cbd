// ArgumentChecks: what the command line holds that CLI11 would report badly, found before parsing.
// An empty argument (`--size ""`, `run ""`, `--out=`) is never meant (a shell variable that was not
// set, a quoting slip): CLI11 drops some and prints others invisibly; it is said with the option or
// position it was in. An unknown command (`toyhost farm`) is named, with the known ones, instead
// of CLI11's "A subcommand is required".
#pragma once

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace toyhost::cli {

// The usage message for the first empty argument in argv, or nothing.
std::optional<std::string> emptyArgumentProblem(CLI::App& app, int argc, char** argv);
// The usage message when the first argument that is not an option names no command, or nothing.
std::optional<std::string> unknownCommandProblem(CLI::App& app, int argc, char** argv);

}  // namespace toyhost::cli
