// Written for the original sdf-explorer: G3D names, no #version.
float sdf(Point3 X) {
    float3 q = abs(X) - float3(0.5);
    float r = lerp(0.1, 0.2, saturate(0.5 + 0.5 * sin(pi * g3d_SceneTime)));
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}
