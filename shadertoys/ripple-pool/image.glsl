// ripple-pool / Image: a tiled swimming pool with a sphere, seen at an angle (default; the
// 3-D view at the end of this file, its camera in common.glsl), or straight from above (TOP_VIEW).
//
// iChannel0 = Buffer D (the height field at the end of the frame, .x = height
// in cells, linear filtering; common.glsl simulates it).
// The top view (TOP_VIEW): the eye is a wide-angle pinhole above the pool centre (half the pool's short
// side up) and the water surface lies in the image plane, so pixel p shows the
// water at p: where you click is where the ripple appears. Towards the edges the
// view meets the water up to ~64 degrees from the normal, where Fresnel matters.
//  - normal from central differences of the height field
//  - refraction (Snell, n = 1.333) of the view ray down to a tiled floor at
//    DEPTH pixels; rays that leave the pool sideways hit the tiled walls
//  - reflection of the scene, mixed in with Schlick's Fresnel (F0 = 0.02 for
//    water): the tiled walls rising RIM above the water, above them a procedural
//    sky + sun. Replacing F by F0 changes the edges of the picture by several
//    levels (a mutation test checks it fails its golden).
//  - Beer-Lambert absorption along the refracted path (red is absorbed most)
//  - caustics by the refracted-area rule: sunlight bent by the surface moves a
//    floor point by -alpha*DEPTH*grad(h) (alpha = 1 - 1/1.333, small slopes), the
//    Jacobian is I - alpha*DEPTH*Hessian(h), light intensity ~ 1/|det J|
//  - the sun is high, so a caustic sits only ~7 px from its ripple; the wall
//    and deck on the sunny side shade a band of floor (the refracted sun ray
//    from the floor point is traced up to the wall top)
// All ripple optics use grid cells (one per pixel up to 180 rows, then scaled),
// the tile pattern scales with the canvas height.

const float GAIN     = 2.5;           // visual height exaggeration of the simulated field
const float DEPTH    = 48.0;          // pool depth in pixels (optical)
const float ETA      = 1.0 / 1.333;   // air -> water
const float ALPHA    = 1.0 - 1.0 / 1.333;
const vec2  DEPTH_M  = vec2(1.1, 3.4); // physical depth, shallow (left) to deep end, metres
const vec3  SIGMA    = vec3(1.10, 0.26, 0.11);   // absorption per metre
const vec3  WATER    = vec3(0.02, 0.16, 0.22);   // in-scattered water colour
#ifdef TOP_VIEW
const vec3  SUN_DIR  = vec3(0.12, 0.16, 0.98);   // towards the sun (normalised below), high:
                                                 // caustics sit close under their ripples
#else
const vec3  SUN_DIR  = vec3(0.60, 0.40, 0.69);   // 3-D view (x right, y to the far side, z up): lower,
                                                 // beyond the pool, so the sphere's shadow shows
#endif
const vec3  SUN_COL  = vec3(1.0, 0.93, 0.82);
const float WALL_UP  = 4.0 * DEPTH;   // height of the shading wall + deck above the floor
const float EYE_UP   = 0.5;           // eye height above the water, in canvas heights

// The simulation's grid: one cell per pixel up to 180 rows, else 180 rows scaled up (gridScale()
// in common.glsl).
vec2 gridSize() { return max(floor(iResolution.xy / gridScale()), vec2(1.0)); }

// Where this frame's time falls between the last two simulation steps (Buffer D holds h after
// the last step due, tick n, in .x and h one step earlier in .y): the water is drawn half a step
// behind iTime, interpolated between them. A frame's number of steps changes with the frame rate
// (3, 2, 3, 2 ... at 24 fps); drawn from the last step alone the picture jumped by 3 and 2 steps'
// worth in turn (+-25% change every frame), interpolated it moves by the same 2.5 every frame.
float stepFraction() { return clamp(iTime * SIM_RATE + 0.5 - float(tickAt(iTime)), 0.0, 1.0); }

