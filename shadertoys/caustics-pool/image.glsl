// caustics-pool — a tiled swimming pool lit by an animated caustic pattern, seen through a
// refracting, moving water surface.
//
// Technique and parameters (the why):
//   * Caustic pattern: an iterated domain warp. Starting from p = 2*pi*uv, each of 4 steps
//     sets q = p + a_i (n1 sin(k1.q + w1 t) + n2 cos(k2.q - w2 t)) with INTEGER wave vectors
//     k1, k2, so q - p is periodic: the whole pattern tiles over one period (CAUSTIC_TILE m).
//     Bright, thin lines sit where the warped lattice sin(2 q.x), sin(2 q.y), sin(q.x + q.y)
//     crosses zero (1 - |sin| raised to a high power); the warp (amplitude 0.75 falling off per
//     step) bends the lattice into the irregular cells of real pool caustics. Mapped onto the
//     water rotated by 37 degrees (so it never lines up with the tiles) and sampled three
//     times with a depth-proportional offset for a little chromatic dispersion.
//   * Projection: a floor/wall point H is lit by the sun ray refracted into the water (Snell,
//     n = 1.33); the caustic is looked up where that ray entered the surface, S = H + Lw s
//     (s = sun path length in the water). Caustic contrast rises over the first ~0.8 m (the
//     light has to focus) and fades slowly with depth (blur). Where S lies outside the pool the
//     wall shades the point.
//   * Beer's law: light is attenuated by exp(-K s) on the way down and exp(-K t) on the way to
//     the eye (t = view path in the water), K = (0.30, 0.045, 0.03) 1/m: pure water absorbs
//     red far more than blue, hence the cyan of white tiles; a little in-scattering toward a
//     pool blue (b = 0.04 1/m). The floor slopes from 1.0 m to 2.6 m so the shift is visible.
//   * Surface: a sum of directional sine waves with deep-water dispersion w = sqrt(g k) (plus a
//     small ripple noise); the view ray is refracted at its normal, the sky reflected with
//     Schlick Fresnel (F0 = 0.02) and a sun glint added.
//   * FLOW_MAP (uncomment below): moving water. Caustics and surface are sampled twice, with
//     coordinates advected along a flow field by phase*FLOW_LEN for two phases half a cycle
//     apart; the weights 1 - |1 - 2 phase| sum to 1 and each phase is weightless when it jumps
//     back, so the reset never shows (flow-map technique as in Valve's water, 2010).
//   iMouse: drag horizontally to orbit the camera around the pool.
//   * TRUTH (`toyhost run --define TRUTH`): the scene itself, for ../shared/tools/gallery_truth.py
//     to average 16 samples of: no distance fade of the surface normal, hard grout edges (no
//     fwidth AA). The deck's haze stays (the scene's air).

// #define FLOW_MAP

const float TAU = 6.28318530718;
const float PW = 3.0;                 // pool half width (x), m
const float PL = 6.0;                 // pool half length (z), m
const float DECK = 0.30;              // deck height above the water line, m
const float FLOOR0 = 1.8;             // floor depth at z = 0, m
const float FLOOR_SLOPE = 0.13;       // depth grows by 0.13 m per m of z (1.02 .. 2.58 m)
const float TILE = 0.25;              // floor/wall tile size, m
const float CAUSTIC_TILE = 1.7;       // period of the caustic pattern on the surface, m
const float IOR = 1.33;
const vec3  K_EXT = vec3(0.30, 0.045, 0.03);   // extinction, 1/m
const float B_SCAT = 0.04;                     // scattering, 1/m
const vec3  C_SCAT = vec3(0.02, 0.13, 0.17);   // in-scattered pool colour
const vec3  SUN_DIR = vec3(0.55, 0.78, -0.30);   // behind-right of the camera
const vec3  SUN_COL = vec3(1.30, 1.22, 1.08);
const vec2  FLOW_DIR = vec2(0.25, 1.0);        // main flow (FLOW_MAP), toward the deep end
const float FLOW_LEN = 0.9;                    // m advected per cycle
const float FLOW_RATE = 0.35;                  // cycles per second

