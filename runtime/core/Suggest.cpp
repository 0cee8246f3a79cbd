#include "core/Suggest.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace toyhost {

namespace {
std::string folded(std::string_view text) {
    std::size_t begin = 0, end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    std::string out(text.substr(begin, end - begin));
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}
}  // namespace

std::size_t editDistance(std::string_view a, std::string_view b) {
    // Three rows of the dynamic programme: two before the current one for transpositions.
    std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::optional<std::string> closestMatch(std::string_view typed, std::span<const std::string> candidates) {
    const std::string key = folded(typed);
    std::optional<std::string> best;
    std::size_t bestDistance = 0;
    for (const std::string& candidate : candidates) {
        if (candidate == typed) continue;
        const std::string other = folded(candidate);
        // "Buffer E", "iChannel4", "Abstract 9": another index, not a typo of the listed ones.
        if (key.size() == other.size() && !key.empty() && key.back() != other.back() &&
            key.compare(0, key.size() - 1, other, 0, other.size() - 1) == 0)
            continue;
        const std::size_t distance = editDistance(key, other);
        const std::size_t allowed = std::clamp<std::size_t>(other.size() / 3, 1, 3);
        if (distance > allowed) continue;
        if (!best || distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

std::string didYouMean(std::string_view typed, std::span<const std::string> candidates) {
    std::optional<std::string> match = closestMatch(typed, candidates);
    return match ? " (did you mean \"" + *match + "\"?)" : std::string();
}

}  // namespace toyhost
