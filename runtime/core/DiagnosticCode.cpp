#include "core/DiagnosticCode.h"

namespace toyhost {

std::string_view codeName(Code code) {
    switch (code) {
#define TOYHOST_CODE_TEXT(name, number, text, category) \
    case Code::name: return text;
        TOYHOST_DIAGNOSTIC_CODES(TOYHOST_CODE_TEXT)
#undef TOYHOST_CODE_TEXT
    }
    return "error";
}

Category categoryOf(Code code) {
    switch (code) {
#define TOYHOST_CODE_CATEGORY(name, number, text, category) \
    case Code::name: return Category::category;
        TOYHOST_DIAGNOSTIC_CODES(TOYHOST_CODE_CATEGORY)
#undef TOYHOST_CODE_CATEGORY
    }
    return Category::Internal;
}

std::string_view categoryName(Category category) {
    switch (category) {
        case Category::Usage: return "usage";
        case Category::Input: return "input";
        case Category::Shader: return "shader";
        case Category::Output: return "output";
        case Category::Gl: return "gl";
        case Category::Interrupted: return "interrupted";
        case Category::Watchdog: return "watchdog";
        case Category::Internal: return "internal";
        case Category::Report: return "report";
    }
    return "internal";
}

}  // namespace toyhost
