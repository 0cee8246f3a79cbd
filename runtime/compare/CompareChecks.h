// CompareChecks: the tolerance and gain a comparison is given, checked once for every caller (the
// library's compareShadertoys and compareImages, Python's compare and compare_images, the CLI):
// a NaN or non-positive PSNR, a level difference outside 0..255, a negative gain are refused
// naming the setting ("min_psnr", "max_diff", "diff_gain"). Pure, no GL.
#pragma once

#include <toyhost/CompareTypes.h>

namespace toyhost {

Status checkCompareTolerance(const CompareTolerance& tolerance, int diffGain);

}  // namespace toyhost
