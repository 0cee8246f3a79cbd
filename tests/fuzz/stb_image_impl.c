/* stb_image's decoder, compiled into fuzz_image from the same header Debian's libstb is built from
   (/usr/include/stb/stb_image.h), so that it carries the sanitizers and libFuzzer's coverage: the
   definitions here take precedence over libstb.so's for the calls in runtime/image/ImageFile.cpp. */
#define STB_IMAGE_IMPLEMENTATION
/* Only stb's PNG decoder is reached from users' files (JPEGs go to libjpeg-turbo). */
#define STBI_ONLY_PNG
#include <stb_image.h>
