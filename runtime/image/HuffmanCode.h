// Length-limited canonical Huffman codes as deflate (RFC 1951, 3.2.2) defines them: code lengths
// from symbol frequencies, and the codes themselves bit-reversed for an LSB-first bit writer.
// CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <span>

namespace toyhost {

// Code lengths (0 = unused symbol) for `freq`, none longer than `maxLength` (<= 15). Symbols with
// frequency 0 get length 0. With two or more used symbols the code is complete (Kraft sum 1),
// which inflate requires of every deflate alphabet; a single used symbol gets length 1. The
// lengths are optimal when no limit is hit; otherwise the frequencies are flattened until it holds.
void huffmanLengths(std::span<const std::uint32_t> freq, int maxLength, std::span<std::uint8_t> lengths);

// Canonical codes for `lengths` (RFC 1951's construction), each reversed over its length so that
// an LSB-first bit writer sends it most significant bit first, as deflate wants.
void canonicalCodes(std::span<const std::uint8_t> lengths, std::span<std::uint16_t> codes);

}  // namespace toyhost
