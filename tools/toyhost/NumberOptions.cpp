// CLI11 validators for numeric options (NumberOptions.h). No GL.
#include "NumberOptions.h"

#include <cstdint>
#include <string>
#include <string_view>

#include "core/NumberText.h"

namespace toyhost::cli {

CLI::Validator wholeNumberOption() {
    return CLI::Validator(
        [](std::string& text) {
            std::string problem = wholeNumberProblem(text, INT32_MIN, INT32_MAX);
            if (problem.empty()) text = std::to_string(*parseDecimalInteger(text));
            return problem;
        },
        "");
}

CLI::Validator decimalNumberOption() {
    return CLI::Validator([](std::string& text) { return decimalNumberProblem(text); }, "");
}

CLI::Validator timeoutSecondsOption() {
    return CLI::Validator([](std::string& text) { return timeoutSecondsProblem(text); }, "");
}

void readNumbersAsDecimal(CLI::App& app) {
    for (CLI::Option* option : app.get_options()) {
        // The type name CLI11 gives the option's value ("INT", "UINT", "FLOAT"), then ":" and the
        // descriptions of its validators.
        const std::string type = option->get_type_name();
        const auto is = [&](std::string_view name) {
            return type.compare(0, name.size(), name) == 0 && (type.size() == name.size() || type[name.size()] == ':');
        };
        // transform: first, before the option's own checks (CLI::Range converts the text as CLI11
        // does); a whole number is handed on rewritten without leading zeros.
        if (is("INT") || is("UINT")) option->transform(wholeNumberOption());
        else if (is("FLOAT")) option->transform(decimalNumberOption());
    }
    for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) readNumbersAsDecimal(*command);
}

}  // namespace toyhost::cli
