/* sdfwb
name: Snail
category: Animal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A garden snail crawling towards +X. The shell is a tube swept along a logarithmic
  spiral (each turn twice the size of the one inside it, the tube radius a fixed fraction of
  the spiral radius, so neighbouring whorls touch), coiled in the XY plane on the snail's back.
  The body is a long tapered foot with a raised head and two eye stalks.
  The audit measures it as truncated at 0.05: inside the shell's envelope the whorl field is
  capped at that margin (see BOUNDED_PART), which leaves plateaus of f = 0.05 near the coil
  axis. Those plateaus are a bound, so the field stays conservative.
  The spiral tube is measured in polar coordinates; the angle term adds at most about 0.6 to
  the gradient, so the tube field is divided by 1.2 (1-Lipschitz, conservative). The open
  end and a core bead are separate candidates so the field stays continuous. Unions and
  smooth unions keep it conservative.
*/
#include "../lib/modelling.glsl"

const float SHELL_MAX_RADIUS = 0.42;   // spiral radius at the aperture
const float SHELL_GROWTH = 0.1103178;  // ln(2) / (2 pi): the spiral doubles every turn
const float SHELL_TUBE = 0.42;         // tube radius / spiral radius
const float SHELL_MIN_PHI = -18.85;    // three turns in from the aperture (phi = 0)

// Distance to the spiral tube at spiral angle phi (<= 0), measured in the point's own
// half plane through the coil axis. Below the innermost turn the tube is held at its
// smallest size, which the core bead swallows.
float whorl(float r, float z, float phi) {
    float spiral = SHELL_MAX_RADIUS * exp(SHELL_GROWTH * max(phi, SHELL_MIN_PHI));
    return length(vec2(r - spiral, z)) - SHELL_TUBE * spiral;
}

float shell(vec3 p) {
    float r = length(p.xy);
    float theta = safeAtan(p.y, p.x);
    // In the half plane at angle theta the whorls are circles of radius k*R centred at
    // r = R; their distance sqrt((r-R)^2 + z^2) - k*R is convex in R with its minimum at
    // R* = r + k|z|/sqrt(1-k^2). So the nearest whorl is one of the two whose R brackets R*,
    // and the candidates only swap where they are equally near: the field stays continuous.
    float rStar = r + SHELL_TUBE * abs(p.z) / sqrt(1.0 - SHELL_TUBE * SHELL_TUBE);
    float turns = (log(max(rStar, 1e-4) / SHELL_MAX_RADIUS) / SHELL_GROWTH - theta) / MODEL_TAU;
    // Whorls past the aperture (phi > 0) do not exist: the last one is whorl 0 below angle 0.
    float top = theta > 0.0 ? -1.0 : 0.0;
    float n0 = min(floor(turns), top);
    float n1 = min(floor(turns) + 1.0, top);
    float d = min(whorl(r, p.z, theta + MODEL_TAU * n0), whorl(r, p.z, theta + MODEL_TAU * n1));
    // Rounded open end of the outermost whorl (at angle 0), always a candidate so that the
    // field stays continuous where the candidates above switch (it equals whorl 0 there).
    float mouth = length(vec3(p.x - SHELL_MAX_RADIUS, p.y, p.z)) - SHELL_TUBE * SHELL_MAX_RADIUS;
    // The angle term of the whorl field adds up to about 0.3 to its gradient away from the
    // coil axis: divide it out.
    d = min(d, mouth) / 1.2;
    // The tiny innermost whorls are filled by a small core bead.
    d = min(d, length(p) - 0.08);
    // Near the coil axis the angle term grows without bound; there the field is well above
    // the margin, so evaluating it only inside the shell's envelope disc and capping it at the
    // margin (see BOUNDED_PART) removes those points while keeping the field continuous.
    float envelope = sdCylinderZ(p, SHELL_MAX_RADIUS * (1.0 + SHELL_TUBE), SHELL_TUBE * SHELL_MAX_RADIUS);
    return BOUNDED_PART(envelope, 0.05, d);
}

float sdf(vec3 p) {
    // Shell on the back; rotated so the aperture opens downwards and forwards.
    vec3 s = p - vec3(-0.12, 0.04, 0.0);
    s.xy = rotate2(s.xy, 1.9);
    float sh = shell(s);

    // Foot: a long tapered slug body along the ground.
    float foot = sdRoundCone(p, vec3(0.42, -0.55, 0.0), vec3(-0.78, -0.62, 0.0), 0.17, 0.07);
    foot = max(foot, -0.7 - p.y);                          // flat sole
    // Neck and head rising at the front.
    float neck = sdRoundCone(p, vec3(0.42, -0.5, 0.0), vec3(0.6, -0.2, 0.0), 0.17, 0.13);
    float body = smoothMin(foot, neck, 0.1);

    // Eye stalks with bulbs, mirrored through z = 0; short feelers below them.
    vec3 m = vec3(p.x, p.y, abs(p.z));
    float stalk = sdRoundCone(m, vec3(0.6, -0.15, 0.05), vec3(0.78, 0.16, 0.11), 0.035, 0.02);
    float bulb = sdSphere(m - vec3(0.785, 0.17, 0.11), 0.045);
    float feeler = sdRoundCone(m, vec3(0.68, -0.28, 0.06), vec3(0.83, -0.38, 0.1), 0.03, 0.015);
    body = smoothMin(body, min(stalk, feeler), 0.03);
    body = min(body, bulb);

    return smoothMin(body, sh, 0.03);
}
