/* sdfwb
name: Helix
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Tube of radius 0.13 around a three-turn helix of radius 0.68 about the Y axis, rising from
  y = -0.68 to 0.68 (both ends at the back, towards -X). Along the helix parameter the squared
  distance is g(u) = rho^2 + R^2 - 2 rho R cos u + (y' - c u)^2; it is convex wherever
  cos u > -c^2 / (rho R), one window per turn, and has no local minimum outside those windows.
  Each window that meets the curve is minimised by Newton's method, started at the minimum of a
  quadratic model and kept inside a shrinking bracket (checked against dense sampling: converged
  to float precision); windows whose height range alone is farther than the best distance so far
  are skipped, and the two ends are checked too, so the least value is the exact distance to the
  curve. The tube radius is far below the curvature radius (about 0.69) and half the coil spacing
  (about 0.22), so the tube is exact inside too. Parameters: tube radius (0.03-0.18).
*/
uniform float tubeRadius = 0.13;  // @range 0.03 0.18 @step 0.01 @label "Tube radius"

float sdf(vec3 p) {
    const float coilRadius = 0.68;
    const float halfTurns = 3.0;              // the parameter runs over [-3 pi, 3 pi]: three turns
    const float rise = 0.68 / (3.0 * 3.14159265);  // height gained per radian
    const float pi = 3.14159265;
    const float tau = 6.2831853;

    float rho = length(p.xz);
    float theta = rho > 1e-7 ? atan(p.z, p.x) : 0.0;
    // Helix point at parameter s: (R cos s, rise s, R sin s). Write s = theta + u; then the
    // squared distance is rho^2 + R^2 - 2 rho R cos u + (lift - rise u)^2 with:
    float lift = p.y - rise * theta;
    float rhoR = rho * coilRadius;
    float uMin = -halfTurns * pi - theta;
    float uMax = halfTurns * pi - theta;

    // Half width of the convex window around each multiple of 2 pi.
    float halfWindow = acos(clamp(-rise * rise / max(rhoR, 1e-12), -1.0, 1.0));

    // The two ends of the curve.
    vec3 startPoint = vec3(-coilRadius, -halfTurns * pi * rise, 0.0);
    vec3 endPoint = vec3(-coilRadius, halfTurns * pi * rise, 0.0);
    float best = min(length(p - startPoint), length(p - endPoint));

    // Windows are centred on u = 2 pi k; at most five meet the curve for three turns.
    int firstWindow = int(ceil((uMin - halfWindow) / tau));
    for (int i = 0; i < 5; ++i) {
        float centre = tau * float(firstWindow + i);
        float lo = max(centre - halfWindow, uMin);
        float hi = min(centre + halfWindow, uMax);
        if (lo > hi) continue;
        // Lower bound from the height difference alone: skip windows that cannot win.
        float heightGap = max(max(rise * lo - lift, lift - rise * hi), 0.0);
        if (heightGap >= best) continue;

        // Half the derivative of g: increasing across the window because g is convex there.
        float slopeLo = rhoR * sin(lo) - rise * (lift - rise * lo);
        float slopeHi = rhoR * sin(hi) - rise * (lift - rise * hi);
        float u;
        if (slopeLo >= 0.0) u = lo;
        else if (slopeHi <= 0.0) u = hi;
        else {
            // Start from the minimum of the quadratic model of g about the window centre; from
            // there Newton reaches float precision in two or three steps (four for margin).
            u = clamp(centre + rise * (lift - rise * centre) / (rhoR + rise * rise), lo, hi);
            for (int iteration = 0; iteration < 4; ++iteration) {
                float slope = rhoR * sin(u) - rise * (lift - rise * u);
                if (slope > 0.0) hi = u; else lo = u;
                float curvature = rhoR * cos(u) + rise * rise;
                float next = u - slope / max(curvature, 1e-12);
                // Keep the iterate inside the bracket: bisect when Newton leaves it, but clamp a
                // step that only rounding pushed past a bracket end (after convergence).
                bool leaves = next < lo - 1e-4 || next > hi + 1e-4;
                u = leaves ? 0.5 * (lo + hi) : clamp(next, lo, hi);
            }
        }
        float s = theta + u;
        vec3 onCurve = vec3(coilRadius * cos(s), rise * s, coilRadius * sin(s));
        best = min(best, length(p - onCurve));
    }
    return best - tubeRadius;
}
