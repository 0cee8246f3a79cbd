#include "SamplingFlags.h"

#include <string>

#include "core/Defaults.h"

namespace toyhost::cli {

void SamplingFlags::define(CLI::App& command) {
    command.add_option("--supersample", supersample_,
                       "Draw Image N x N times a frame with fragCoord on a grid inside each pixel and average the "
                       "draws (anti-aliasing; buffers still run once a frame; default " +
                           std::to_string(defaults::kSupersample) + ": the site's pixels)");
    command.add_option("--motion-blur", motionBlur_,
                       "Draw Image at S times inside the shutter interval and average them (buffers, iFrame and "
                       "iTimeDelta stay the frame's; with --supersample every offset is drawn S times, each draw "
                       "at a time of its own)");
    command.add_option("--shutter", shutter_,
                       "Shutter angle of --motion-blur in degrees: the interval is angle/360 of the frame step "
                       "(default " + std::to_string(static_cast<int>(defaults::kShutterDegrees)) + ", the film convention)");
    command.add_option("--shutter-offset", shutterOffset_,
                       "Where the shutter interval of --motion-blur sits: open (at the frame's time, the default), "
                       "centre (around it) or close (ending at it)");
    command.add_option("--sample-space", sampleSpace_,
                       "How the samples are averaged: linear (in linear light, the default) or display (the 8-bit "
                       "display values box-averaged, as a larger render scaled down by an image editor)");
    command.add_flag("--dither", dither_,
                     "Add an 8x8 ordered dither to the averaged frame before it is rounded to 8 bits (smooth gradients)");
}

void SamplingFlags::applyTo(SessionSettings& settings) const {
    settings.supersample = supersample_;
    settings.motionBlur = motionBlur_;
    settings.shutterDegrees = shutter_;
    settings.dither = dither_;
    settings.shutterOffset = shutterOffset_;
    settings.sampleSpace = sampleSpace_;
}

}  // namespace toyhost::cli
