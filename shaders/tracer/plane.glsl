// Cutting plane: dot(n, p) = offset, drawn as in the paper: a thick black zero contour, thin
// isocontours every sdfwb_contourSpacing, outside a yellow-to-blue ramp with distance, inside solid
// orange. Lines are anti-aliased with screen-space derivatives, so they keep a constant width.
// Overlays (SDFWB_PLANE_LIPSCHITZ): red where |grad f| > 1 beyond tolerance, grey where it is ~0
// away from the surface; NaN/Inf is always magenta. A mesh SDF's uncertain sign is hatched violet.

uniform vec3 sdfwb_planeNormal;       // unit
uniform float sdfwb_planeOffset;
uniform float sdfwb_contourSpacing;   // isocontour spacing (1/64 by default)
uniform float sdfwb_rampDistance;     // distance at which the outside ramp reaches full blue

// How much the field f at plane point p changes from one pixel to the next. A mesh's field leaves
// its helper lanes unevaluated (mesh_field.glsl), so fwidth(f) would read their placeholder values
// along every primitive's edge. A mesh's field is a distance (|grad f| = 1): with the gradient in
// the plane at a uniform angle to the pixel grid, |df/dx| + |df/dy| averages 4/pi times a pixel's
// side on the plane, which stands in.
float sdfwb_fieldPerPixel(float f, vec3 p) {
#ifdef SDFWB_MESH_FRAGMENT
    return max(0.5 * (length(dFdx(p)) + length(dFdy(p))) * 1.2732395, 1e-9);
#else
    return max(fwidth(f), 1e-9);
#endif
}

// Coverage in [0, 1] of a line of `widthPixels` at the zeros of `value` (value's units change by
// perPixel per pixel).
float sdfwb_lineCoverage(float value, float perPixel, float widthPixels) {
    return 1.0 - smoothstep(0.5 * widthPixels - 0.5, 0.5 * widthPixels + 0.5, abs(value) / perPixel);
}

vec3 sdfwb_planeColor(vec3 p) {
#ifdef SDFWB_PLANE_FIELD
    vec2 field = sdfwb_planeFieldAt(p); // a mesh's own field, computed once per plane (trace_core.glsl)
    float f = field.x;
#else
    float f = sdfwb_sdf(p);
#endif
    float fPerPixel = sdfwb_fieldPerPixel(f, p); // before any return: derivatives need the whole quad
    if (isnan(f) || isinf(f)) return vec3(1.0, 0.0, 1.0);
    vec3 color;
    if (f < 0.0) {
        color = vec3(0.93, 0.55, 0.18);  // inside: solid orange
    } else {
        float x = clamp(f / sdfwb_rampDistance, 0.0, 1.0);
        color = mix(vec3(0.98, 0.9, 0.35), vec3(0.15, 0.3, 0.75), sqrt(x));
        // isocontours every spacing (outside only, as in the paper)
        float phase = f / sdfwb_contourSpacing;
        float contour = phase - floor(phase + 0.5);
        float perPixel = fPerPixel / sdfwb_contourSpacing;
        float thin = 1.0 - smoothstep(0.25, 1.0, abs(contour) / perPixel);
        // fade contours out where they would be denser than ~3 pixels apart
        thin *= clamp(1.0 / (perPixel * 3.0), 0.0, 1.0);
        color = mix(color, vec3(0.12), 0.7 * thin);
    }
#ifdef SDFWB_PLANE_LIPSCHITZ
    const float h = 1e-3;
    vec3 g = vec3(sdfwb_sdf(p + vec3(h, 0, 0)) - sdfwb_sdf(p - vec3(h, 0, 0)), sdfwb_sdf(p + vec3(0, h, 0)) - sdfwb_sdf(p - vec3(0, h, 0)),
                  sdfwb_sdf(p + vec3(0, 0, h)) - sdfwb_sdf(p - vec3(0, 0, h))) / (2.0 * h);
    float slope = length(g);
    if (isnan(slope) || isinf(slope)) return vec3(1.0, 0.0, 1.0);
    if (slope > 1.02) color = mix(color, vec3(0.9, 0.05, 0.05), clamp((slope - 1.02) * 4.0 + 0.35, 0.0, 0.85));
    else if (slope < 0.05 && abs(f) > 4.0 * sdfwb_contourSpacing) color = mix(color, vec3(0.55), 0.8);
#endif
#ifdef SDFWB_MESH_NODES_BINDING
    // A triangle mesh's field: violet hatching where its winding number is within 1/4 of 1/2, where
    // the mesh is open or overlaps itself and inside or outside is a guess (the audit's
    // sign-uncertain flag counts the same points).
#ifdef SDFWB_PLANE_FIELD
    float winding = field.y;
#else
    float winding = sdfwb_meshWinding(p);
#endif
    if (abs(winding - 0.5) < 0.25) {
        float stripe = step(4.0, mod(SDFWB_PIXEL_CENTRE.x + SDFWB_PIXEL_CENTRE.y, 8.0));
        color = mix(color, vec3(0.55, 0.2, 0.85), 0.3 + 0.4 * stripe);
    }
#endif
    // the zero contour: thick and black
    color = mix(color, vec3(0.0), sdfwb_lineCoverage(f, fPerPixel, 3.0));
    return color;
}

// Distance along the ray to the plane inside the [-1,1]^3 box, or -1.
float sdfwb_intersectPlane(vec3 origin, vec3 direction) {
    float denominator = dot(direction, sdfwb_planeNormal);
    if (abs(denominator) < 1e-8) return -1.0;
    float t = (sdfwb_planeOffset - dot(origin, sdfwb_planeNormal)) / denominator;
    if (t <= 0.0) return -1.0;
    vec3 p = origin + t * direction;
    return all(lessThanEqual(abs(p), vec3(1.0 + sdfwb_boxMargin))) ? t : -1.0;
}
