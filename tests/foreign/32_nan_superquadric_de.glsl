// Imitates: Fragmentarium-style distance estimators with CamelCase
// #define parameters and a `float DE(vec3 p)` entry -- here a "superquadric"
// written with pow(p, vec3(Power)) expanded by hand, copied from a
// version that mirrored the object into the positive octant first; the
// abs() was lost in the copy.
//
// Why NaN: the dimple term sqrt(p.x * p.y * p.z) was written for the positive
// octant; where the product is negative sqrt gives NaN on IEEE hardware
// (llvmpipe, NVIDIA; GLSL leaves it undefined). It is added last, so nothing
// (not even pow(), whose exp2 on llvmpipe clamps a NaN to a finite value)
// can swallow it: half of the cube is NaN. Every point with
// an odd number of negative coordinates -- half of the cube -- gets NaN, and it flows
// straight into the result (no min/max after it). In the four finite octants
// the field is ||p||_3.5 - Radius, a p-norm with p >= 2, whose gradient has
// Euclidean length <= 1, plus the sqrt term, whose slope passes 1.05 in thin
// layers along the coordinate planes (|grad f| 2.65 at 1e-6 from one). The
// audit's 99.9th-percentile estimate cannot see them, so it gives only nan
// (a known miss: tests/foreign/README.md).
// expect: entry=DE flags=nan animated=no

#define Power 3.5
#define Radius 0.7

float DE(vec3 p)
{
	vec3 q = pow(abs(p), vec3(Power));
	// the octant version's dimple term, meant for p >= 0: sqrt(p.x * p.y * p.z)
	return pow(q.x + q.y + q.z, 1.0/Power) - Radius + 0.01 * sqrt(p.x * p.y * p.z);
}
