// Imitates: a file for the original sdf-explorer in its G3D dialect (Point3, float3, saturate and
// the prelude's `pi` used without declaring them), where one helper happens to name a local
// variable `pi` (a "point i" in a loop over control points) while the SDF itself uses the
// prelude's constant. A detector that looked for any declaration of `pi` anywhere would think the
// file defines it and drop the prelude's, and sdf() would not compile.
//
// Why the audit should find it clean: the shape is a capsule chain through three control points
// (the exact distance to a polyline, minus a radius), unioned with a sphere whose radius is
// 0.1 * pi; min of exact distances is exact, so |grad| <= 1, continuous, no plateau.
// expect: entry=sdf flags=none animated=no

float segmentDistance(Point3 X, Point3 a, Point3 b) {
    float3 pa = X - a, ba = b - a;
    float h = saturate(dot(pa, ba) / dot(ba, ba));
    return length(pa - ba * h);
}

float chain(Point3 X) {
    const Point3 points[3] = Point3[3](Point3(-0.6, -0.3, 0.0), Point3(0.0, 0.3, 0.1), Point3(0.6, -0.2, -0.1));
    float d = 1e10;
    for (int i = 0; i < 2; ++i) {
        Point3 pi = points[i];
        Point3 pj = points[i + 1];
        d = min(d, segmentDistance(X, pi, pj));
    }
    return d - 0.12;
}

float sdf(Point3 X) {
    float ball = length(X - Point3(0.0, -0.45, 0.25)) - 0.1 * pi;
    return min(chain(X), ball);
}