// ------------------------------------------------------------------------ hashing / noise --
float hash21(vec2 p) {
    uvec2 u = uvec2(ivec2(floor(p)) + 4096);
    uint h = u.x * 0x27d4eb2du ^ (u.y + 0x9e3779b9u) * 0x85ebca6bu;
    h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15; h *= 0x846ca68bu; h ^= h >> 16;
    return float(h) * (1.0 / 4294967296.0);
}

float vnoise(vec2 p) {
    vec2 i = floor(p), f = p - i;
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash21(i), hash21(i + vec2(1, 0)), u.x),
               mix(hash21(i + vec2(0, 1)), hash21(i + vec2(1, 1)), u.x), u.y);
}

// ------------------------------------------------------------------------ caustic pattern --
// uv in pattern periods (tiles with period 1 in u and v); returns ~0 .. 3, mean ~0.35
float causticPattern(vec2 uv, float t) {
    vec2 p = uv * TAU;
    vec2 q = p;
    // integer wave vectors keep every step periodic in p with period 2 pi
    const vec2 K1[4] = vec2[4](vec2(1.0, 2.0), vec2(2.0, -1.0), vec2(-1.0, 3.0), vec2(3.0, 1.0));
    const vec2 K2[4] = vec2[4](vec2(2.0, -3.0), vec2(1.0, 1.0), vec2(-3.0, -2.0), vec2(1.0, -2.0));
    for (int i = 0; i < 4; i++) {
        float fi = float(i);
        float a = 0.75 / (1.0 + 0.6 * fi);
        vec2 k1 = K1[i], k2 = K2[i];
        vec2 n1 = normalize(vec2(-k1.y, k1.x) + 0.5 * k1);     // displacement directions
        vec2 n2 = normalize(vec2(k2.y, -k2.x) + 0.3 * k2);
        float a1 = dot(k1, q) + t * (1.1 + 0.2 * fi) + fi * 1.3;
        float a2 = dot(k2, q) - t * (0.9 + 0.15 * fi) + fi * 2.1;
        q = p + a * (n1 * sin(a1) + n2 * cos(a2));
    }
    vec3 s = abs(sin(vec3(2.0 * q.x, 2.0 * q.y, q.x + q.y + 0.3)));
    vec3 l = pow(1.0 - s, vec3(14.0, 14.0, 10.0));
    float c = l.x + l.y + 0.7 * l.z;
    return c * c * 0.8 + 0.3 * c;
}

// RGB caustic with a little dispersion: red focuses slightly deeper than blue
vec3 causticRGB(vec2 uv, float t, vec2 disp) {
    return vec3(causticPattern(uv + disp, t),
                causticPattern(uv, t),
                causticPattern(uv - disp, t));
}

// ------------------------------------------------------------------------- water surface --
// height field gradient (dh/dx, dh/dz) of a sum of directional waves + ripple noise
vec2 waveGrad(vec2 p, float t) {
    vec2 g = vec2(0.0);
    float ang = 0.3, k = 2.2, amp = 0.009;
    for (int i = 0; i < 6; i++) {
        vec2 d = vec2(cos(ang), sin(ang));
        float w = sqrt(9.81 * k);
        g += d * (amp * k * cos(dot(p, d) * k - w * t + float(i) * 2.4));
        ang += 2.39996;              // golden angle: directions spread evenly
        k *= 1.43;
        amp *= 0.70;
    }
    // small ripples: finite-difference gradient of moving value noise
    vec2 rp = p * 5.0 + vec2(0.3, 0.2) * t;
    float n0 = vnoise(rp);
    g += 0.005 * 5.0 * vec2(vnoise(rp + vec2(0.05, 0.0)) - n0, vnoise(rp + vec2(0.0, 0.05)) - n0) / 0.05;
    return g;
}

vec2 flowAt(vec2 xz) {
    // a gently meandering flow field (m per cycle, scaled by FLOW_LEN)
    return normalize(FLOW_DIR) + vec2(0.35 * sin(xz.y * 0.6 + 1.0), 0.2 * sin(xz.x * 0.9));
}

