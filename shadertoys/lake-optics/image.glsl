// lake-optics — Image pass: a sandy shore sloping into deep water, seen from above at an angle.
//
// Technique (the water model is the point of this shader):
//   * The view ray hits the water plane y = 0 at P, is refracted (Snell, n = 1.33) at the
//     animated surface normal and marched through the water to the bottom B.
//       d_acc = |B - P|   the path length of the view ray inside the water
//       d     = -h(B)     the water depth above the bottom point (the sun's path down to it)
//   * Bottom radiance L_b = albedo * (sun * caustics + ambient) * exp(-K (d + d_acc)):
//     K is an RGB extinction coefficient (1/m), applied to the light going down to the bottom
//     and to the light coming back up along the view ray.
//   * In-scattering: water = L_b + C_s E (b / K) (1 - exp(-K d_acc)); the longer the path, the
//     more the colour tends to the water's own light: the scatter colour C_s lit by the light that
//     enters the water, E = sun * cos(refracted sun) + sky ambient (b = scattering coefficient,
//     1/m), of which a deep column returns b / K per channel (what K absorbs first never comes
//     back). Extended Reinhard tone map before gamma.
//   * Sky reflection by Schlick's Fresnel, F = F0 + (1 - F0)(1 - cos)^5, F0 = 0.02 for water:
//     colour = mix(water, sky(reflect), F).
//   Presets (keys 1-3, kept in Buffer A texel (0,0).x = 0, 1, 2):
//     1 tropical ocean   K = (0.46, 0.09, 0.06)  b = 0.11  C_s = (0.05, 0.05, 0.10)
//       pure water absorbs red most and blue least; few particles -> clear, blue.
//     2 muddy river      K = (1.05, 1.20, 1.55)  b = 0.90  C_s = (0.24, 0.17, 0.08)
//       suspended silt attenuates all colours strongly (grey-ish) with a bit more loss in blue;
//       the same silt back-scatters a lot, so the water turns opaque light brown within ~2 m.
//     3 tannin lake      K = (0.45, 0.80, 2.20)  b = 0.04  C_s = (0.055, 0.026, 0.007)
//       dissolved organic matter (humic acids / tannins) absorbs blue very strongly and red
//       weakly, but there are few particles: clear, dark amber "tea" water, black when deep.
//   Colours are linear; gamma 1/2.2 and a fixed +-1 level dither at the end. iMouse x (while
//   dragged) turns the camera. The preset indicator (1-3 squares, top left) shows for 2 s after
//   a preset key, so captured frames carry no overlay unless a key was pressed.
//   TRUTH (`toyhost run --define TRUTH`): the scene itself, for ../shared/tools/gallery_truth.py
//   to average 16 samples of: no distance calming of the normal, no pixel filter of the waves,
//   and PIXEL_SAMPLES (4) samples stacked along each truth pixel's height (64 a port pixel in all:
//   the tool's 16 leave moire in the far water, see mainImage and docs/gallery.md).
//   (Buffer A only keeps the preset and the key time, the same at any canvas size.)

const vec3 SUN_DIR = vec3(-0.38, 0.70, -0.60);   // behind-left of the camera: no glint in view
const vec3 SUN_COL = vec3(1.25, 1.15, 1.00);
const float WATER_IOR = 1.33;
#ifdef TRUTH
const int   PIXEL_SAMPLES = 4;    // samples stacked along each pixel's height (see mainImage)
#else
const int   PIXEL_SAMPLES = 1;
#endif

// ---------------------------------------------------------------- noise (hash-based, own) --
float hash2i(ivec2 c) {
    uint h = uint(c.x) * 0x8da6b343u ^ uint(c.y) * 0xd8163841u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return float(h) * (1.0 / 4294967296.0);
}

float vnoise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = p - i;
    vec2 u = f * f * (3.0 - 2.0 * f);
    ivec2 c = ivec2(i);
    float a = hash2i(c);
    float b = hash2i(c + ivec2(1, 0));
    float d = hash2i(c + ivec2(0, 1));
    float e = hash2i(c + ivec2(1, 1));
    return mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}

