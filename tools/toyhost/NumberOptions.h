// CLI11 validators for numeric options, checked as text before CLI11 converts them
// (core/NumberText.h): CLI11 alone reads 0x10 as 16, 010 as 8, '' as "not given" and wraps
// 4294967396 to 100. readNumbersAsDecimal puts them on every numeric option at once. No GL.
#pragma once

#include <CLI/CLI.hpp>

namespace toyhost::cli {

// A whole decimal number, handed on without leading zeros (use with ->transform: it rewrites).
CLI::Validator wholeNumberOption();
// A decimal number (fractions allowed).
CLI::Validator decimalNumberOption();
// Seconds for a watchdog limit: 0 (off) or within the accepted range.
CLI::Validator timeoutSecondsOption();

// Every numeric option of `app` and of its subcommands, found by the type CLI11 converts it to:
// whole numbers (INT, UINT) through wholeNumberOption, the others (FLOAT) through
// decimalNumberOption, each before the option's own checks. Called once, after every command is
// declared, so that no option is left out (--supersample 0x10 once was 16, --tile 0x40 64).
void readNumbersAsDecimal(CLI::App& app);

}  // namespace toyhost::cli