vec3 surfaceNormal(vec2 xz, float t, float fade) {
    vec2 g;
#ifdef FLOW_MAP
    vec2 fl = flowAt(xz) * FLOW_LEN;
    float ph0 = fract(t * FLOW_RATE);
    float ph1 = fract(t * FLOW_RATE + 0.5);
    float w0 = 1.0 - abs(1.0 - 2.0 * ph0);
    g = w0 * waveGrad(xz - fl * ph0, t) + (1.0 - w0) * waveGrad(xz - fl * ph1 + vec2(0.37, 0.71), t);
    g *= 1.25;   // averaging two phases lowers the contrast a little: compensate
#else
    g = waveGrad(xz, t);
#endif
    g *= fade;
    return normalize(vec3(-g.x, 1.0, -g.y));
}

vec3 causticAt(vec2 xz, float t, vec2 disp) {
    // rotated so the pattern's lattice does not line up with the tiles
    vec2 uv = mat2(0.8, 0.6, -0.6, 0.8) * xz / CAUSTIC_TILE;
#ifdef FLOW_MAP
    vec2 fl = mat2(0.8, 0.6, -0.6, 0.8) * flowAt(xz) * (FLOW_LEN / CAUSTIC_TILE);
    float ph0 = fract(t * FLOW_RATE);
    float ph1 = fract(t * FLOW_RATE + 0.5);
    float w0 = 1.0 - abs(1.0 - 2.0 * ph0);
    vec3 c = w0 * causticRGB(uv - fl * ph0, t, disp)
           + (1.0 - w0) * causticRGB(uv - fl * ph1 + vec2(0.5, 0.25), t, disp);
    // two partly overlapping nets: restore the contrast of a single one
    return max(c * 1.25 - 0.08, 0.0);
#else
    return causticRGB(uv, t, disp);
#endif
}

// ------------------------------------------------------------------------------- shading --
vec3 sky(vec3 rd) {
    float y = max(rd.y, 0.0);
    vec3 c = mix(vec3(0.70, 0.82, 0.95), vec3(0.18, 0.42, 0.85), sqrt(y));
    float s = max(dot(rd, normalize(SUN_DIR)), 0.0);
    return c + vec3(1.0, 0.9, 0.7) * 0.3 * pow(s, 6.0);
}

// grout mask of a square tiling with cell size `size` (1 in the tile, 0 in the grout)
float tileMask(vec2 uv, float size, float grout) {
    vec2 f = fract(uv / size);
    vec2 d = min(f, 1.0 - f);
#ifdef TRUTH
    vec2 fw = vec2(1e-6);   // hard grout edges: the truth averages them itself
#else
    vec2 fw = fwidth(uv / size) + 1e-4;
#endif
    vec2 m = smoothstep(grout - fw, grout + fw, d);
    return m.x * m.y;
}

vec3 floorAlbedo(vec2 xz) {
    vec2 cell = floor(xz / TILE);
    vec3 tileCol = vec3(0.80, 0.90, 0.92) * (0.94 + 0.06 * hash21(cell));
    // two dark-blue lane lines, two tiles wide, with a T at each end
    float lane = (cell.x == -7.0 || cell.x == -6.0 || cell.x == 5.0 || cell.x == 6.0) ? 1.0 : 0.0;
    lane *= step(abs(xz.y), PL - 1.25);
    float tbar = step(abs(abs(xz.y) - (PL - 1.375)), 0.125)
               * (step(abs(xz.x + 1.5), 0.75) + step(abs(xz.x - 1.5), 0.75));
    lane = max(lane, min(tbar, 1.0));
    tileCol = mix(tileCol, vec3(0.04, 0.10, 0.32), lane);
    return mix(vec3(0.52, 0.56, 0.56), tileCol, tileMask(xz, TILE, 0.035));
}

