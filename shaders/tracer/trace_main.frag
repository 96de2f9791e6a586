// Main of the sphere tracer: trace, then shade with the composed shading piece, which defines
// vec3 sdfwb_shade(vec3 position, vec3 normal, vec3 direction, sdfwb_Hit hit); markers
// (markers.glsl, SDFWB_MARKERS) are drawn over the result. A fragment shader, or with
// SDFWB_COMPUTE a compute shader that writes 8x8 tiles of pixels into sdfwb_target.

#ifndef SDFWB_COMPUTE
out vec4 sdfwb_color;
#endif

#ifdef SDFWB_BACKGROUND_IMAGE
uniform sampler2D sdfwb_backgroundImage;
uniform vec4 sdfwb_backgroundFit; // uv = fragCoord / resolution * xy + zw: the image covers the frame, centred
#endif

// What a ray that hits nothing shows: the background colour, or the image behind the shape.
vec3 sdfwb_missColor() {
#ifdef SDFWB_BACKGROUND_IMAGE
    vec2 uv = SDFWB_PIXEL_CENTRE / sdfwb_resolution * sdfwb_backgroundFit.xy + sdfwb_backgroundFit.zw;
    return textureLod(sdfwb_backgroundImage, vec2(uv.x, 1.0 - uv.y), 0.0).rgb; // one level (as the matcap)
#else
    return sdfwb_background;
#endif
}

vec4 sdfwb_pixel(vec3 direction) {
#if defined(SDFWB_MESH_RAYCAST)
    // A mesh's own field: one walk for the hit and its face (trace_core.glsl).
    vec3 normal;
    sdfwb_Hit hit = sdfwb_meshTrace(sdfwb_cameraPosition, direction, normal);
#elif defined(SDFWB_OUTPUT_STATS) || defined(SDFWB_PROBE) || defined(SDFWB_SHADING_STEPS) || !defined(SDFWB_FUSED_MARCH)
    sdfwb_Hit hit = sdfwb_marchRay(sdfwb_cameraPosition, direction);
#else
    // The picture: march and normal in one loop (one copy of the SDF for the driver to compile).
    vec3 normal;
    sdfwb_Hit hit = sdfwb_traceWithNormal(sdfwb_cameraPosition, direction, normal);
#endif
#ifdef SDFWB_CONES
    if (sdfwb_conePass) return sdfwb_packConeStart(sdfwb_coneEnd(hit.status, hit.t, hit.value));
#endif
#ifdef SDFWB_OUTPUT_STATS
    // Measurement output (float target): steps; the hit distance, or for a miss minus its kind
    // (-1 left the box, -2 out of steps, -3 NaN/Inf); |f| at the hit; the length of the shading
    // normal (1 unless it went NaN).
    if (hit.found) {
        vec3 normal = sdfwb_normalAt(hit.position, hit.t, hit.value, direction);
        return vec4(float(hit.steps), hit.t, abs(sdfwb_sdf(hit.position)), length(normal));
    }
    return vec4(float(hit.steps), -float(hit.status), 0.0, 0.0);
#else
#ifdef SDFWB_SHADING_STEPS
    // The heat map shows the work of every pixel, misses included.
    return vec4(sdfwb_stepsColor(hit), 1.0);
#else
#ifdef SDFWB_PLANE
    // The plane is opaque: it shows wherever it is nearer than the (possibly clipped) surface.
    float tPlane = sdfwb_intersectPlane(sdfwb_cameraPosition, direction);
    // Hits count a little before the true surface (the hit tolerance): give the plane that margin.
    if (tPlane > 0.0 && (!hit.found || tPlane <= hit.t + 2.0 * sdfwb_epsilonScale * sdfwb_pixelAngle() * tPlane + 1e-5))
        return vec4(sdfwb_planeColor(sdfwb_cameraPosition + tPlane * direction), 1.0);
#endif
    if (!hit.found) return vec4(sdfwb_missColor(), 1.0);
#if (defined(SDFWB_PROBE) || !defined(SDFWB_FUSED_MARCH)) && !defined(SDFWB_MESH_RAYCAST)
    vec3 normal = sdfwb_normalAt(hit.position, hit.t, hit.value, direction);
#endif
    vec3 color = sdfwb_shade(hit.position, normal, direction, hit);
#ifdef SDFWB_AO
    color *= sdfwb_ambientOcclusion(hit.position, normal);
#endif
    return vec4(color, 1.0);
#endif
#endif
}

#ifdef SDFWB_COMPUTE
layout(local_size_x = 8, local_size_y = 8) in;
// The caller's target itself where it is a texture of RGBA8, RGBA16F or RGBA32F (stores round as
// the fragment tracer's output would), else a float image blitted over it. No format: a
// write-only image takes the format it is bound with. Row 0 at the bottom, as a framebuffer's.
layout(binding = 0) uniform writeonly image2D sdfwb_target;

// One invocation a pixel; the tiles past the frame's edge have idle lanes. A ray that misses the
// box ends at its entry test (sdfwb_intersectBox), which is what the fragment tracer's proxy box
// saves it.
void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= int(sdfwb_resolution.x) || pixel.y >= int(sdfwb_resolution.y)) return;
    sdfwb_computePixel = vec2(pixel) + 0.5;
    vec4 color = sdfwb_pixel(sdfwb_primaryRay(sdfwb_computePixel));
#if defined(SDFWB_MARKERS) && !defined(SDFWB_OUTPUT_STATS)
    color.rgb = sdfwb_drawMarkers(color.rgb);
#endif
    imageStore(sdfwb_target, pixel, color);
}
#else
void main() {
    // The cone pass draws one fragment per tile: its ray goes through the tile's centre.
#ifdef SDFWB_CONES
    vec2 fragment = sdfwb_conePass ? (floor(gl_FragCoord.xy) + 0.5) * float(sdfwb_coneTile) : gl_FragCoord.xy;
#else
    vec2 fragment = gl_FragCoord.xy;
#endif
    sdfwb_color = sdfwb_pixel(sdfwb_primaryRay(fragment));
#if defined(SDFWB_MARKERS) && !defined(SDFWB_OUTPUT_STATS)
    if (!SDFWB_CONE_PASS) sdfwb_color.rgb = sdfwb_drawMarkers(sdfwb_color.rgb);
#endif
}
#endif
