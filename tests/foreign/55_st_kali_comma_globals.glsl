// Imitates: a whole Shadertoy in Kali's (Pablo Roman Andrioli's) style:
// lowercase globals declared together at file scope,
// `float det = .005, maxdist = 50., pi = 3.1416;`, a `mat2 rot(float a)`,
// `float de(vec3 p)`, a `normal()` with `vec3 e = vec3(0., det, 0.)` and
// the `e.yxx` swizzles, a `march(from, dir)` loop on `totdist`, a `from`
// and `dir` camera turned with rot(iTime*...), and a few lines of colour
// maths at the end: a cube stood on its corner (turned by pi/4 and by
// atan(1/sqrt 2)), hollowed by a sphere so only its edges remain, with a
// ball inside the cage.
//
// Issue 47, class 3: `pi` is declared in a comma list (the third name of
// `float det = ..., maxdist = ..., pi = ...;`), not as `float pi = ...;`,
// and de() uses it. `pi` is also a name sdfwb supplies to files that use it
// undeclared (the G3D dialect); it must see that this file declares it,
// and neither declare it again nor replace it.
//
// Why the audit should find it clean: the box and both spheres are exact
// distances; the rotations are isometries; the cage is max(box, -sphere)
// (a subtraction: a lower bound with |grad| <= 1, continuous), and the
// ball inside is joined by min(). The cage's convex creases (the rims of
// the holes) read at most ~1.04 to the audit's per-axis differences,
// under 1.05. The ball (0.22) sits inside the hollow (0.45), clear of the
// cage. Finite; within 0.61 of the origin (the cube's half diagonal), the
// field grows outside: no flag. iTime turns the camera only, but the file
// reads it: animated.
// expect: entry=de flags=none animated=yes

float det = .005, maxdist = 50., pi = 3.1416;
vec3 ldir = vec3(.5, 1., -.7);

mat2 rot(float a) {
	float s = sin(a), c = cos(a);
	return mat2(c, s, -s, c);
}

float box(vec3 p, vec3 c) {
	vec3 pc = abs(p) - c;
	return length(max(vec3(0.), pc)) + min(0., max(pc.z, max(pc.x, pc.y)));
}

float de(vec3 p) {
	vec3 q = p;
	q.xz *= rot(pi / 4.);
	q.yz *= rot(atan(1. / sqrt(2.)));
	float cage = max(box(q, vec3(.35)), -(length(p) - .45));
	float ball = length(p) - .22;
	return min(cage, ball);
}

vec3 normal(vec3 p) {
	vec3 e = vec3(0., det, 0.);
	return normalize(vec3(de(p + e.yxx) - de(p - e.yxx),
	                      de(p + e.xyx) - de(p - e.xyx),
	                      de(p + e.xxy) - de(p - e.xxy)));
}

float shadow(vec3 p, vec3 dir) {
	float sh = 1., totdist = 2. * det, d;
	for (int i = 0; i < 40; i++) {
		d = de(p + dir * totdist);
		sh = min(sh, 8. * d / totdist);
		totdist += max(d, .01);
		if (sh < .001 || totdist > 3.) break;
	}
	return clamp(sh, 0., 1.);
}

vec3 march(vec3 from, vec3 dir) {
	vec3 p, col = vec3(0.);
	float d, totdist = 0.;
	for (int i = 0; i < 150; i++) {
		p = from + totdist * dir;
		d = de(p);
		if (d < det || totdist > maxdist) break;
		totdist += d;
	}
	vec3 back = vec3(.25, .2, .3) * (1. - abs(dir.y));
	if (d < det) {
		vec3 n = normal(p - det * dir);
		vec3 l = normalize(ldir);
		float dif = max(0., dot(l, n)) * shadow(p, l);
		float spec = pow(max(0., dot(reflect(l, n), dir)), 20.);
		col = (length(p) < .3 ? vec3(1., .5, .2) : vec3(.6, .7, .8)) * (.15 + dif) + spec * .5;
	} else col = back;
	return col;
}

void mainImage( out vec4 fragColor, in vec2 fragCoord )
{
	vec2 uv = fragCoord.xy / iResolution.xy - .5;
	uv.x *= iResolution.x / iResolution.y;
	vec3 from = vec3(0., .3, -2.5);
	vec3 dir = normalize(vec3(uv, 1.3));
	dir.yz *= rot(-.1);
	from.xz *= rot(iTime * .3);
	dir.xz *= rot(iTime * .3);
	vec3 col = march(from, dir);
	col = mix(col, vec3(length(col)) * .6, .2);
	fragColor = vec4(pow(col, vec3(.9)), 1.);
}
