/* sdfwb
name: Hex Bolt and Nut
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A hexagon-head bolt standing on its head with a real helical thread and a hex nut
  part-way down. The thread is a triangular profile swept along a helix: the radius of the
  shank varies with u = fract((y + pitch * angle / 2pi) / pitch). Its slopes (0.8 along the
  axis, at most 0.09 around it, the tooth fading out inside the core) and the radial term
  are orthogonal, giving a gradient of at most 1.29, so the threaded field is divided by 1.3. Hexagons are slab intersections
  with chamfers: bounds. Conservative.
*/
#include "../lib/modelling.glsl"

const float PITCH = 0.1;
const float THREAD_DEPTH = 0.04;
const float CORE_RADIUS = 0.15;

// Threaded rod along Y between y0 and y1, with a chamfered tip at y1.
float threadedRod(vec3 p, float y0, float y1) {
    float r = length(p.xz);
    float angle = safeAtan(p.z, p.x);
    float u = fract((p.y + PITCH * angle / MODEL_TAU) / PITCH);
    float tooth = 1.0 - 2.0 * abs(u - 0.5);                 // triangle wave 0..1
    // The tooth fades out towards the axis (r < CORE_RADIUS is solid anyway): otherwise the
    // angle term, which scales with 1/r, would blow up near the axis.
    float depth = THREAD_DEPTH * clamp((r - 0.05) / (CORE_RADIUS - 0.05), 0.0, 1.0);
    float thread = (r - CORE_RADIUS - depth * tooth) / 1.3;
    float ends = max(y0 - p.y, p.y - y1);
    float chamfer = (r + (p.y - y1) - CORE_RADIUS) * 0.7071;   // 45 degree chamfer at the tip
    return max(max(thread, ends), chamfer);
}

// Hexagonal prism along Y (apothem r, half height h) with both rims chamfered.
float hexBlock(vec3 p, float r, float h) {
    float hex = sdHexPrismY(p, r, h);
    float chamfer = (length(p.xz) + abs(p.y) - r * 1.12 - h) * 0.7071;
    return max(hex, chamfer);
}

float sdf(vec3 p) {
    // Head at the bottom, shank rising to +Y (it stands on its head).
    float head = hexBlock(p - vec3(0.0, -0.72, 0.0), 0.36, 0.12);
    float washer = sdCylinder(p - vec3(0.0, -0.58, 0.0), 0.34, 0.02);
    // The thread runs the whole visible shank; bounding cylinder keeps it cheap far away.
    vec3 s = p;
    float bound = sdCylinder(s - vec3(0.0, 0.1, 0.0), CORE_RADIUS + THREAD_DEPTH + 0.01, 0.72);
    float rod = BOUNDED_PART(bound, 0.05, threadedRod(s, -0.6, 0.8));

    // Nut threaded on part-way: a hex block with a bore (the rod fills the bore).
    float nut = hexBlock(p - vec3(0.0, 0.1, 0.0), 0.32, 0.12);
    nut = max(nut, -sdCylinder(p - vec3(0.0, 0.1, 0.0), CORE_RADIUS + 0.02, 0.2));
    return min(min(head, washer), min(rod, nut));
}
