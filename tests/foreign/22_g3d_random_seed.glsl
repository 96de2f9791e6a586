// Imitates: original sdf-explorer scenes in the G3D dialect (Point3 X,
// float3, lerp, no #version) that use the host's noise texture
// g3d_uniformRandom as a source of per-scene random constants: a few texels
// at FIXED coordinates pick the sizes of three pebbles. Both texelFetch()
// and texture() at a constant coordinate are used.
//
// Why the audit should find it clean: the texture is read at positions
// that do not depend on X, so the "random" numbers are constants for the
// whole field (texel values are in [0,1], mapped to radii in [0.12, 0.3]).
// The field is then a union (min) of three exact balls and an exact box:
// continuous, 1-Lipschitz, finite, bounded inside the cube.
// expect: entry=sdf flags=none animated=no

float3 pebbleRadii() {
    ivec2 size = textureSize(g3d_uniformRandom, 0);
    float a = texelFetch(g3d_uniformRandom, ivec2(3, 7) % size, 0).r;
    float b = texelFetch(g3d_uniformRandom, ivec2(11, 2) % size, 0).g;
    float c = texture(g3d_uniformRandom, float2(0.37, 0.81)).b;
    return lerp(float3(0.12), float3(0.3), clamp(float3(a, b, c), 0.0, 1.0));
}

float sdf(Point3 X) {
    float3 r = pebbleRadii();
    float d = length(X - Point3(-0.45, -0.2, 0.1)) - r.x;
    d = min(d, length(X - Point3(0.05, -0.2, -0.3)) - r.y);
    d = min(d, length(X - Point3(0.5, -0.2, 0.25)) - r.z);

    // the tray they lie on
    float3 q = abs(X - Point3(0.0, -0.55, 0.0)) - float3(0.85, 0.05, 0.65);
    float tray = length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
    return min(d, tray);
}
