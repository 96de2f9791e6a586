// Gooch warm/cool shading with wrap lighting: surfaces facing the key light are warm, those
// facing away cool, with a soft wrap so no part goes black; a little rim light shows silhouettes.
uniform vec3 sdfwb_lightDirection;  // unit, towards the light, world space

vec3 sdfwb_shade(vec3 position, vec3 normal, vec3 direction, sdfwb_Hit hit) {
    const vec3 warm = vec3(0.85, 0.55, 0.25);
    const vec3 cool = vec3(0.12, 0.22, 0.48);
    const vec3 base = vec3(0.62, 0.62, 0.6);
    float wrap = 0.5 + 0.5 * dot(normal, sdfwb_lightDirection);  // wrap lighting: [-1, 1] -> [0, 1]
    vec3 color = mix(cool + 0.2 * base, warm + 0.3 * base, wrap);
    vec3 halfway = normalize(sdfwb_lightDirection - direction);
    color += 0.25 * pow(max(dot(normal, halfway), 0.0), 40.0);
    color += 0.15 * pow(1.0 - max(dot(normal, -direction), 0.0), 3.0);
    // No upper clamp: highlights above 1 reach float targets (.exr); 8-bit targets clamp on write.
    return max(color, 0.0);
}
