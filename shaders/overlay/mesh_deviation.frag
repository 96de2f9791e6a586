// Mesh overlay, per pixel: the field at the mesh's own point under the pixel (not at its
// vertices: a flat triangle strays most in its middle). For an exact field |f| is the mesh's
// distance from the true surface. Light grey where the mesh lies on the surface, red where it
// sits outside (f > 0), blue where inside, full colour at sdfwb_deviationScale and beyond;
// magenta where the field is not finite. Shaded by the facet's own normal (a headlight), so the
// facets stay visible.
in vec3 sdfwb_world;
out vec4 sdfwb_color;

uniform float sdfwb_deviationScale;
uniform vec3 sdfwb_cameraPosition;

void main() {
    float f = sdfwb_sdf(sdfwb_world);
    vec3 facet = cross(dFdx(sdfwb_world), dFdy(sdfwb_world));
    vec3 toEye = normalize(sdfwb_cameraPosition - sdfwb_world);
    float facing = dot(facet, facet) > 0.0 ? abs(dot(normalize(facet), toEye)) : 1.0;
    float light = 0.3 + 0.7 * facing;
    vec3 colour;
    if (isnan(f) || isinf(f)) {
        colour = vec3(1.0, 0.0, 1.0);
    } else {
        float s = clamp(abs(f) / sdfwb_deviationScale, 0.0, 1.0);
        vec3 far = f > 0.0 ? vec3(0.9, 0.12, 0.08) : vec3(0.1, 0.3, 0.95);
        colour = mix(vec3(0.85), far, sqrt(s));
    }
    sdfwb_color = vec4(colour * light, 1.0);
}
