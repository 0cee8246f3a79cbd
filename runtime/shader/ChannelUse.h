// ChannelUse: which iChannelN a pass's own code names, found by scanning its text (comments and
// the preprocessor's view aside), so that a channel the code samples but the manifest leaves
// unbound can be reported before it silently reads black. Pure text logic, no GL needed.
#pragma once

#include <array>
#include <string_view>

#include "manifest/ManifestDesc.h"

namespace toyhost {

// True at N when `code` names iChannelN (or the Image pass's struct iChN) outside comments.
std::array<bool, kChannelCount> channelsNamed(std::string_view code);

// One warning per pass whose code names channels that nothing is bound to (they read as black on
// the site too, so this is a warning, not an error).
std::vector<Diagnostic> unboundChannelWarnings(const ManifestDesc& manifest);

}  // namespace toyhost
