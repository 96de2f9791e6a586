/* sdfwb
name: Swaying Tree
category: Nature
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A broadleaf tree bending in the wind (period 4 s): a tapered trunk that forks into
  two branches under a lumpy crown (an ellipsoid with ten
  spheres blended on), on a small mound of earth. The sway
  shifts x by s(y, t) = A sin(wt) ((y + 0.86) / 1.8)^2, a shear whose slope |ds/dy| stays
  below 0.14; the field is divided by 1.14 to keep its gradient under 1. Unions and smooth
  unions make it conservative.
*/
#include "../lib/modelling.glsl"

float tree(vec3 p) {
    // Trunk with a flared foot, forking into two branches.
    float trunk = sdRoundCone(p, vec3(0.0, -0.82, 0.0), vec3(0.0, -0.05, 0.0), 0.16, 0.1);
    float branchA = sdRoundCone(p, vec3(0.0, -0.15, 0.0), vec3(0.28, 0.2, 0.1), 0.07, 0.04);
    float branchB = sdRoundCone(p, vec3(0.0, -0.2, 0.0), vec3(-0.25, 0.15, -0.12), 0.065, 0.04);
    float wood = smoothMin(trunk, min(branchA, branchB), 0.05);

    // Crown: ten overlapping leafy clumps, blended just enough to read as one bumpy cloud.
    const vec4 clumps[10] = vec4[10](
        vec4(0.0, 0.35, 0.0, 0.36), vec4(0.32, 0.22, 0.15, 0.25), vec4(-0.33, 0.25, -0.12, 0.26),
        vec4(0.12, 0.2, 0.36, 0.24), vec4(-0.15, 0.22, -0.35, 0.24), vec4(0.05, 0.62, 0.05, 0.24),
        vec4(0.28, 0.48, -0.18, 0.22), vec4(-0.25, 0.5, 0.2, 0.22), vec4(-0.3, 0.15, 0.28, 0.2),
        vec4(0.32, 0.12, -0.25, 0.2));
    float crown = sdEllipsoid(p - vec3(0.0, 0.32, 0.0), vec3(0.55, 0.42, 0.55));
    for (int i = 0; i < 10; ++i)
        crown = smoothMin(crown, sdSphere(p - clumps[i].xyz, clumps[i].w), 0.1);
    return min(wood, crown);
}

float sdf(vec3 p, float time) {
    // Ground mound: a flattened ellipsoid the tree stands in (does not sway).
    float mound = sdEllipsoid(p - vec3(0.0, -0.86, 0.0), vec3(0.45, 0.08, 0.45));
    // Bend: a horizontal shift growing with the square of the height above the ground.
    float h = clamp((p.y + 0.86) / 1.8, 0.0, 1.0);
    float shift = 0.12 * sin(6.2831853 * time / 4.0) * h * h;
    float t = tree(vec3(p.x - shift, p.y, p.z)) / 1.14;
    return max(smoothMin(t, mound, 0.06), -0.9 - p.y);      // flat underneath
}
