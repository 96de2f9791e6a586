// Fragment main of the sphere tracer: trace, then shade with the composed shading piece, which
// defines vec3 shade(vec3 position, vec3 normal, vec3 direction, Hit hit).

out vec4 o_color;

void main() {
    vec3 direction = primaryRay(gl_FragCoord.xy);
    Hit hit = traceRay(u_cameraPosition, direction);
#ifdef SDFWB_OUTPUT_STATS
    // Measurement output (float target): steps; the hit distance, or for a miss minus its kind
    // (-1 left the box, -2 out of steps, -3 NaN/Inf); |f| at the hit; the length of the shading
    // normal (1 unless it went NaN).
    if (hit.found) {
        vec3 normal = normalAt(hit.position, hit.t, direction);
        o_color = vec4(float(hit.steps), hit.t, abs(map(hit.position)), length(normal));
    } else {
        o_color = vec4(float(hit.steps), -float(hit.status), 0.0, 0.0);
    }
    return;
#endif
#ifdef SDFWB_SHADING_STEPS
    // The heat map shows the work of every pixel, misses included.
    o_color = vec4(stepsColor(hit), 1.0);
    return;
#else
#ifdef SDFWB_PLANE
    // The plane is opaque: it shows wherever it is nearer than the (possibly clipped) surface.
    float tPlane = intersectPlane(u_cameraPosition, direction);
    // Hits count a little before the true surface (the hit tolerance): give the plane that margin.
    if (tPlane > 0.0 && (!hit.found || tPlane <= hit.t + 2.0 * u_epsilonScale * pixelAngle() * tPlane + 1e-5)) {
        o_color = vec4(planeColor(u_cameraPosition + tPlane * direction), 1.0);
        return;
    }
#endif
    if (!hit.found) {
        o_color = vec4(u_background, 1.0);
        return;
    }
    vec3 normal = normalAt(hit.position, hit.t, direction);
    vec3 color = shade(hit.position, normal, direction, hit);
#ifdef SDFWB_AO
    color *= ambientOcclusion(hit.position, normal);
#endif
    o_color = vec4(color, 1.0);
#endif
}
