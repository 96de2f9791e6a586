// Helpers every sampler file can use. Composed after the user's SDF and before the sampler.
// Every name here carries the reserved prefix sdfwb_, so nothing in the user's SDF can clash with it.
//
// Randomness is counter-based: sdfwb_random01(index, stream) depends only on the run's seed, the
// sample's global index and a stream number the sampler chooses. No state is carried between
// samples, so a run gives the same numbers whatever the chunk size or shard.

uniform uint sdfwb_sampleCount;   // N of the whole run (not of this chunk or shard)
uniform uvec2 sdfwb_seed;         // 64-bit seed, low and high words
uniform float sdfwb_gradientStep; // central-difference step of the written gradient
uniform uint sdfwb_cubeSide;      // smallest n with n^3 >= N (computed exactly on the CPU)
uniform uint sdfwb_squareSide;    // smallest n with n^2 >= N
uniform vec4 sdfwb_parameters[4]; // free parameters for samplers driven by the program (plane analysis)
uniform float sdfwb_surfaceTolerance = 1e-5;  // sdfwb_traceRay() hits at |f| below this
uniform uint sdfwb_chunkFirst;     // global index of this chunk's first sample
uniform bool sdfwb_tetrahedralGradient = false;  // sdfwb_gradientAt(): the tracer's 4-tap scheme (benchmarks)

// The field at p (when `value` is asked for) and, when `gradient` is, its raw gradient: 6-tap
// central differences of step h (not normalised: its length shows the field's Lipschitz
// behaviour) or the tracer's 4 tetrahedron taps (sdfwb_tetrahedralGradient). A mesh's own field (SDFWB_MESH_SURFACE) without
// taps writes the exact gradient of the value's own walk.
// Every evaluation goes through one call of the field in a loop whose count is a uniform's: a
// driver inlines the field at every call site, so seven written-out calls compiled a heavy field
// seven times (a mesh's walks took seconds to compile on llvmpipe). Each tap's point is the
// written-out form's, and so is each component's sum (up to the sign of a zero).
// A field without loops (SDFWB_FIELD_WITHOUT_LOOPS, set by the composer) compiles small, and its
// calls written out run faster than the loop on cheap fields: the same points and sums, in order.
#if defined(SDFWB_FIELD_WITHOUT_LOOPS) && !defined(SDFWB_MESH_SURFACE)
float sdfwb_valueAndGradient(vec3 p, float h, bool value, bool gradient, bool taps, out vec3 result) {
    float f0 = value ? sdfwb_sdf(p) : 0.0;
    result = vec3(0.0);
    if (!gradient || !taps) return f0;
    if (sdfwb_tetrahedralGradient) {
        vec3 a = sdfwb_tetrahedronTap(0), b = sdfwb_tetrahedronTap(1), c = sdfwb_tetrahedronTap(2), d = sdfwb_tetrahedronTap(3);
        vec3 sum = vec3(0.0);
        sum += a * sdfwb_sdf(p + a * h);
        sum += b * sdfwb_sdf(p + b * h);
        sum += c * sdfwb_sdf(p + c * h);
        sum += d * sdfwb_sdf(p + d * h);
        result = sum / (4.0 * h);
    } else {
        const vec3 x = vec3(1.0, 0.0, 0.0), y = vec3(0.0, 1.0, 0.0), z = vec3(0.0, 0.0, 1.0);
        result = vec3(sdfwb_sdf(p + x * h) - sdfwb_sdf(p - x * h), sdfwb_sdf(p + y * h) - sdfwb_sdf(p - y * h),
                      sdfwb_sdf(p + z * h) - sdfwb_sdf(p - z * h)) /
                 (2.0 * h);
    }
    return f0;
}
#else
float sdfwb_valueAndGradient(vec3 p, float h, bool value, bool gradient, bool taps, out vec3 result) {
    bool tetrahedral = sdfwb_tetrahedralGradient;
    int count = !gradient || !taps ? 0 : tetrahedral ? 4 : 6;
    float f0 = 0.0;
    vec3 sum = vec3(0.0); // the taps' offsets times their values
    vec3 exact = vec3(0.0);
    for (int i = value ? 0 : 1; i <= count; ++i) {
        // Tap i: +x -x +y -y +z -z, or the tetrahedron's corner i - 1 (common/geometry.glsl).
        int axis = (i - 1) / 2;
        float side = (i & 1) == 1 ? 1.0 : -1.0;
        vec3 offset = vec3(0.0);
        if (i > 0 && !tetrahedral) offset[axis] = side;
        if (i > 0 && tetrahedral) offset = sdfwb_tetrahedronTap(i - 1);
        vec3 q = i == 0 ? p : p + offset * h;
#if defined(SDFWB_MESH_SURFACE)
        vec3 g;
        float f = sdfwb_meshSdfGradient(q, g);
        if (i == 0) exact = g;
#else
        float f = sdfwb_sdf(q);
#endif
        if (i == 0)
            f0 = f;
        else if (tetrahedral)
            sum += offset * f;
        else
            sum[axis] += side * f; // one axis: an infinite tap leaves the other two alone
    }
    if (count == 0)
        result = gradient ? exact : vec3(0.0);
    else
        result = sum / ((tetrahedral ? 4.0 : 2.0) * h);
    return f0;
}
#endif

