// pingpong-probe: exact small integers in float buffers that prove Shadertoy's ping-pong rule
// and frame-0 clearing. Expected values at frame n (every pixel):
//   Buffer A = (n + 1, n, 10 n, 0.25)            A reads itself and B: both the previous frame
//   Buffer B = (10 (n + 1), (n + 1)(n + 2) / 2, n, 0.5)   B reads A: this frame; itself: previous
//   Image    = (A.x / 100, B.x / 1000, B.y / 1000, 1)     alpha forced to 1
vec4 fetch(sampler2D s, vec2 fragCoord) { return texelFetch(s, ivec2(fragCoord), 0); }
