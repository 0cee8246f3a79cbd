// CurrentContext: a GlContext for a context that belongs to the caller (a program that embeds
// toyhost and renders with its own window and loop): it is whatever context is current on the
// calling thread; toyhost never makes it current, releases or destroys it. Needs that context
// current (OpenGL ES 3.0 or later) when created and whenever toyhost renders.
#pragma once

#include <memory>

#include "gl/GlContext.h"

namespace toyhost {

// Fails when no context is current or it lacks what Shadertoy's player needs (OpenGL ES 3, float
// render targets).
Result<std::shared_ptr<GlContext>> adoptCurrentContext();

}  // namespace toyhost
