// SourceText: the bytes of a pass that GL must not see as they are. A UTF-8 byte order mark at the
// start is removed (editors add it; GL reads it as garbage); a NUL byte is an error (GL stops
// reading the source there, silently); a non-ASCII character outside a comment is an error naming
// it (GL reports only "unexpected end of file"). Non-ASCII in comments stays: it works on the site.
// Pure text logic, no GL needed.
#pragma once

#include <string>
#include <vector>

#include "core/Diagnostic.h"

namespace toyhost {

// Cleans `code` in place; problems go to `problems` with `file`, `pass` and line:column.
void checkShaderText(std::string& code, const std::string& file, const std::string& pass,
                     std::vector<Diagnostic>& problems);

}  // namespace toyhost