float fbm3(vec2 p) {
    float s = 0.0, a = 0.5;
    for (int i = 0; i < 3; i++) {
        s += a * vnoise(p);
        p = mat2(1.6, 1.2, -1.2, 1.6) * p + 7.3;
        a *= 0.5;
    }
    return s / 0.875;
}

// ---------------------------------------------------------------------------- terrain --
// "Offshore distance" s: < 0 is the beach, the sand shelf runs to s ~ 13, then a drop-off.
float offshore(vec2 xz) {
    return xz.x + 0.35 * xz.y + 1.8 * sin(0.11 * xz.y + 0.6) + 3.0 * (vnoise(xz * 0.07) - 0.5);
}

// depth (m, positive below the water line) as a function of s
float depthProfile(float s) {
    if (s < 0.0) return max(s * 0.10, -2.0);                    // beach rising inland
    return 2.1 * (1.0 - exp(-s / 4.5)) + 27.0 * smoothstep(12.5, 22.0, s);
}

// coral / rock patches on the shelf (0..1)
float patchMask(vec2 xz, float s) {
    float n = fbm3(xz * 0.28 + 3.1);
    return smoothstep(0.56, 0.70, n) * smoothstep(5.0, 7.5, s) * (1.0 - smoothstep(14.0, 19.0, s));
}

float terrainH(vec2 xz) {
    float s = offshore(xz);
    float h = -depthProfile(s);
    // sand ripples, strongest in the shallows
    float rip = sin(dot(xz, vec2(2.6, 1.1)) + 2.0 * vnoise(xz * 0.6));
    h += 0.035 * rip * smoothstep(-0.5, 1.0, s) * (1.0 - smoothstep(8.0, 14.0, s));
    // patches stand ~0.5 m proud of the sand
    h += 0.55 * patchMask(xz, s) * (0.7 + 0.3 * vnoise(xz * 2.3));
    // gentle dunes on land
    h += 0.5 * (fbm3(xz * 0.15) - 0.5) * (1.0 - smoothstep(-3.0, 0.0, s));
    return h;
}

vec3 terrainNormal(vec2 xz, float h) {
    const float e = 0.04;
    float hx = terrainH(xz + vec2(e, 0.0));
    float hz = terrainH(xz + vec2(0.0, e));
    return normalize(vec3(h - hx, e, h - hz));
}

vec3 terrainAlbedo(vec2 xz, float h) {
    float s = offshore(xz);
    float grain = vnoise(xz * 9.0);
    vec3 sand = mix(vec3(0.80, 0.71, 0.54), vec3(0.88, 0.80, 0.64), grain);
    sand *= 0.88 + 0.12 * fbm3(xz * 0.5 + 20.0);                  // large-scale sand variation
    // dark sea-grass / rock / coral patches
    float pm = patchMask(xz, s);
    float tint = vnoise(xz * 1.1 + 11.0);
    vec3 patchCol = mix(vec3(0.20, 0.26, 0.12), vec3(0.45, 0.30, 0.22), tint);
    vec3 c = mix(sand, patchCol, smoothstep(0.05, 0.5, pm));
    // wet sand just above the water line, dry grass far inland
    float above = h;
    c *= mix(1.0, 0.62, smoothstep(0.35, 0.0, above) * step(0.0, above));
    c = mix(c, vec3(0.42, 0.45, 0.22), smoothstep(1.1, 1.9, above) * smoothstep(0.45, 0.6, fbm3(xz * 0.4)));
    return c;
}

// ---------------------------------------------------------------------------- sky --
vec3 sky(vec3 rd) {
    float y = max(rd.y, 0.0);
    vec3 c = mix(vec3(0.64, 0.77, 0.92), vec3(0.12, 0.32, 0.78), sqrt(y));
    float s = max(dot(rd, normalize(SUN_DIR)), 0.0);
    c += vec3(1.0, 0.9, 0.7) * (0.25 * pow(s, 8.0) + 30.0 * pow(s, 900.0));
    return c;
}

