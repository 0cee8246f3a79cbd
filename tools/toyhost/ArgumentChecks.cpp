#include "ArgumentChecks.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <vector>

#include "core/Suggest.h"

namespace toyhost::cli {

std::optional<std::string> emptyArgumentProblem(CLI::App& app, int argc, char** argv) {
    CLI::App* command = nullptr;  // the subcommand, once its name has been seen
    std::string commandName;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const std::string where = commandName.empty() ? "toyhost" : "toyhost " + commandName;
        if (arg.rfind("--", 0) == 0 && arg.size() > 2 && arg.back() == '=')
            return arg.substr(0, arg.size() - 1) + ": the value after '=' is empty (an unset shell variable?)";
        if (!arg.empty()) {
            if (!command && arg[0] != '-') {
                for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
                    if (sub->check_name(arg)) command = sub, commandName = arg;
            }
            continue;
        }
        // The option before it, if it takes a value, is the one left without.
        const std::string previous = i > 1 ? argv[i - 1] : "";
        if (previous.size() > 1 && previous[0] == '-' && previous.find('=') == std::string::npos) {
            const CLI::Option* option = command ? command->get_option_no_throw(previous) : nullptr;
            if (!option) option = app.get_option_no_throw(previous);
            if (option && option->get_expected_max() > 0 && option->get_type_size_max() > 0)
                return previous + ": the value is empty (\"\"; an unset shell variable?)";
        }
        return where + ": argument " + std::to_string(i) +
               " is empty (\"\"): a path, an option or a value cannot be empty (an unset shell variable?)";
    }
    return std::nullopt;
}

std::optional<std::string> unknownCommandProblem(CLI::App& app, int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-' || argv[1][0] == '\0') return std::nullopt;  // options, or said above
    const std::string typed = argv[1];
    std::vector<std::string> known;
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        if (sub->check_name(typed)) return std::nullopt;
        known.push_back(sub->get_name());
    }
    std::string list;
    for (const std::string& name : known) list += (list.empty() ? "" : ", ") + name;
    std::error_code ec;
    if (std::filesystem::exists(typed, ec))  // `toyhost myshader/`: what was meant is plain
        return "unknown command \"" + typed + "\": to run that shadertoy, toyhost run " + typed + " (commands: " + list + ")";
    return "unknown command \"" + typed + "\"" + didYouMean(typed, known) + " (known: " + list + "; toyhost --help)";
}

}  // namespace toyhost::cli
