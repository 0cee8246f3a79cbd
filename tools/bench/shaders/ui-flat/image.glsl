// A flat, UI-like frame for the PNG encoder benchmark: solid panels, a grid of buttons, thin
// lines and a progress bar; large areas of one colour, as in a tool's screenshot.
float box(vec2 p, vec2 lo, vec2 hi) { return step(lo.x, p.x) * step(lo.y, p.y) * step(p.x, hi.x) * step(p.y, hi.y); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord;
    vec2 r = iResolution.xy;
    vec3 col = vec3(0.93);                                                 // background
    col = mix(col, vec3(0.16, 0.18, 0.22), box(p, vec2(0.0, r.y - 48.0), r));  // title bar
    col = mix(col, vec3(0.85, 0.87, 0.9), box(p, vec2(0.0), vec2(260.0, r.y - 48.0)));  // side panel
    for (int i = 0; i < 12; ++i) {
        float y = r.y - 90.0 - float(i) * 40.0;
        col = mix(col, i == 3 ? vec3(0.2, 0.45, 0.9) : vec3(0.98), box(p, vec2(12.0, y), vec2(248.0, y + 30.0)));
    }
    vec2 cell = mod(p - vec2(280.0, 20.0), vec2(180.0, 120.0));
    float inGrid = box(p, vec2(280.0, 20.0), r - vec2(20.0, 68.0));
    col = mix(col, vec3(1.0), inGrid * box(cell, vec2(0.0), vec2(170.0, 110.0)));
    col = mix(col, vec3(0.75), inGrid * box(cell, vec2(0.0, 109.0), vec2(170.0, 110.0)));
    float progress = fract(iTime * 0.1);
    col = mix(col, vec3(0.3, 0.75, 0.4), box(p, vec2(280.0, r.y - 40.0), vec2(280.0 + progress * (r.x - 300.0), r.y - 8.0)));
    fragColor = vec4(col, 1.0);
}