float Hs(vec2 pos)   // bilinear height at a position in cells, clamped to the grid (walls)
{
    pos = clamp(pos, vec2(0.5), gridSize() - 0.5);
    vec2 h = texture(iChannel0, pos / iResolution.xy).xy;
    return GAIN * mix(h.y, h.x, stepFraction());
}

float hash21(vec2 q)
{
    q = fract(q * vec2(123.34, 456.21));
    q += dot(q, q + 45.32);
    return fract(q.x * q.y);
}

vec3 sky(vec3 r)
{
    vec3 sd = normalize(SUN_DIR);
    float up = clamp(r.z, 0.0, 1.0);
    vec3 c = mix(vec3(0.72, 0.84, 0.95), vec3(0.20, 0.42, 0.78), pow(up, 0.6));
    // a few soft streaks of cloud, fixed in direction space
    vec2 cp = r.xy / max(r.z, 0.15);
    float cl = sin(cp.x * 3.1 + sin(cp.y * 2.3)) * sin(cp.y * 4.7 + 1.3);
    c = mix(c, vec3(0.93, 0.95, 0.98), 0.25 * smoothstep(0.2, 0.9, cl));
    float s = max(dot(r, sd), 0.0);
    c += SUN_COL * (pow(s, 20000.0) * 60.0 + pow(s, 400.0) * 1.5 + pow(s, 40.0) * 0.3);
    return c;
}

// Tile albedo at a 2-D tile-space coordinate (1 unit = 1 tile); aa = one pixel
// in tile units (a constant: fwidth is not reliable inside the wall/floor branch).
vec3 tiles(vec2 t, float grout, float aa)
{
    vec2 cell = floor(t);
    vec2 f = fract(t);
    vec2 e = min(f, 1.0 - f);
    float g = smoothstep(grout - 0.5 * aa, grout + aa, min(e.x, e.y));
    float v = hash21(cell);
    vec3 tile = mix(vec3(0.80, 0.90, 0.92), vec3(0.92, 0.96, 0.97), v);
    tile *= 0.94 + 0.06 * (1.0 - length(f - 0.5));          // slight glaze
    return mix(vec3(0.50, 0.58, 0.60), tile, g);
}

