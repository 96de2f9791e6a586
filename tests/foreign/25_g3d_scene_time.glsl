// Imitates: an original sdf-explorer scene in the G3D dialect with its
// library split into guarded include files: lib/g3d_shapes.glsl (which
// itself includes "g3d_math.glsl" next to it) and lib/g3d_math.glsl again
// directly -- the #ifndef guard makes the second copy empty. Uses Point3,
// float3, lerp, saturate, pi and the host's g3d_SceneTime uniform; the
// entry is the explorer's `float sdf(Point3 X)`.
//
// Why the audit should find it clean: the shapes from the library are
// exact (balls, capsule, rounded box, torus) and joined with min or the
// library's polynomial smoothUnion (1-Lipschitz). g3d_SceneTime only
// enters through angles and a blend weight w in [0,1] that does not depend
// on X; lerp(a, b, w) of two 1-Lipschitz fields is then 1-Lipschitz and
// continuous. Rotations are isometries. Everything stays in the cube.
// expect: entry=sdf flags=none animated=yes

#include "lib/g3d_shapes.glsl"
#include "lib/g3d_math.glsl"

float sdf(Point3 X) {
    float t = g3d_SceneTime;

    // a lamp: base, arm, and a head that morphs between a ball and a box
    float base = roundedBoxSDF(X, Point3(0.0, -0.7, 0.0), Vector3(0.45, 0.06, 0.45), 0.03);

    Vector3 V = rotateY(X, 0.5 * t);
    float arm = capsuleSDF(V, Point3(0.0, -0.64, 0.0), Point3(0.25, 0.2, 0.0), 0.05);

    float w = saturate(0.5 + 0.5 * sin(pi * t));
    Point3 headCentre = Point3(0.25, 0.35, 0.0);
    float head = lerp(ballSDF(V, headCentre, 0.2),
                      boxSDF(V, headCentre, float3(0.16)), w);

    float ring = torusSDF(rotateX(V - headCentre, radians2(90.0)), Point3(0.0), 0.22, 0.025);

    float d = smoothUnion(base, arm, 0.08);
    d = smoothUnion(d, head, 0.06);
    return min(d, ring);
}