// The raw gradient alone (see sdfwb_valueAndGradient), by taps on every field.
vec3 sdfwb_gradientAt(vec3 p, float h) {
    vec3 gradient;
    sdfwb_valueAndGradient(p, h, false, true, true, gradient);
    return gradient;
}

// 32-bit integer finaliser: xorshift-multiply rounds. The multipliers are the "lowbias32"
// constants found by Chris Wellons' hash-prospector search (public domain), which give near-ideal
// avalanche: every input bit flips every output bit with probability ~1/2.
uint sdfwb_scramble(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// Four independent uniform numbers in [0, 1) for (sample index, stream), chained through the
// seed so that different seeds give unrelated sequences. Exactly representable (24 random bits
// times 2^-24), so the positions come out the same on every IEEE-754 device.
vec4 sdfwb_random4(uint index, uint stream) {
    uint seedKey = sdfwb_scramble(sdfwb_seed.y ^ sdfwb_scramble(sdfwb_seed.x));
    uint sampleKey = sdfwb_scramble(index ^ seedKey);
    uint streamKey = sdfwb_scramble(stream * 0x9e3779b9u + sampleKey);
    uvec4 bits = uvec4(sdfwb_scramble(streamKey), sdfwb_scramble(streamKey + 0x9e3779b9u), sdfwb_scramble(streamKey + 0x3c6ef372u),
                       sdfwb_scramble(streamKey + 0xdaa66d2bu));
    return vec4(bits >> 8u) * (1.0 / 16777216.0);
}

float sdfwb_random01(uint index, uint stream) { return sdfwb_random4(index, stream).x; }

// Uniform in the cube [-1, 1]^3.
vec3 sdfwb_randomInCube(uint index, uint stream) { return sdfwb_random4(index, stream).xyz * 2.0 - 1.0; }

// Uniform on the unit sphere.
vec3 sdfwb_randomDirection(uint index, uint stream) {
    vec4 u = sdfwb_random4(index, stream);
    float z = u.x * 2.0 - 1.0;
    float azimuth = 6.28318530718 * u.y;
    float ring = sqrt(max(0.0, 1.0 - z * z));
    return vec3(ring * cos(azimuth), ring * sin(azimuth), z);
}

// Standard normal variate (Box-Muller); u.x is kept away from 0 so log() stays finite.
float sdfwb_randomGaussian(uint index, uint stream) {
    vec4 u = sdfwb_random4(index, stream);
    float radius = sqrt(-2.0 * log(max(u.x, 1e-7)));
    return radius * cos(6.28318530718 * u.y);
}

// Three independent standard normal variates (two Box-Muller pairs, one value unused).
vec3 sdfwb_randomGaussian3(uint index, uint stream) {
    vec4 u = sdfwb_random4(index, stream);
    vec2 radius = sqrt(-2.0 * log(max(u.xz, vec2(1e-7))));
    vec2 angle = 6.28318530718 * u.yw;
    return vec3(radius.x * cos(angle.x), radius.x * sin(angle.x), radius.y * cos(angle.y));
}

// Coordinate of lattice point k of n evenly spaced points covering [-1, 1] (ends included).
float sdfwb_latticeCoordinate(uint k, uint n) { return n > 1u ? -1.0 + 2.0 * float(k) / float(n - 1u) : 0.0; }

// Sphere-traces from `origin` along unit `direction` through the [-1,1]^3 box (with a margin):
// the first surface crossing inside the box, whichever side of it the ray enters on.
// On a hit, `hit` is the point with |f| < sdfwb_surfaceTolerance (1e-5 unless set).
bool sdfwb_traceRay(vec3 origin, vec3 direction, out vec3 hit) {
    const float margin = 0.05;
    vec2 span = sdfwb_intersectBox(origin, direction, 1.0 + margin);
    float t = max(span.x, 0.0);
    float tEnd = span.y;
    hit = vec3(0.0);
    for (int step = 0; step < 512 && t <= tEnd; ++step) {
        float d = sdfwb_sdf(origin + t * direction);
        if (isnan(d) || isinf(d)) return false;
        if (abs(d) < sdfwb_surfaceTolerance) {
            hit = origin + t * direction;
            return true;
        }
        // |d|: a ray whose box entry lies inside the solid (a ground plane, a shape cut by the
        // box) marches forward to where it leaves it, instead of backwards out of the box.
        t += abs(d);
    }
    return false;
}

// One sample's ray attempt: a random point in the cube seen from a random direction outside it.
bool sdfwb_traceRandomRay(uint index, uint attempt, out vec3 hit) {
    vec3 target = sdfwb_randomInCube(index, 2u * attempt) * 0.9;
    vec3 direction = sdfwb_randomDirection(index, 2u * attempt + 1u);
    vec3 origin = target - 3.0 * direction;
    return sdfwb_traceRay(origin, direction, hit);
}

// The sampler file composed next defines samplePosition(): the macro gives its definition our
// prefix, so an SDF that defines a function of that name (composed before) does not clash with it.
// sample.comp calls sdfwb_samplePosition() and #undefs the macro.
#define samplePosition sdfwb_samplePosition