vec3 floorAlbedo(vec2 q, float tileSize)
{
    vec2 t = q / tileSize;
    float aa = 1.0 / (tileSize * gridScale());        // one pixel, in tiles
    vec3 c = tiles(t, 0.03, aa);
    // lane line down the middle with a T at each end (edges antialiased)
    vec2 ext = gridSize() / tileSize;
    float mid = ext.y * 0.5;
    float xs = min(t.x - 1.6, ext.x - 1.6 - t.x);     // distance to the T bars
    float lane = min(1.0 - smoothstep(0.35 - aa, 0.35 + aa, abs(t.y - mid)),
                     smoothstep(-aa, aa, xs));
    float tbar = min(1.0 - smoothstep(1.3 - aa, 1.3 + aa, abs(t.y - mid)),
                     1.0 - smoothstep(0.18 - aa, 0.18 + aa, abs(xs)));
    float m = max(lane, tbar);
    return mix(c, c * vec3(0.10, 0.16, 0.38), m);
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

// Caustic brightness on a floor `depth` cells below the water, for the sunlight that crossed the
// surface at sc: the refracted-area rule. Sunlight bent by the surface moves a floor point by
// -alpha*depth*grad(h) (small slopes), the Jacobian is I - alpha*depth*Hessian(h), light ~ 1/|det J|.
float causticAt(vec2 sc, float depth)
{
    // Hessian of h at sc (bilinear samples)
    float k = ALPHA * depth;
    float c0 = Hs(sc);
    float hxx = Hs(sc + vec2(1, 0)) + Hs(sc - vec2(1, 0)) - 2.0 * c0;
    float hyy = Hs(sc + vec2(0, 1)) + Hs(sc - vec2(0, 1)) - 2.0 * c0;
    float hxy = 0.25 * (Hs(sc + vec2(1, 1)) + Hs(sc - vec2(1, 1))
                      - Hs(sc + vec2(1, -1)) - Hs(sc + vec2(-1, 1)));
    float det = (1.0 - k * hxx) * (1.0 - k * hyy) - k * k * hxy * hxy;
    // normalised once: flat water (det = 1) gives exactly 1
    float caustic = (1.0 + 0.12) / (abs(det) + 0.12);
    return min(caustic, 6.0);
}

// Schlick's Fresnel reflectance of water (F0 = 0.02) for the cosine of the angle of incidence.
float fresnel(float cosi)
{
    float F = 0.02 + 0.98 * pow(1.0 - cosi, 5.0);
    return F;
}

// Light on a tiled wall: sun on the walls facing it, sky light on all. `dir` is the ray that
// reached the wall (its sign tells which wall), `acrossX` whether the wall is an x = const one.
vec3 litWall(vec3 albedo, vec2 dir, bool acrossX)
{
    vec3 sd = normalize(SUN_DIR);
    bool sunny = acrossX ? (dir.x * sd.x < 0.0) : (dir.y * sd.y < 0.0);
    return albedo * (vec3(0.30, 0.38, 0.45) + 1.5 * SUN_COL * (sunny ? 0.55 : 0.1) * sd.z);
}

// What the water reflects along r (upwards) from the surface point s: the walls above the
// water up to RIM, then the sky.
vec3 reflectedScene(vec3 s, vec3 r, vec2 res, float tileSize)
{
    vec2 bound = mix(vec2(0.0), res, step(0.0, r.xy));
    vec2 rd = vec2(abs(r.x) < 1e-6 ? 1e-6 : r.x, abs(r.y) < 1e-6 ? 1e-6 : r.y);
    vec2 l = max((bound - s.xy) / rd, 0.0);
    bool acrossX = l.x < l.y;                         // meets a wall x = const first
    vec3 w = s + r * min(l.x, l.y);
    if (w.z >= RIM) return sky(r);
    float along = acrossX ? w.y : w.x;
    vec3 albedo = tiles(vec2(along, RIM - w.z) / tileSize, 0.03, 1.0 / (tileSize * gridScale())) * 0.92;
    return litWall(albedo, r.xy, acrossX);
}

#ifdef TOP_VIEW
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    // everything below is in grid cells: the picture is the grid scaled up
    vec2 res = gridSize();
    vec2 fc = fragCoord / gridScale();
    float tileSize = res.y / 11.0;

    // --- surface ---------------------------------------------------------
    float h = Hs(fc);
    float gx = 0.5 * (Hs(fc + vec2(1, 0)) - Hs(fc - vec2(1, 0)));
    float gy = 0.5 * (Hs(fc + vec2(0, 1)) - Hs(fc - vec2(0, 1)));
    vec3 n = normalize(vec3(-gx, -gy, 1.0));

    vec3 eye = vec3(0.5 * res, EYE_UP * res.y);
    vec3 s = vec3(fc, h);
    vec3 v = normalize(s - eye);

    vec3 sd = normalize(SUN_DIR);
    vec3 tl0 = refract(-sd, vec3(0, 0, 1), ETA);      // sunlight below calm water
    vec2 lightShift = tl0.xy / -tl0.z;                 // floor offset per px of depth

    // --- refracted ray: floor or wall -------------------------------------
    vec3 t = refract(v, n, ETA);
    float lam = (DEPTH + h) / -t.z;                   // distance to the floor
    // distance to the side walls along t.xy
    vec2 bound = mix(vec2(0.0), res, step(0.0, t.xy));
    vec2 td = vec2(abs(t.x) < 1e-6 ? 1e-6 : t.x, abs(t.y) < 1e-6 ? 1e-6 : t.y);
    vec2 lw = (bound - s.xy) / td;
    lw = max(lw, 0.0);
    float lwall = min(lw.x, lw.y);

    vec3 albedo;
    float light;                                      // direct sun reaching the hit
    float pathLen;
    if (lwall < lam) {
        // hit a wall: tile it in (along-wall, depth) coordinates
        vec3 w = s + t * lwall;
        float along = (lw.x < lw.y) ? w.y : w.x;
        vec2 wt = vec2(along, -w.z) / tileSize;
        albedo = tiles(wt, 0.03, 1.0 / (tileSize * gridScale())) * 0.92;
        bool sunny = (lw.x < lw.y) ? (t.x * sd.x < 0.0) : (t.y * sd.y < 0.0);
        light = sunny ? 0.55 : 0.1;
        pathLen = lwall;
    } else {
        vec2 q = s.xy + t.xy * lam;                   // floor hit
        albedo = floorAlbedo(q, tileSize);

        // where did the sunlight hitting q cross the surface?
        vec2 sc = q - lightShift * DEPTH;
        vec2 sw = q - lightShift * WALL_UP;           // top of the wall/deck line
        vec2 inside = min(sw, res - sw);
        float shade = smoothstep(-4.0, 4.0, min(inside.x, inside.y));

        float caustic = causticAt(sc, DEPTH);

        // soft darkening where floor meets walls
        vec2 dq = min(q, res - q);
        float ao = 0.72 + 0.28 * smoothstep(0.0, 0.8 * DEPTH, min(dq.x, dq.y));
        albedo *= ao;
        light = shade * caustic;
        pathLen = lam;
    }

    vec3 lit = albedo * (vec3(0.30, 0.38, 0.45) + 1.5 * SUN_COL * light * sd.z);
    // Beer-Lambert along the underwater path (plus the same distance up again
    // for the light, roughly), with in-scattering towards the water colour
    float depthM = mix(DEPTH_M.x, DEPTH_M.y, smoothstep(0.15, 0.85, fc.x / res.x));
    float metres = (pathLen + DEPTH) / DEPTH * depthM * 0.5;
    vec3 T = exp(-SIGMA * metres);
    vec3 refr = lit * T + WATER * (1.0 - T);

    // --- reflection + Fresnel ----------------------------------------------
    vec3 r = reflect(v, n);
    vec3 refl = reflectedScene(s, r, res, tileSize);
    float cosi = clamp(dot(-v, n), 0.0, 1.0);
    float F = fresnel(cosi);

    vec3 col = mix(refr, refl, F);

    // tone map + gamma
    col = 1.0 - exp(-col * 1.3);
    col = pow(col, vec3(1.0 / 2.2));
    fragColor = vec4(col + ditherNoise(fragCoord), 1.0);
}
#else
// --- The 3-D view (the default; common.glsl's camera) ---------------------------------------------
// World: y up, units of grid cells, the water plane y = 0 over the pool [0, grid.x] x [0, grid.y]
// (x, z), the floor at y = -D, the walls rising RIM above the water, a stone deck at y = RIM around.
// A sphere rests on the floor and breaks the surface. Everything is intersected analytically: the
// view ray meets the sphere, the deck, the walls above the water or the water; at the water the
// height field (interpolated between steps, as the top view) gives the normal, and Schlick's Fresnel
// mixes the reflection (sphere, walls, sky) with the refraction (floor, walls, sphere under water).
// Light under the water: the sun refracted by calm water; the floor's caustics use the refracted-area
// rule at the point where that light crossed the surface (causticAt, flat water = 1), and the sphere
// shadows the floor: the floor point's ray back towards the sun is softly occluded by the sphere
// (distance from the sphere's centre to that ray, smoothstep across 0.8-1.25 radii). The sphere's
// under-water part gets its caustic the same way.

