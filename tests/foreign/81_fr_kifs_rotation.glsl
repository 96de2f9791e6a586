// Imitates: a Fragmentarium (Syntopia) fragment for a Menger sponge as a kaleidoscopic IFS in
// Knighty's style, with a rotation inside the loop: `#define providesInit`, `#include
// "MathUtils.frag"` (the host's library: `mat3 rotationMatrix3(vec3 v, float angle)`, the angle
// in degrees) and `#include "DE-Raytracer.frag"` (camera, main(), colouring, and the `vec4
// orbitTrap` written here undeclared), `#group Menger`, annotated uniforms including vector
// sliders (`uniform vec3 RotVector; slider[(0,0,0),(1,1,1),(1,1,1)]`), a file-scope
// `mat3 rot;` that `void init()` fills from the sliders once per frame, `float DE(vec3 z)`
// with `z *= rot;` at the top of each iteration, and a `#preset Default` that tilts the
// rotation axis to x and sets the angle to 10 degrees. The file declares no `uniform float
// time;` and uses none.
//
// Host support: sdfwb reads the annotated uniforms as parameters (the vector sliders' middle
// triples are their defaults), applies the Default preset (Iterations 6, RotVector 1,0,0,
// RotAngle 10; Scale and Offset keep their defaults 3 and 1,1,1), provides MathUtils'
// rotationMatrix3 (degrees), declares orbitTrap, and calls init() before the field. The entry
// is `DE`.
//
// Why the audit should find it discontinuous: the Menger folds (abs(), then three conditional
// swaps that sort the coordinates) are continuous (a swap is the identity on its plane) and
// 1-Lipschitz, z = Scale z - Offset (Scale - 1) scales by 3, undone by pow(Scale, -n), and the
// last level's cube is exact: every piece is 1-Lipschitz. But the Menger's extra step,
// `if (z.z < -0.5 Offset.z (Scale - 1)) z.z += Offset.z (Scale - 1)`, moves z.z from just below
// -1 to just below +1: a jump of 2 in the point, harmless in the plain sponge only because the
// next iteration's abs() sends -1 and +1 to the same place. Here the next iteration turns the
// point first (`z *= rot`, 10 degrees about x), which mixes z.z into z.y before abs(), so the
// two sides of each such plane land apart and the field jumps there, at every level but the
// last (after the last one, the cube is symmetric in z): the audit confirms jumps of about
// 0.008 (median) and reads a Lipschitz constant of about 0.9 elsewhere (the pieces' 1, sampled).
// With the slider defaults (RotAngle 0) or a rotation about z (which leaves z.z alone) the same
// file is continuous and flags nothing. The sponge is the cube [-1, 1]^3 turned a little per
// level: it fills the view, and the field grows outside it; no NaN. No time: not animated.
// expect: entry=DE flags=discontinuous animated=no

#define providesInit
#include "MathUtils.frag"
#include "DE-Raytracer.frag"
#group Menger

// Based on Knighty's kaleidoscopic IFS (fractalforums.com), Menger variant.

// Number of iterations.
uniform int Iterations;  slider[0,8,100]

// Number of iterations that feed the orbit trap colouring.
uniform int ColorIterations;  slider[0,3,100]

// Scale parameter. A perfect Menger is 3.0
uniform float Scale; slider[0.00,3.0,4.00]

// Axis of the rotation applied at each iteration
uniform vec3 RotVector; slider[(0,0,0),(1,1,1),(1,1,1)]

// Rotation angle, in degrees
uniform float RotAngle; slider[0.00,0,180]

// Scaling centre
uniform vec3 Offset; slider[(0,0,0),(1,1,1),(1,1,1)]

mat3 rot;

void init() {
	rot = rotationMatrix3(normalize(RotVector), RotAngle);
}

float DE(vec3 z)
{
	int n = 0;
	while (n < Iterations) {
		z *= rot;

		// fold into the sorted octant: x >= y >= z >= 0
		z = abs(z);
		if (z.x < z.y) z.xy = z.yx;
		if (z.x < z.z) z.xz = z.zx;
		if (z.y < z.z) z.yz = z.zy;

		// stretch about the corner, then bring the middle layer back
		z = Scale * z - Offset * (Scale - 1.0);
		if (z.z < -0.5 * Offset.z * (Scale - 1.0)) z.z += Offset.z * (Scale - 1.0);

		if (n < ColorIterations) orbitTrap = min(orbitTrap, abs(vec4(z, dot(z, z))));
		n++;
	}

	// distance to the last level's cube, pulled back to the first
	vec3 d = abs(z) - Offset;
	float box = min(max(d.x, max(d.y, d.z)), 0.0) + length(max(d, 0.0));
	return box * pow(Scale, float(-n));
}

#preset Default
FOV = 0.5
Eye = 2.6,2.0,3.7
Target = 0,0,0
Up = -0.18,0.94,-0.29
Detail = -3
DetailAO = -0.5
FudgeFactor = 1
MaxRaySteps = 200
AO = 0,0,0,0.8
Specular = 0.3
SpecularExp = 24
SpotLightDir = -0.4,0.6
CamLight = 1,1,1,0.8
BaseColor = 0.9,0.85,0.8
OrbitStrength = 0.4
X = 0.4,0.7,1,0.5
Y = 1,0.6,0.2,0.4
Z = 0.8,0.8,0.8,0.3
R = 0.3,0.4,0.9,0.1
BackgroundColor = 0.3,0.35,0.4
Iterations = 6
ColorIterations = 3
RotVector = 1,0,0
RotAngle = 10
#endpreset
