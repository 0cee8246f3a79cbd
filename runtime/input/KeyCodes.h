// Key names -> JavaScript keyCode, the index of the keyboard texture (KeyboardState). Used by key
// scripts and the CLI. Pure logic, no GL context needed.
#pragma once

#include <string_view>

#include "core/Result.h"

namespace toyhost {

// Accepted, case-insensitive:
//   "A".."Z" (65..90), "0".."9" (48..57: the digit keys, not key codes 0..9),
//   "space" 32, "enter"/"return" 13, "escape"/"esc" 27, "tab" 9, "backspace" 8,
//   "shift" 16, "ctrl"/"control" 17, "alt" 18, "pause" 19, "capslock" 20,
//   "pageup" 33, "pagedown" 34, "end" 35, "home" 36,
//   "left" 37, "up" 38, "right" 39, "down" 40 (also "arrowleft" ... "arrowdown"),
//   "insert" 45, "delete" 46, "meta" 91, "numpad0".."numpad9" 96..105, "f1".."f12" 112..123,
//   "semicolon" 186, "equal" 187, "comma" 188, "minus" 189, "period" 190, "slash" 191,
//   "backquote" 192, "bracketleft" 219, "backslash" 220, "bracketright" 221, "quote" 222;
//   and a key code written as a number of two or three digits, "10".."255".
// Errors: `unknown key "spacebar"`, `key code 300 is out of range 0..255`.
Result<int> keyCodeFromName(std::string_view name);

}  // namespace toyhost
