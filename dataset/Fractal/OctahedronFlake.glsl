/* sdfwb
name: Octahedron Flake
category: Fractal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Octahedron flake (Sierpinski octahedron), four levels: an octahedron with vertices on the
  axes at distance 0.92 is replaced by its six half-size copies at the vertices, again and again.
  Built by folding: taking absolute values and sorting the coordinates so that x is the largest
  are reflections in symmetry planes of the octahedron, and they carry every corner copy onto the
  +X one; scaling by 2 about the +X vertex then maps that copy onto the whole. After the levels,
  the plane bound of the unit octahedron (exact inside, a lower bound outside) is divided by
  2^levels. Reflections are isometries and continuous, so the field is 1-Lipschitz and never
  exceeds the true distance: conservative.
*/
float sdf(vec3 p) {
    const float vertexDistance = 0.92;
    const int levels = 4;
    vec3 z = p / vertexDistance;
    for (int level = 0; level < levels; ++level) {
        z = abs(z);
        // Sort so that x is the largest coordinate: reflections across the planes x = y and x = z.
        if (z.y > z.x) z.xy = z.yx;
        if (z.z > z.x) z.xz = z.zx;
        z = 2.0 * z - vec3(1.0, 0.0, 0.0);
    }
    float octahedron = (abs(z.x) + abs(z.y) + abs(z.z) - 1.0) * 0.57735027;
    return octahedron * vertexDistance / float(1 << levels);
}
