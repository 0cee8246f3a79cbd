// toyhost/Export.h (public API, stable): TOYHOST_API marks what libtoyhost.so exports. The library
// is compiled with hidden visibility, so everything else (the runtime's modules, the GL loader,
// third-party code) stays inside it. No GL needed.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define TOYHOST_API __attribute__((visibility("default")))
#else
#define TOYHOST_API
#endif