const vec3  SPHERE_ALBEDO = vec3(0.62, 0.56, 0.50);
const vec3  DECK = vec3(0.62, 0.58, 0.52);       // stone around the pool

vec3 zUp(vec3 v) { return vec3(v.x, v.z, v.y); } // world (y up) <-> the z-up frame of sky(), SUN_DIR

// How much of the light coming from direction l reaches p past the sphere (soft: 0 inside its
// shadow, 1 beyond 1.25 radii of the shadow's axis).
float sphereOcclusion(vec3 p, vec3 l)
{
#ifdef NO_SPHERE
    return 1.0;
#else
    vec4 sp = poolSphere();
    vec3 v = sp.xyz - p;
    float along = dot(v, l);
    if (along <= 0.0) return 1.0;
    return smoothstep(0.8 * sp.w, 1.25 * sp.w, length(v - l * along));
#endif
}

// The sunlight under calm water: the direction it travels, in the world frame.
vec3 sunUnderWater() { return zUp(refract(-normalize(SUN_DIR), vec3(0, 0, 1), ETA)); }

// The caustic brightness at an under-water point p: the sunlight reaching it crossed the surface
// where the ray from p back towards the sun meets y = 0.
float causticAtPoint(vec3 p)
{
    vec3 tl = sunUnderWater();
    vec2 sc = p.xz - tl.xz / tl.y * p.y;          // tl.y < 0, p.y < 0: moves towards the sun
    return causticAt(sc, -p.y);
}

