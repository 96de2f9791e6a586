/* sdfwb
name: Claw Hammer
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A claw hammer standing on its handle: a tapered, rounded handle with a grip bulge,
  and a steel head whose round striking face points to +X and whose split, curved claw
  bends down at -X (two tapered tubes along circular arcs with a notch between them).
  Exact primitives joined with min, max and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Handle: tapered, slightly flattened in z, with a swelling grip near the bottom.
    float handle = sdRoundCone(p, vec3(0.0, -0.82, 0.0), vec3(0.0, 0.45, 0.0), 0.085, 0.06);
    float grip = sdEllipsoid(p - vec3(0.0, -0.62, 0.0), vec3(0.1, 0.22, 0.1));
    handle = smoothMin(handle, grip, 0.08);

    // Head: a block around the handle top, a neck and a round striking face at +X.
    float eye = sdRoundBox(p - vec3(0.0, 0.55, 0.0), vec3(0.13, 0.14, 0.1), 0.03);
    float neck = sdRoundCone(p, vec3(0.1, 0.55, 0.0), vec3(0.45, 0.55, 0.0), 0.08, 0.09);
    float face = sdCylinderX(p - vec3(0.55, 0.55, 0.0), 0.12, 0.1) - 0.015;
    float head = smoothMin(smoothMin(eye, neck, 0.05), face, 0.04);

    // Claw: two tapered prongs curving down at -X, split by a narrow notch.
    vec3 c = p - vec3(-0.1, 0.25, 0.0);
    // Arc of radius 0.36 centred below the head, from angle 1.55 (inside the head) down to
    // 0.35 (the tip), measured from -X towards +Y; the tube tapers from 0.09 to 0.02.
    float a = safeAtan(c.y, -c.x);
    bool onArc = a >= 0.35 && a <= 1.55;
    vec2 centre = 0.36 * vec2(-cos(a), sin(a));
    float taper = mix(0.02, 0.09, (a - 0.35) / 1.2);
    float claw = onArc ? length(vec3(c.xy - centre, c.z)) - taper : 1e3;
    // End spheres are always candidates, so the field is continuous where onArc switches.
    float rootEnd = length(vec3(c.xy - 0.36 * vec2(-cos(1.55), sin(1.55)), c.z)) - 0.09;
    float tipEnd = length(vec3(c.xy - 0.36 * vec2(-cos(0.35), sin(0.35)), c.z)) - 0.02;
    claw = min(claw, min(rootEnd, tipEnd));
    // The taper changes the radius by 0.07 over an arc length of 0.43: slope 0.16.
    claw /= 1.16;
    claw = max(claw, -(abs(p.z) - 0.015));                   // the V-notch
    head = smoothMin(head, claw, 0.04);
    return min(handle, head);
}
