/* sdfwb
name: Sierpinski Tetrahedron
category: Fractal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Sierpinski tetrahedron (tetrix) with six levels, standing on a face with a vertex up and
  a face turned to +X. Built by folding: in the frame where the vertices are (1,1,1), (-1,-1,1),
  (1,-1,-1) and (-1,1,-1), reflecting across the bisector planes x+y=0, x+z=0 and y+z=0 moves the
  point towards the (1,1,1) corner (the reflections are symmetries of the tetrahedron), and
  scaling by 2 about that vertex maps its corner tetrahedron onto the whole. After the levels, the
  plane bound of the unit tetrahedron (exact inside, a lower bound outside) is divided by 2^levels.
  Reflections are isometries and continuous, so the field is 1-Lipschitz and never exceeds the true
  distance: conservative.
*/
float sdf(vec3 p) {
    const float scale = 0.66;  // world units per fractal unit (vertices at distance sqrt(3))
    const int levels = 6;
    // Centre the bounding box: the fractal spans y in [-0.577, 1.732] and x in [-1.633, 0.816].
    const vec3 offset = vec3(0.4082483, 0.5773503, 0.0) * scale;
    // Rotation to the fractal's frame: world X, Y, Z go to these unit vectors (orthonormal).
    const vec3 frameX = vec3(0.4082483, 0.4082483, -0.8164966);  // (1, 1, -2) / sqrt 6: towards a face
    const vec3 frameY = vec3(0.5773503, 0.5773503, 0.5773503);   // (1, 1, 1) / sqrt 3: the top vertex
    const vec3 frameZ = vec3(0.7071068, -0.7071068, 0.0);        // (1, -1, 0) / sqrt 2
    vec3 q = (p + offset) / scale;
    vec3 z = q.x * frameX + q.y * frameY + q.z * frameZ;

    for (int level = 0; level < levels; ++level) {
        if (z.x + z.y < 0.0) z.xy = -z.yx;
        if (z.x + z.z < 0.0) z.xz = -z.zx;
        if (z.y + z.z < 0.0) z.yz = -z.zy;
        z = 2.0 * z - 1.0;
    }
    // Unit tetrahedron: the four face planes, each at distance 1/sqrt(3) from the centre.
    float planes = max(max(-z.x - z.y - z.z, z.x + z.y - z.z), max(-z.x + z.y + z.z, z.x - z.y + z.z));
    float tetrahedron = (planes - 1.0) * 0.5773503;
    return tetrahedron * scale / float(1 << levels);
}
