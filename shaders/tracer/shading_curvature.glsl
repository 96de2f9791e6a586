// Absolute mean curvature |H|, black (flat) to red (curved). For a distance field the mean
// curvature is half the Laplacian; its 7-tap estimate uses a step of a few pixel footprints,
// so the picture does not turn to noise up close.
uniform float sdfwb_curvatureScale;  // |H| that maps to full red

vec3 sdfwb_shade(vec3 position, vec3 normal, vec3 direction, sdfwb_Hit hit) {
    float h = max(4.0 * sdfwb_pixelAngle() * hit.t, 1e-4);
    float center = sdfwb_sdf(position);
    float laplacian = (sdfwb_sdf(position + vec3(h, 0, 0)) + sdfwb_sdf(position - vec3(h, 0, 0)) + sdfwb_sdf(position + vec3(0, h, 0)) +
                       sdfwb_sdf(position - vec3(0, h, 0)) + sdfwb_sdf(position + vec3(0, 0, h)) + sdfwb_sdf(position - vec3(0, 0, h)) - 6.0 * center) / (h * h);
    float curvature = abs(0.5 * laplacian);
    float value = clamp(curvature / sdfwb_curvatureScale, 0.0, 1.0);
    // A little shape cue so flat regions are not a featureless black.
    float light = 0.08 + 0.1 * max(dot(normal, -direction), 0.0);
    return vec3(max(value, light), light * (1.0 - value), light * (1.0 - value));
}