vec3 shadeSphere(vec3 p, bool underWater)
{
    vec4 sp = poolSphere();
    vec3 n = (p - sp.xyz) / sp.w;
    vec3 sd = zUp(normalize(SUN_DIR));
    vec3 amb = vec3(0.30, 0.38, 0.45) * (0.6 + 0.4 * n.y);
    float sun;
    if (underWater) sun = max(dot(n, -sunUnderWater()), 0.0) * causticAtPoint(p);
    else            sun = max(dot(n, sd), 0.0);
    return SPHERE_ALBEDO * (amb + 1.5 * SUN_COL * sun);
}

// What the light under the water shows along d from o (o on the surface): the sphere, the floor or a
// wall, lit, then Beer-Lambert absorbed along the path (plus the light's path down, roughly).
vec3 underWater(vec3 o, vec3 d, vec2 g, float tileSize)
{
    float D = POOL_DEPTH * g.y;
    vec3 sd = normalize(SUN_DIR);
    float lam = (D + o.y) / max(-d.y, 1e-4);      // to the floor
    vec2 bound = mix(vec2(0.0), g, step(0.0, d.xz));
    vec2 dd = vec2(abs(d.x) < 1e-6 ? 1e-6 : d.x, abs(d.z) < 1e-6 ? 1e-6 : d.z);
    vec2 lw = max((bound - o.xz) / dd, 0.0);
    float lwall = min(lw.x, lw.y);
    float ls = sphereHit(o, d);

    vec3 lit;
    float pathLen;
    if (ls > 0.0 && ls < min(lam, lwall)) {
        pathLen = ls;
        lit = shadeSphere(o + d * ls, true);
    } else if (lwall < lam) {
        vec3 w = o + d * lwall;
        bool acrossX = lw.x < lw.y;
        float along = acrossX ? w.z : w.x;
        vec3 albedo = tiles(vec2(along, -w.y) / tileSize, 0.03, 1.0 / (tileSize * gridScale())) * 0.92;
        bool sunny = acrossX ? (d.x * sd.x < 0.0) : (d.z * sd.y < 0.0);
        lit = albedo * (vec3(0.30, 0.38, 0.45) + 1.5 * SUN_COL * (sunny ? 0.55 : 0.1) * sd.z
                        * sphereOcclusion(w, -sunUnderWater()));
        pathLen = lwall;
    } else {
        vec3 q = o + d * lam;
        vec3 albedo = floorAlbedo(q.xz, tileSize);
        // the wall + deck on the sunny side shade a band of floor
        vec3 tl = sunUnderWater();
        vec2 sw = q.xz - tl.xz / -tl.y * (D + RIM);
        vec2 inside = min(sw, g - sw);
        float shade = smoothstep(-4.0, 4.0, min(inside.x, inside.y));
        vec2 dq = min(q.xz, g - q.xz);
        albedo *= 0.72 + 0.28 * smoothstep(0.0, 0.8 * D, min(dq.x, dq.y));
        float light = shade * causticAtPoint(q) * sphereOcclusion(q, -tl);
#ifndef NO_SPHERE
        vec4 sp = poolSphere();                   // the sphere also hides sky light near its foot
        albedo *= 1.0 - 0.45 * pow(clamp(sp.w / length(sp.xyz - q), 0.0, 1.0), 4.0);
#endif
        lit = albedo * (vec3(0.30, 0.38, 0.45) + 1.5 * SUN_COL * light * sd.z);
        pathLen = lam;
    }
    vec3 hit = o + d * pathLen;
    float depthM = mix(DEPTH_M.x, DEPTH_M.y, smoothstep(0.15, 0.85, hit.x / g.x));
    float metres = (pathLen - hit.y) / D * depthM * 0.5;
    vec3 T = exp(-SIGMA * metres);
    return lit * T + WATER * (1.0 - T);
}

