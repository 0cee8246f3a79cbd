// CLI11 validators for numeric options, checked as text before CLI11 converts them
// (core/NumberText.h): CLI11 alone reads 0x10 as 16, 010 as 8 and '' as "not given". No GL.
#pragma once

#include <CLI/CLI.hpp>

namespace toyhost::cli {

// A whole decimal number, handed on without leading zeros (use with ->transform: it rewrites).
CLI::Validator wholeNumberOption();
// A decimal number (fractions allowed).
CLI::Validator decimalNumberOption();
// Seconds for a watchdog limit: 0 (off) or within the accepted range.
CLI::Validator timeoutSecondsOption();

}  // namespace toyhost::cli