// ------------------------------------------------------------------------ water surface --
// sum of directional waves with deep-water dispersion w = sqrt(g k); returns the normal.
// Nine waves, turned by the golden angle and x1.37 in wavenumber (no common period in view), each
// modulated by slow value noise of its own so the pattern comes in patches instead of a visibly
// repeating sheet. Each wave is filtered by the pixel it is seen through: `dPx`, `dPy` are the
// steps on the water from this pixel to its right and upper neighbours, and a box that wide turns
// cos(phase) into cos(phase) * sin(h) / h with h half the phase change across it, per axis (the
// average of a wave over a pixel, exactly, for a plane; zero past two lobes). A wave that crosses
// the view keeps the detail the pixel resolves across it; one seen along its own direction far away
// averages out. (Issue 29: fading by the strip's long axis at 3-8 rad left 0.37 of the truth's far
// detail; this gives 0.42, and every PSNR rises; docs/gallery.md.)
float boxResponse(float phaseChange) {
    float h = 0.5 * abs(phaseChange);
    return h < 1e-3 ? 1.0 : (h < 6.2831853 ? sin(h) / h : 0.0);
}
vec3 waterNormal(vec2 p, float t, vec2 dPx, vec2 dPy) {
    vec2 g = vec2(0.0);
    float ang = 0.4, k = 1.3, amp = 0.020;
    for (int i = 0; i < 9; i++) {
        vec2 dir = vec2(cos(ang), sin(ang));
        float w = sqrt(9.81 * k);
        float patchy = 0.35 + 1.3 * vnoise(p * 0.13 + vec2(float(i) * 7.1, 0.05 * t));
        float keep = boxResponse(k * dot(dir, dPx)) * boxResponse(k * dot(dir, dPy));
        g += dir * (amp * k * patchy * keep * cos(dot(p, dir) * k - w * t + float(i) * 1.7));
        ang += 2.39996;
        k *= 1.37;
        amp *= 0.78;
    }
    return normalize(vec3(-g.x, 1.0, -g.y));
}

// cheap animated caustic net: two warped sine layers, bright where both are near a crest
float causticLayer(vec2 q, float t) {
    q += 0.8 * sin(q.yx * 0.9 + vec2(0.7, 1.0) * t);
    q += 0.35 * sin(q.yx * 2.3 - vec2(1.1, 0.6) * t);
    vec2 s = abs(sin(q));
    return pow(1.0 - min(s.x, s.y), 5.0);
}
float caustic(vec2 p, float t) {
    float c = causticLayer(p * 2.2, t) + causticLayer(mat2(0.8, 0.6, -0.6, 0.8) * p * 2.9 + 4.0, 1.2 * t);
    return 0.45 + 1.6 * c;
}

// ---------------------------------------------------------------------------- march --
// march a ray (ro, rd) against the height field from t0 to t1; returns t of the hit or -1
// Once below, it bisects between the last point above and this one (5 halvings) in the same loop,
// not in a loop of its own nested in the step loop: llvmpipe runs an if's body for every pixel and
// a loop's at least once, so a nested bisection cost one more height evaluation at every step
// (docs/performance.md).
float marchTerrain(vec3 ro, vec3 rd, float t0, float t1, int steps) {
    float t = t0;
    float tPrev = t0;
    int i = 0, halvings = -1;           // halvings >= 0: bisecting [tPrev, t]
    for (int n = 0; n < 96 + 5; n++) {
        if (halvings < 0 && (i >= steps || i >= 96 || t > t1)) break;
        float m = halvings < 0 ? t : 0.5 * (tPrev + t);
        vec3 p = ro + rd * m;
        float dh = p.y - terrainH(p.xz);
        if (halvings >= 0) {
            if (dh < 0.0) t = m; else tPrev = m;
            if (++halvings == 5) return 0.5 * (tPrev + t);
            continue;
        }
        if (dh < 0.0) { halvings = 0; continue; }
        tPrev = t;
        t += max(0.04, 0.45 * dh);
        i++;
    }
    return -1.0;
}

// ------------------------------------------------------------------------- presets --
void getPreset(int id, out vec3 K, out float b, out vec3 Cs) {
    if (id == 1) {          // muddy river
        K = vec3(1.05, 1.20, 1.55); b = 0.90; Cs = vec3(0.24, 0.17, 0.08);
    } else if (id == 2) {   // tannin / peat lake
        K = vec3(0.45, 0.80, 2.20); b = 0.04; Cs = vec3(0.055, 0.026, 0.007);
    } else {                // tropical ocean (default)
        K = vec3(0.46, 0.09, 0.06); b = 0.11; Cs = vec3(0.05, 0.05, 0.10);
    }
}

