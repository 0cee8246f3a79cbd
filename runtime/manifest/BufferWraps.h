// BufferWraps: the site's buffer wrap quirk as manifest data. The site sets a buffer's (or Cube
// A's) wrap on its textures whenever a channel reading it is created, so the last created reader
// decides the wrap every reader samples with. Pure data logic, no GL needed.
#pragma once

#include <array>
#include <optional>

#include "manifest/ManifestDesc.h"

namespace toyhost {

// Index kBufferCount: Cube A.
using BufferWraps = std::array<std::optional<Wrap>, kBufferCount + 1>;

// The wrap each buffer and Cube A ends up with (none where nothing reads it): channels are created
// in an export's listed order (passes as listed, each pass's inputs as listed, PassDesc/ChannelDesc
// listedAt), and in a manifest in render order and channel order.
BufferWraps siteBufferWraps(const ManifestDesc& manifest);

// The wrap `channel` samples with: the buffer's or Cube A's from `wraps`, its own for other kinds.
Wrap wrapSampled(const BufferWraps& wraps, const ChannelDesc& channel);

}  // namespace toyhost
