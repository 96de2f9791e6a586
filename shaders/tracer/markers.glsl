// Marked points (the audit's example points, "show where"): a ring of 7 pixels radius around each,
// drawn over everything, so a point inside the solid or behind the plane still shows.
uniform vec3 sdfwb_markers[16];
uniform int sdfwb_markerCount;

vec3 sdfwb_drawMarkers(vec3 color) {
    float aspect = sdfwb_resolution.x / sdfwb_resolution.y;
    for (int i = 0; i < sdfwb_markerCount && i < 16; ++i) {
        vec3 v = sdfwb_markers[i] - sdfwb_cameraPosition;
        float z = dot(v, sdfwb_cameraForward);
        if (z <= sdfwb_nearPlane) continue;
        vec2 ndc = vec2(dot(v, sdfwb_cameraRight) / (z * sdfwb_tanHalfFovY * aspect), dot(v, sdfwb_cameraUp) / (z * sdfwb_tanHalfFovY));
        vec2 centre = (ndc * 0.5 + 0.5) * sdfwb_resolution;
        float d = length(SDFWB_PIXEL_CENTRE - centre);
        // a white ring with a dark rim, readable on any shading
        float ring = 1.0 - smoothstep(1.0, 2.0, abs(d - 7.0));
        float rim = 1.0 - smoothstep(1.0, 2.0, abs(d - 9.5));
        color = mix(color, vec3(0.0), 0.8 * rim);
        color = mix(color, vec3(1.0, 0.15, 0.85), ring);
    }
    return color;
}
