// Suggest: "did you mean ...?" for near misses in what a user typed (a JSON key, a pass name, a
// stock media id). Pure text logic, no GL needed.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace toyhost {

// Edit distance with adjacent transpositions (optimal string alignment), case-sensitive.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate `typed` most likely meant, or nothing when none is close: equal after trimming
// spaces and ignoring case ("Image " -> "Image", "image" -> "Image"), or within an edit distance
// of about a third of the candidate's length (at least 1, at most 3; case ignored). `typed` itself
// is never suggested, nor a candidate that differs only in its last character ("Buffer E" is
// another index, not a typo of "Buffer A"). Ties go to the first candidate.
std::optional<std::string> closestMatch(std::string_view typed, std::span<const std::string> candidates);

// " (did you mean \"X\"?)" for closestMatch's answer, or "" when there is none.
std::string didYouMean(std::string_view typed, std::span<const std::string> candidates);

}  // namespace toyhost