vec3 wallAlbedo(vec2 uv, float y) {
    // uv = (along the wall, height); a band of small dark mosaic tiles at the water line
    if (y > -0.30) {
        vec2 cell = floor(uv / (TILE * 0.5));
        vec3 c = mix(vec3(0.05, 0.18, 0.45), vec3(0.10, 0.35, 0.60), hash21(cell + 17.0));
        return mix(vec3(0.5, 0.53, 0.55), c, tileMask(uv, TILE * 0.5, 0.05));
    }
    vec2 cell = floor(uv / TILE);
    vec3 tileCol = vec3(0.80, 0.90, 0.92) * (0.94 + 0.06 * hash21(cell + 3.0));
    return mix(vec3(0.52, 0.56, 0.56), tileCol, tileMask(uv, TILE, 0.035));
}

vec3 deckColor(vec3 p) {
    vec3 L = normalize(SUN_DIR);
    // distance outside the pool rectangle: the coping is the first 0.35 m
    vec2 e = abs(p.xz) - vec2(PW, PL);
    float dOut = length(max(e, 0.0)) + min(max(e.x, e.y), 0.0);
    vec3 alb;
    if (dOut < 0.35) {
        alb = vec3(0.86, 0.84, 0.80) * (0.95 + 0.05 * vnoise(p.xz * 20.0));
    } else {
        vec2 cell = floor(p.xz / 0.6);
        alb = vec3(0.70, 0.64, 0.55) * (0.88 + 0.12 * hash21(cell + 40.0));
        alb *= 0.9 + 0.1 * vnoise(p.xz * 12.0);
        alb = mix(vec3(0.45, 0.42, 0.38), alb, tileMask(p.xz, 0.6, 0.012));
    }
    return alb * (SUN_COL * L.y + vec3(0.30, 0.36, 0.45));
}

// lit colour of a surface point under water (before the view-path attenuation)
vec3 shadeUnderwater(vec3 H, vec3 n, vec3 alb, float t) {
    vec3 L = normalize(SUN_DIR);
    vec3 Lw = -refract(-L, vec3(0.0, 1.0, 0.0), 1.0 / IOR);   // refracted sun, pointing up
    float s = -H.y / Lw.y;                                       // sun path in the water
    vec3 S = H + Lw * s;                                         // where that light entered
    float lit = step(abs(S.x), PW) * step(abs(S.z), PL);         // else blocked by the wall
    float ndl = max(dot(n, Lw), 0.0);
    vec3 direct = vec3(0.0);
    if (lit * ndl > 0.0) {
        vec2 disp = normalize(Lw.xz + 1e-4) * 0.006 * s;
        vec3 c = causticAt(S.xz, t, disp);
        float k = smoothstep(0.0, 0.8, s) * (0.55 + 0.45 * exp(-0.25 * s));
        vec3 light = mix(vec3(1.0), 0.3 + 2.4 * c, k);
        direct = SUN_COL * ndl * light * exp(-K_EXT * s);
    }
    vec3 ambient = vec3(0.22, 0.32, 0.42) * exp(-K_EXT * max(-H.y, 0.0)) * (0.6 + 0.4 * n.y);
    return alb * (direct + ambient);
}

