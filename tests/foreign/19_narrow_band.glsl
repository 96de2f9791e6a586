// Imitates: code that stores or streams an SDF as a narrow band (distance
// textures, voxel tools, "sdf baking" snippets): the field is clamped to
// +-BAND because only the band around the surface is kept. Written with an
// `sdf(vec3 p)` entry and IQ-style helpers; the shape is a rounded box with
// a hole drilled through it.
//
// Why truncated: clamp(d, -BAND, BAND) with BAND = 0.1 is flat (|grad| = 0)
// everywhere more than 0.1 from the surface, i.e. over almost all of the
// outside region out to distance 3. The underlying field (rounded box
// minus a cylinder, via max) is exact/1-Lipschitz and continuous, and
// clamping does not raise the gradient, so no other flag.
// expect: entry=sdf flags=truncated animated=no

#define BAND 0.1

float sdRoundBox(vec3 p, vec3 b, float r)
{
    vec3 q = abs(p) - b + r;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float sdCylinderZ(vec3 p, float r)
{
    return length(p.xy) - r;
}

float sdf(vec3 p)
{
    float d = max(sdRoundBox(p, vec3(0.5, 0.5, 0.3), 0.08), -sdCylinderZ(p, 0.25));
    return clamp(d, -BAND, BAND);
}
