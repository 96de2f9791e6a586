// Imitates: Shadertoy code that keeps its objects in const arrays
// (`const vec3 points[5] = vec3[](...)`), loops over them in map(), and
// returns a `struct Hit` from a helper; the loop has the well-meant "early
// out" `if (h.d < 0.0) break;` ("already inside something, stop looking").
// The same loop also breaks at a fixed count (harmless).
//
// Why discontinuous: the early out makes the answer depend on which blob
// the loop meets first, not on which is nearest. Blobs 0 and 1 overlap
// (centres 0.3 apart, radii 0.45 and 0.4). Walking along +x inside blob 1,
// just outside blob 0 the loop reaches blob 1 and returns about -0.25;
// just inside blob 0 it stops at blob 0 and returns about -0.0. So the
// field jumps (by up to ~0.25) across every part of a blob's surface that
// lies inside a later blob: about 1.7 square units in all, since all five
// blobs overlap heavily. Outside all blobs there is no break and the field
// is the plain min (1-Lipschitz). Finite, bounded.
// expect: entry=map flags=discontinuous animated=no

#define COUNT 5

struct Hit {
    float d;
    int id;
};

const vec3 points[5] = vec3[](
    vec3( 0.0,  0.0,  0.0),
    vec3( 0.3,  0.0,  0.0),
    vec3(-0.3,  0.25, 0.0),
    vec3( 0.1, -0.3,  0.25),
    vec3(-0.1,  0.1, -0.35)
);

const float radii[5] = float[](0.45, 0.4, 0.35, 0.3, 0.3);

Hit nearest(vec3 p) {
    Hit h = Hit(1e10, -1);
    for (int i = 0; i < 8; i++) {
        if (i >= COUNT) break;                // fixed count: harmless
        float d = length(p - points[i]) - radii[i];
        if (d < h.d) {
            h.d = d;
            h.id = i;
        }
        if (h.d < 0.0) break;                 // early out: NOT harmless
    }
    return h;
}

// the same loop without the early out, for comparison (not the entry)
float nearestAll(vec3 p) {
    float d = 1e10;
    for (int i = 0; i < COUNT; i++) d = min(d, length(p - points[i]) - radii[i]);
    return d;
}

float map(vec3 p) {
    return nearest(p).d;
}