vec3 shadeLand(vec3 p, vec3 rd) {
    vec3 n = terrainNormal(p.xz, p.y);
    vec3 alb = terrainAlbedo(p.xz, p.y);
    vec3 L = normalize(SUN_DIR);
    float dif = max(dot(n, L), 0.0);
    vec3 amb = vec3(0.30, 0.36, 0.45) * (0.6 + 0.4 * n.y);
    return alb * (SUN_COL * dif + amb);
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

// One sample of the scene along the camera ray through uv.
vec3 sceneSample(vec2 uv, vec3 ro, vec3 rt, vec3 up, vec3 fw, float t, vec3 K, float b, vec3 Cs) {
    vec3 rd0 = uv.x * rt + uv.y * up + 1.7 * fw;   // before normalising: the neighbours' rays below
    vec3 rd = normalize(rd0);

    vec3 col;
    vec3 L = normalize(SUN_DIR);
    if (rd.y >= -0.001) {
        col = sky(rd);
    } else {
        float tW = ro.y / -rd.y;                            // water plane y = 0
        float tTop = max((ro.y - 2.2) / -rd.y, 0.0);        // land is below y = 2.2
        float tL = marchTerrain(ro, rd, tTop, tW, 48);
        if (tL > 0.0) {
            col = shadeLand(ro + rd * tL, rd);
        } else {
            vec3 P = ro + rd * tW;
#ifdef TRUTH
            float fade = 1.0;                    // the scene itself (see the header)
            vec2 dPx = vec2(0.0), dPy = vec2(0.0);
#else
            float fade = 1.0 / (1.0 + tW * 0.04);           // the foam line's texture calms far away
            // where the rays of the right and upper neighbours meet the water
            vec3 rdx = normalize(rd0 + 2.0 / iResolution.y * rt);
            vec3 rdy = normalize(rd0 + 2.0 / iResolution.y * up);
            vec2 dPx = (ro + rdx * (ro.y / max(-rdx.y, 1e-4))).xz - P.xz;
            vec2 dPy = (ro + rdy * (ro.y / max(-rdy.y, 1e-4))).xz - P.xz;
#endif
            vec3 n = waterNormal(P.xz, t, dPx, dPy);
            vec3 rr = refract(rd, n, 1.0 / WATER_IOR);

            // march the refracted ray to the bottom (at most 45 m of water)
            const float MAX_PATH = 45.0;
            float tB = marchTerrain(P, rr, 0.0, MAX_PATH, 64);
            float dAcc = tB >= 0.0 ? tB : MAX_PATH;
            vec3 bottom = vec3(0.0);
            if (tB >= 0.0) {
                vec3 B = P + rr * tB;
                float d = max(-B.y, 0.0);
                vec3 nb = terrainNormal(B.xz, B.y);
                vec3 alb = terrainAlbedo(B.xz, B.y);
                // sunlight refracted into the water, with caustics that blur out with depth
                vec3 Lw = -refract(-L, vec3(0.0, 1.0, 0.0), 1.0 / WATER_IOR);
                float dif = max(dot(nb, Lw), 0.0);
                float ca = mix(1.0, caustic(B.xz - Lw.xz / Lw.y * d, t), exp(-0.25 * d));
                vec3 light = SUN_COL * dif * ca + vec3(0.25, 0.33, 0.42) * (0.5 + 0.5 * nb.y);
                bottom = alb * light * exp(-K * (d + dAcc));
            }
            // the scatter colour is lit by what enters the water: the refracted sun and the sky
            vec3 Lw0 = -refract(-L, vec3(0.0, 1.0, 0.0), 1.0 / WATER_IOR);
            vec3 incident = SUN_COL * Lw0.y + vec3(0.25, 0.33, 0.42);
            // the water's own light (single scattering): the light that enters is scattered back
            // by the particles (colour C_s, coefficient b) while the water absorbs it on the way
            // down and back up; a deep column returns b / (2 K) per channel, so the red that K
            // takes first never comes back and tropical deep water turns blue-green, not the
            // particles' own lavender. Along the view ray it builds up as 1 - exp(-K d_acc).
            vec3 deep = Cs * incident * b / K;
            vec3 water = bottom + deep * (1.0 - exp(-K * dAcc));

            // Fresnel (Schlick) blend with the reflected sky
            float cosi = clamp(dot(-rd, n), 0.0, 1.0);
            float F = 0.02 + 0.98 * pow(1.0 - cosi, 5.0);
            vec3 rf = reflect(rd, n);
            rf.y = abs(rf.y);
            col = mix(water, sky(rf), F);

            // a thin line of foam at the water's edge
            float depthHere = -terrainH(P.xz);
            float foam = smoothstep(0.10, 0.0, depthHere)
                       * mix(0.5, smoothstep(0.3, 0.7, vnoise(P.xz * 2.5 + vec2(0.0, t * 0.5))), fade);
            col = mix(col, vec3(0.9, 0.93, 0.95) * (SUN_COL * max(L.y, 0.0) + 0.3), 0.6 * foam);
        }
    }

    return col;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int preset = int(clamp(texelFetch(iChannel0, ivec2(0), 0).x + 0.5, 0.0, 2.0));
    vec3 K, Cs; float b;
    getPreset(preset, K, b, Cs);

    float t = iTime;
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;

    // camera: 11 m above the water, looking down ~22 degrees across the shore, the horizon in view
    float yaw = 0.0;
    if (iMouse.z > 0.0) yaw = (iMouse.x / iResolution.x - 0.5) * 1.2;
    vec3 ro = vec3(-1.0, 11.0, -11.0);
    vec3 ta = vec3(6.5, 4.0, 4.5);
    vec3 fw0 = ta - ro;
    fw0.xz = mat2(cos(yaw), -sin(yaw), sin(yaw), cos(yaw)) * fw0.xz;
    vec3 fw = normalize(fw0);
    vec3 rt = normalize(cross(vec3(0.0, 1.0, 0.0), fw));
    vec3 up = cross(fw, rt);
    // One sample a pixel; the truth's far water takes more: its waves change phase by far more
    // than a pixel holds there, and 16 samples a pixel (the tool's) leave moire; PIXEL_SAMPLES,
    // stacked along each pixel's vertical axis (the long axis of its strip of water), make the
    // average converge. Tone map (extended Reinhard, white at 2) per sample: highlights roll off
    // instead of clipping, the dark water keeps its colour.
    vec3 col = vec3(0.0);
    for (int k = 0; k < PIXEL_SAMPLES; k++) {
        float dy = (float(k) + 0.5) / float(PIXEL_SAMPLES) - 0.5;
        vec3 c = sceneSample(uv + vec2(0.0, 2.0 * dy / iResolution.y), ro, rt, up, fw, t, K, b, Cs);
        col += c * (1.0 + c / 4.0) / (1.0 + c);
    }
    col /= float(PIXEL_SAMPLES);
    col = pow(clamp(col, 0.0, 1.0), vec3(1.0 / 2.2)) + ditherNoise(fragCoord);

    // preset indicator: 1-3 small squares in the top-left corner, for 2 s after a preset key
    // (Buffer A texel (0,0).y = iTime of the last preset key, -1 before any)
    float keyTime = texelFetch(iChannel0, ivec2(0), 0).y;
    bool showPreset = keyTime >= 0.0 && iTime - keyTime < 2.0 && texelFetch(iChannel0, ivec2(0), 0).w > 0.5;
    vec2 px = fragCoord - vec2(8.0, iResolution.y - 14.0);
    float sz = max(4.0, iResolution.y / 90.0);
    for (int i = 0; i < 3; i++) {
        if (i > preset || !showPreset) break;
        vec2 q = px - vec2(float(i) * sz * 1.8, 0.0);
        if (q.x >= 0.0 && q.x < sz && q.y >= -sz && q.y < 0.0) col = vec3(1.0);
    }

    fragColor = vec4(col, 1.0);
}
