// Imitates: original sdf-explorer scenes in the G3D dialect that read the
// host's noise texture g3d_uniformRandom (values in [0,1]) -- here a
// cobblestone slab whose stones get a random height from texelFetch() at
// their cell index; Point3/float2/float3, lerp and saturate from the host.
//
// Why discontinuous: each 0.25-wide stone takes its height from ONE texel
// (texelFetch, no filtering), 0.06 * (texel value), so the slab's top jumps
// at every stone border by 0.06 times the difference of two neighbouring
// noise texels -- typically ~0.02, far above 1e-3, on most borders. (With
// a constant texture there would be no jump; the host's texture is noise.)
// The field stays finite (small amplitude, texel values in [0,1]) and is
// 1-Lipschitz inside each stone column; the slab is bounded.
// expect: entry=sdf flags=discontinuous animated=no

float stoneHeight(float2 cell) {
    ivec2 size = textureSize(g3d_uniformRandom, 0);
    ivec2 texel = (ivec2(cell) % size + size) % size;
    return 0.06 * saturate(texelFetch(g3d_uniformRandom, texel, 0).r);
}

float sdf(Point3 X) {
    float2 cell = floor(X.xz / 0.25);
    float top = lerp(-0.3, -0.2, 0.5) + stoneHeight(cell);   // slab top around y = -0.25
    float3 c = float3(0.0, 0.5 * (top - 0.6), 0.0);          // slab spans y in [-0.6, top]
    float3 h = float3(0.75, 0.5 * (top + 0.6), 0.75);
    float3 d = abs(X - c) - h;
    return length(max(d, 0.0)) + min(max(d.x, max(d.y, d.z)), 0.0);
}
