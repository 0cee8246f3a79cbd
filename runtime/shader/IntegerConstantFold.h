// IntegerConstantFold: the browsers' values for the integer constant operations GLSL ES leaves
// undefined. ANGLE folds every operation on constants in its front end, for every backend, and
// gives these a value of its own; Mesa folds them differently. Pure text work over
// shader/GlslTokens; no GL needed.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "shader/GlslTokens.h"

namespace toyhost {

struct ConstantFoldEdit {
    std::size_t offset = 0;  // into the tokenized text
    std::size_t erase = 0;   // bytes replaced
    std::string text;        // ANGLE's value, with the replaced span's newlines after it
};

// The edits in text order, each one nested in another dropped (it starts first, or at the same
// token and ends later: the outer one's value already has the inner one's). For the folders.
std::vector<ConstantFoldEdit> outermostEdits(std::vector<ConstantFoldEdit> edits);

// How many times each name is declared (`TYPE NAME`, also after a comma in the same statement): a
// name declared `const` once and never again is a constant the folders may read (it cannot be
// shadowed). For the constant folders of shader/.
std::map<std::string_view, int> countDeclarations(const std::vector<GlslToken>& tokens);

// For each scalar `int`/`uint` operation `a / b`, `a % b`, `a << b`, `a >> b` outside directives
// whose two operands this module can evaluate (literals, `int(...)`/`uint(...)` of them,
// parentheses, unary `- + ~`, `* / % + - << >> & ^ |`, and names declared `const int`/`const
// uint` once in the text), when ANGLE's folder gives it a value of its own:
//   - division or remainder by 0: INT_MAX (int), UINT_MAX (uint);
//   - INT_MIN / -1: INT_MAX;
//   - `%` with a negative int operand: 0;
//   - a shift by less than 0 or more than 31: 0;
// an edit that writes that value in place of the whole operation. Other operations are left to
// the driver, which folds them as ANGLE does. Vectors, macros and non-constant operands are left
// as they are (a browser does not fold a non-constant operand either). An edit nested in another
// is dropped: the outer one's value already has the inner one's.
std::vector<ConstantFoldEdit> foldUndefinedIntegerConstants(const std::vector<GlslToken>& tokens);

}  // namespace toyhost