// Triangular dither of +-1 code value per channel, fixed per pixel (the same every frame, so it
// neither flickers nor changes a golden frame): turns the 8-bit steps of smooth gradients into
// grain. Two uniform hashes per channel (one 3-vector hash of the pixel, another of a shifted one).
vec3 ditherNoise(vec2 fragCoord) {
    vec3 p = fract(vec3(fragCoord.xyx) * vec3(0.1031, 0.1030, 0.0973));
    p += dot(p, p.yxz + 33.33);
    vec3 a = fract((p.xxy + p.yzz) * p.zyx);
    vec3 q = fract(vec3(fragCoord.yxy + 17.0) * vec3(0.1031, 0.1030, 0.0973));
    q += dot(q, q.yxz + 33.33);
    vec3 b = fract((q.xxy + q.yzz) * q.zyx);
    return (a + b - 1.0) / 255.0;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float t = iTime;
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;

    // camera at the shallow-end corner, 3.4 m above the water, looking down the pool
    float yaw = 0.0;
    if (iMouse.z > 0.0) yaw = (iMouse.x / iResolution.x - 0.5) * 2.5;
    vec3 ta = vec3(0.4, -1.6, 0.4);
    vec3 off = vec3(-3.8, 5.4, -5.4);
    off.xz = mat2(cos(yaw), sin(yaw), -sin(yaw), cos(yaw)) * off.xz;
    vec3 ro = ta + off;
    vec3 fw = normalize(ta - ro);
    vec3 rt = normalize(cross(vec3(0.0, 1.0, 0.0), fw));
    vec3 up = cross(fw, rt);
    vec3 rd = normalize(uv.x * rt + uv.y * up + 1.8 * fw);

    vec3 L = normalize(SUN_DIR);
    vec3 col;
    if (rd.y >= 0.0) {
        col = sky(rd);
    } else {
        float tD = (ro.y - DECK) / -rd.y;
        vec3 A = ro + rd * tD;
        if (abs(A.x) > PW || abs(A.z) > PL) {
            col = deckColor(A);
            // soft fade to the sky colour far away
            col = mix(col, sky(vec3(rd.x, 0.0, rd.z)), 1.0 - exp(-0.0004 * tD * tD));
        } else {
            // inside the pool opening: the dry wall above the water, or the water
            float tW = ro.y / -rd.y;
            float txw = (sign(rd.x) * PW - ro.x) / rd.x;
            float tzw = (sign(rd.z) * PL - ro.z) / rd.z;
            float tWall = min(txw, tzw);
            if (tWall < tW) {
                vec3 Q = ro + rd * tWall;
                bool isX = txw < tzw;
                vec3 n = isX ? vec3(-sign(rd.x), 0.0, 0.0) : vec3(0.0, 0.0, -sign(rd.z));
                vec3 alb = wallAlbedo(vec2(isX ? Q.z : Q.x, Q.y), Q.y);
                col = alb * (SUN_COL * max(dot(n, L), 0.0) + vec3(0.30, 0.36, 0.45));
            } else {
                vec3 P = ro + rd * tW;
#ifdef TRUTH
                float fade = 1.0;
#else
                float fade = 1.0 / (1.0 + 0.05 * tW);
#endif
                vec3 n = surfaceNormal(P.xz, t, fade);
                vec3 r = refract(rd, n, 1.0 / IOR);

                // first hit of the refracted ray: sloped floor or one of the four walls
                float tF = -(P.y + FLOOR0 + FLOOR_SLOPE * P.z) / (r.y + FLOOR_SLOPE * r.z);
                if (tF < 0.0) tF = 1e4;
                float tx = (sign(r.x) * PW - P.x) / r.x;
                float tz = (sign(r.z) * PL - P.z) / r.z;
                float th = min(tF, min(tx, tz));
                vec3 H = P + r * th;
                vec3 nH, alb;
                if (th == tF) {
                    nH = normalize(vec3(0.0, 1.0, FLOOR_SLOPE));
                    alb = floorAlbedo(H.xz);
                } else if (th == tx) {
                    nH = vec3(-sign(r.x), 0.0, 0.0);
                    alb = wallAlbedo(vec2(H.z, H.y), H.y);
                } else {
                    nH = vec3(0.0, 0.0, -sign(r.z));
                    alb = wallAlbedo(vec2(H.x, H.y), H.y);
                }
                vec3 under = shadeUnderwater(H, nH, alb, t);
                under *= exp(-K_EXT * th);                         // Beer's law to the eye
                under = mix(C_SCAT, under, exp(-B_SCAT * th));     // in-scattering

                float cosi = clamp(dot(-rd, n), 0.0, 1.0);
                float F = 0.02 + 0.98 * pow(1.0 - cosi, 5.0);
                vec3 rf = reflect(rd, n);
                rf.y = abs(rf.y);
                col = mix(under, sky(rf), F);
                col += SUN_COL * 3.0 * pow(max(dot(rf, L), 0.0), 900.0);   // sun glint
            }
        }
    }

    col = 1.0 - exp(-1.15 * col);                 // gentle tone map
    col = pow(col, vec3(1.0 / 2.2));
    fragColor = vec4(col + ditherNoise(fragCoord), 1.0);
}
