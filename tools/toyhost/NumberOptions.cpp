// CLI11 validators for numeric options (NumberOptions.h). No GL.
#include "NumberOptions.h"

#include <cstdint>
#include <string>

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

}  // namespace toyhost::cli
