// Imitates: Syntopia's Fragmentarium / "Distance Estimated 3D Fractals"
// style kaleidoscopic IFS: a Sierpinski tetrahedron made of plane folds
// (z.xy = -z.yx when z.x + z.y < 0, ...), z = z*Scale - Offset*(Scale-1),
// CamelCase #define parameters, a fold() helper and `float DE(vec3 z)`.
// Four iterations; the last level is a ball of radius 1.5 (in the folded
// frame), and the whole thing is scaled by 0.5 to fit the cube.
//
// Why the audit should find it clean: each fold reflects across a plane
// through the origin and is the identity on that plane, so it is
// continuous and distance-preserving; z*Scale - c scales distances by
// Scale, undone by pow(Scale, -n). The result, length(z) - 1.5 pulled
// back, is continuous and 1-Lipschitz, with no bailout and no escape test
// (so no orbit-escape jumps). Far away |z_n| ~ Scale^n |z_0|: it grows.
// expect: entry=DE flags=none animated=no

#define Iterations 4
#define Scale 2.0
#define Offset vec3(1.0)
#define Radius 1.5
#define WorldScale 0.5

vec3 fold(vec3 z)
{
	if (z.x + z.y < 0.0) z.xy = -z.yx;
	if (z.x + z.z < 0.0) z.xz = -z.zx;
	if (z.y + z.z < 0.0) z.zy = -z.yz;
	return z;
}

float DE(vec3 z)
{
	z /= WorldScale;
	int n = 0;
	while (n < Iterations) {
		z = fold(z);
		z = z*Scale - Offset*(Scale - 1.0);
		n++;
	}
	return (length(z) - Radius) * pow(Scale, -float(n)) * WorldScale;
}
