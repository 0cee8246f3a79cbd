#include "image/HuffmanCode.h"

#include <algorithm>
#include <array>
#include <vector>

namespace toyhost {
namespace {
// Depths of the leaves of a Huffman tree over `weights` (ascending), by the two-queue method:
// leaves and merged nodes each come out in ascending weight, so no heap is needed.
void treeDepths(const std::vector<std::uint64_t>& weights, std::vector<int>& depth) {
    const std::size_t n = weights.size();
    std::vector<std::uint64_t> merged(n - 1);
    std::vector<int> parent(2 * n - 1, -1);  // leaves 0..n-1, merged nodes n..2n-2
    std::size_t leaf = 0, inner = 0;
    auto takeSmallest = [&](std::size_t made) -> std::size_t {
        if (leaf < n && (inner >= made || weights[leaf] <= merged[inner])) return leaf++;
        return n + inner++;
    };
    auto weightOf = [&](std::size_t node) { return node < n ? weights[node] : merged[node - n]; };
    for (std::size_t made = 0; made + 1 < n; ++made) {
        const std::size_t a = takeSmallest(made), b = takeSmallest(made);
        merged[made] = weightOf(a) + weightOf(b);
        parent[a] = parent[b] = static_cast<int>(n + made);
    }
    std::vector<int> nodeDepth(2 * n - 1, 0);
    for (std::size_t node = 2 * n - 2; node-- > 0;)
        nodeDepth[node] = nodeDepth[static_cast<std::size_t>(parent[node])] + 1;
    depth.assign(nodeDepth.begin(), nodeDepth.begin() + static_cast<std::ptrdiff_t>(n));
}
}  // namespace

void huffmanLengths(std::span<const std::uint32_t> freq, int maxLength, std::span<std::uint8_t> lengths) {
    std::fill(lengths.begin(), lengths.end(), std::uint8_t{0});
    std::vector<std::size_t> used;
    for (std::size_t s = 0; s < freq.size(); ++s)
        if (freq[s]) used.push_back(s);
    if (used.empty()) return;
    if (used.size() == 1) {
        lengths[used[0]] = 1;
        return;
    }
    std::vector<std::uint64_t> weight(freq.size());
    for (std::size_t s : used) weight[s] = freq[s];
    std::vector<std::uint64_t> sortedWeights(used.size());
    std::vector<int> depth;
    for (;;) {
        std::stable_sort(used.begin(), used.end(), [&](std::size_t a, std::size_t b) { return weight[a] < weight[b]; });
        for (std::size_t i = 0; i < used.size(); ++i) sortedWeights[i] = weight[used[i]];
        treeDepths(sortedWeights, depth);
        if (*std::max_element(depth.begin(), depth.end()) <= maxLength) break;
        // Too deep: flatten the distribution and build again. Halving converges to equal weights,
        // a balanced tree of depth ceil(log2(symbols)), which every caller's limit allows.
        for (std::size_t s : used) weight[s] = std::max<std::uint64_t>(1, weight[s] >> 1);
    }
    for (std::size_t i = 0; i < used.size(); ++i) lengths[used[i]] = static_cast<std::uint8_t>(depth[i]);
}

void canonicalCodes(std::span<const std::uint8_t> lengths, std::span<std::uint16_t> codes) {
    std::array<std::uint16_t, 16> count{};
    for (std::uint8_t l : lengths) ++count[l];
    count[0] = 0;
    std::array<std::uint16_t, 16> next{};
    std::uint32_t code = 0;
    for (int bits = 1; bits < 16; ++bits) {
        code = (code + count[static_cast<std::size_t>(bits - 1)]) << 1;
        next[static_cast<std::size_t>(bits)] = static_cast<std::uint16_t>(code);
    }
    for (std::size_t s = 0; s < lengths.size(); ++s) {
        const int l = lengths[s];
        if (!l) {
            codes[s] = 0;
            continue;
        }
        std::uint32_t c = next[static_cast<std::size_t>(l)]++, reversed = 0;
        for (int b = 0; b < l; ++b, c >>= 1) reversed = (reversed << 1) | (c & 1);
        codes[s] = static_cast<std::uint16_t>(reversed);
    }
}

}  // namespace toyhost
