// Whether this machine's EGL has the device platform (EGL_EXT_platform_device) at all, asked of
// libEGL directly rather than through toyhost, so that a device-platform test skips only where the
// platform is absent and fails where it is there but broken. Needs EGL, no context.
#pragma once

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <optional>
#include <string>

namespace toyhost::testing {

// Absent means exactly one of: libEGL resolves no eglQueryDevicesEXT or no eglGetPlatformDisplayEXT
// (the functions are asked for, as toyhost does: glvnd with NVIDIA's driver listed devices while
// its extension string lacked the name), or eglQueryDevicesEXT succeeds and lists no device. Then
// the reason, for the skip message. Everything else is "present": a query that fails, a device
// whose display does not initialise, a context that cannot be made are defects the test reports
// (the class of the H100 glvnd bug, which a skip on any failure hid).
inline std::optional<std::string> eglDevicePlatformAbsence() {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!queryDevices || !getPlatformDisplay)
        return std::string("libEGL has no eglQueryDevicesEXT or eglGetPlatformDisplayEXT (no EGL_EXT_platform_device)");
    EGLint count = 0;
    if (queryDevices(0, nullptr, &count) && count == 0) return std::string("EGL lists no device");
    return std::nullopt;
}

}  // namespace toyhost::testing