// The walls above the water, the deck and the sky along d from o (o above or on the water).
vec3 aboveWater(vec3 o, vec3 d, vec2 g, float tileSize)
{
    float ls = sphereHit(o, d);
    if (ls > 0.0 && (o + d * ls).y >= 0.0) return shadeSphere(o + d * ls, false);
    vec3 sd = zUp(normalize(SUN_DIR));
    if (o.y > RIM) {                               // the camera: the deck first
        if (d.y >= 0.0) return sky(zUp(d));
        vec3 p = o + d * ((RIM - o.y) / d.y);
        if (p.x < 0.0 || p.z < 0.0 || p.x > g.x || p.z > g.y) {
            vec3 albedo = DECK * (0.9 + 0.1 * hash21(floor(p.xz / (0.5 * tileSize))));
            return albedo * (vec3(0.30, 0.38, 0.45) + 1.5 * SUN_COL * sd.y);
        }
        o = p;
    }
    return reflectedScene(zUp(o), zUp(d), g, tileSize);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 g = gridSize();
    float tileSize = g.y / 11.0;
    vec3 eye;
    vec3 d = cameraRay(fragCoord, eye);

    vec3 col;
    vec2 cell = pixelToCell(fragCoord);             // the water seen here (common.glsl), if any
    if (cell.x < 0.0) {
        col = aboveWater(eye, d, g, tileSize);
    } else {
        // the water: the surface point, its normal from the height field's differences
        vec3 s = vec3(cell.x, 0.0, cell.y);
        float gx = 0.5 * (Hs(s.xz + vec2(1, 0)) - Hs(s.xz - vec2(1, 0)));
        float gz = 0.5 * (Hs(s.xz + vec2(0, 1)) - Hs(s.xz - vec2(0, 1)));
        vec3 n = normalize(vec3(-gx, 1.0, -gz));
        vec3 r = reflect(d, n);
        r.y = max(r.y, 1e-3);
        vec3 refl = aboveWater(s, r, g, tileSize);
        vec3 refr = underWater(s, refract(d, n, ETA), g, tileSize);
        col = mix(refr, refl, fresnel(clamp(dot(-d, n), 0.0, 1.0)));
    }

    col = 1.0 - exp(-col * 1.3);
    col = pow(col, vec3(1.0 / 2.2));
    fragColor = vec4(col + ditherNoise(fragCoord), 1.0);
}
#endif
