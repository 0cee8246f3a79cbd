#include <toyhost/Version.h>

namespace toyhost {

const char* versionString() { return TOYHOST_VERSION_STRING; }

Version version() { return {TOYHOST_VERSION_MAJOR, TOYHOST_VERSION_MINOR, TOYHOST_VERSION_PATCH}; }

}  // namespace toyhost
