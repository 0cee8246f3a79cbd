// The Python side of toyhost's comparison (include/toyhost/Compare.h): `_toyhost.compare` (two
// shadertoys rendered with the same inputs, frame by frame, on a GL thread of its own with the GIL
// released) and `_toyhost.compare_images` (two numpy frames). toyhost/_compare.py shapes the
// results. compare needs no GL on the calling thread; compare_images none at all.
#pragma once

#include <pybind11/pybind11.h>

namespace toyhost::python {

void bindCompare(pybind11::module_& module);

}  // namespace toyhost::python
