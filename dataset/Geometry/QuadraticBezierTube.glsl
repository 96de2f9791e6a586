/* sdfwb
name: Quadratic Bezier Tube
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Tube of radius 0.14 around a quadratic Bezier arch (a parabola arc, so a planar curve,
  here tilted to face the +X side). The nearest curve parameter makes the derivative of the squared distance
  vanish, a cubic in t, solved in closed form (Cardano's formula with one real root, the
  trigonometric form with three), polished by a Newton step and clamped to [0, 1]; the least of
  the candidate distances is the exact distance to the arc. Subtracting the radius is exact
  inside too because the radius is below the arc's smallest radius of curvature (about 0.36) and the
  arc never comes back near itself. Parameters: radius (0.03-0.18).
*/
uniform float radius = 0.14;  // @range 0.03 0.18 @step 0.01 @label "Tube radius"


// Real cube root that accepts negative arguments.
float cubeRoot(float x) { return sign(x) * pow(abs(x), 1.0 / 3.0); }

// Exact distance from p to the quadratic Bezier curve start -> (control) -> end.
float bezierDistance(vec3 p, vec3 start, vec3 control, vec3 end) {
    // B(t) = start + 2t * toControl + t^2 * bend
    vec3 toControl = control - start;
    vec3 bend = start - 2.0 * control + end;
    vec3 fromPoint = start - p;
    // (B(t) - p) . B'(t) = 0, divided by |bend|^2: t^3 + k2 t^2 + k1 t + k0 = 0.
    float inverseBend = 1.0 / dot(bend, bend);
    float k2 = 3.0 * dot(toControl, bend) * inverseBend;
    float k1 = (2.0 * dot(toControl, toControl) + dot(fromPoint, bend)) * inverseBend;
    float k0 = dot(fromPoint, toControl) * inverseBend;
    // Substitute t = x - k2 / 3 to remove the square term: x^3 + a x + b = 0.
    float a = k1 - k2 * k2 / 3.0;
    float b = k2 * (2.0 * k2 * k2 - 9.0 * k1) / 27.0 + k0;
    float discriminant = 0.25 * b * b + a * a * a / 27.0;

    // Candidate parameters: the local minima of the squared distance (the clamping below also
    // yields the ends, which is where any minimum over [0, 1] that is not a root must lie).
    vec2 candidates;
    if (discriminant >= 0.0) {
        // One real root (Cardano).
        float s = sqrt(discriminant);
        candidates = vec2(cubeRoot(-0.5 * b + s) + cubeRoot(-0.5 * b - s));
    } else {
        // Three real roots 2m cos(phi/3 - 2 pi k/3), m = sqrt(-a/3). The middle one (k = 1) is a
        // local maximum of the squared distance, so only the largest (k = 0) and smallest (k = 2) count.
        float m = sqrt(-a / 3.0);
        float phi = acos(clamp(-b / (2.0 * max(m * m * m, 1e-30)), -1.0, 1.0));
        candidates = 2.0 * m * cos(vec2(phi, phi + 6.2831853) / 3.0);
    }
    candidates -= k2 / 3.0;

    float best = 1e10;
    for (int i = 0; i < 2; ++i) {
        float t = candidates[i];
        // One Newton step on the cubic recovers the precision lost to cancellation.
        float value = ((t + k2) * t + k1) * t + k0;
        float slope = (3.0 * t + 2.0 * k2) * t + k1;
        if (abs(slope) > 1e-12) t -= value / slope;
        t = clamp(t, 0.0, 1.0);
        best = min(best, length(fromPoint + (2.0 * toControl + bend * t) * t));
    }
    return best;
}

float sdf(vec3 p) {
    const vec3 start = vec3(-0.47, -0.73, 0.78);
    const vec3 control = vec3(-0.37, 1.78, 0.03);
    const vec3 end = vec3(0.62, -0.59, -0.66);
    return bezierDistance(p, start, control, end) - radius;
}
