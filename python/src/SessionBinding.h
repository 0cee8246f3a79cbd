// The Python side of toyhost::Session (the native `_toyhost.Session`): a headless session living on
// its own GL worker thread, stepped and read back with the GIL released, frames read straight into
// numpy arrays. toyhost/__init__.py wraps it with the friendlier mouse/keys/render API.
// No GL on the calling thread: every GL call runs on the session's worker.
#pragma once

#include <pybind11/pybind11.h>

namespace toyhost::python {

void bindSession(pybind11::module_& module);

// Raises (a usage error) in a child forked while a session was open in its parent: GL cannot
// start there (the driver's threads stayed in the parent) and would wait forever.
void refuseAfterForkWithGlOpen();

}  // namespace toyhost::python
