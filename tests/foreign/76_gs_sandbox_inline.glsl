// Imitates: a GLSL Sandbox (glslsandbox.com) entry as the gallery keeps them: the site's template
// header (`#ifdef GL_ES` / `precision highp float;` / `#endif`, then the
// `#extension GL_OES_standard_derivatives : enable` line the editor adds after it, whether the
// shader uses derivatives or not), the site's inputs declared under its own names
// (`uniform float time; uniform vec2 mouse; uniform vec2 resolution;`, the mouse normalised to
// 0..1), `void main( void )` writing gl_FragColor, and golfed code: one-letter names, a march
// with no distance function, the field written inline in the loop (`vec3 p = o + r * t;`, a
// rippled ball, `t += d;`), normals by central differences of the same field written again
// in a #define, and a glow piled up from the steps.
//
// Host support: sdfwb treats `void main( void )` as Shadertoy's mainImage, `time` as the time,
// `resolution` and `mouse` as the frame size and the (normalised) mouse. The field is written
// inline, as in issue 47's files 63-71: the entry is the function whose loop steps t by d,
// main, which sdfwb reads as mainImage (so entry=mainImage, as for 63-71).
//
// Why the audit should find it non-conservative: d = |p| - 0.6 + 0.04 sin(10 x + time)
// sin(10 y) sin(10 z). The ripple's gradient is 0.4 (cos sx sy sz, sx cy sz, sx sy cz) (s, c
// the sines and cosines of the three arguments), whose length reaches 0.4 (at sx = 0, sy = sz =
// +-1, and the like), so |grad d| reaches 1.4 where it points along the radius: a golfer's
// field, which such shaders march anyway (they overshoot a little and nobody minds); the audit
// reads 1.35. Continuous (sines and a length), finite (nothing divides), and growing outside
// (the ripple is at most 0.04). `time` is in the field: animated.
// expect: entry=mainImage flags=non-conservative animated=yes

#ifdef GL_ES
precision highp float;
#endif

#extension GL_OES_standard_derivatives : enable

uniform float time;
uniform vec2 mouse;
uniform vec2 resolution;

void main( void ) {

	vec2 u = ( gl_FragCoord.xy * 2. - resolution.xy ) / min( resolution.x, resolution.y );
	float a = ( mouse.x - .5 ) * 6.28 + .7, b = .4 + mouse.y * .5;
	vec3 o = 3.2 * vec3( sin( a ) * cos( b ), sin( b ), cos( a ) * cos( b ) );
	vec3 f = normalize( -o ), s = normalize( cross( f, vec3( 0, 1, 0 ) ) ), v = cross( s, f );
	vec3 r = normalize( u.x * s + u.y * v + 1.7 * f );

	float t = 0., g = 0.;
	for ( int i = 0; i < 100; i++ ) {
		vec3 p = o + r * t;
		float d = length( p ) - .6 + sin( p.x * 10. + time ) * sin( p.y * 10. ) * sin( p.z * 10. ) * .04;
		if ( d < .001 || t > 8. ) break;
		t += d;
		g += .01 / ( .05 + d * d );
	}

	vec3 c = vec3( .02, .03, .06 ) + g * vec3( .01, .015, .03 );
	if ( t < 8. ) {
		vec3 p = o + r * t, e = vec3( .001, 0, 0 );
		#define F(q) ( length( q ) - .6 + sin( (q).x * 10. + time ) * sin( (q).y * 10. ) * sin( (q).z * 10. ) * .04 )
		vec3 n = normalize( vec3( F( p + e.xyy ) - F( p - e.xyy ), F( p + e.yxy ) - F( p - e.yxy ), F( p + e.yyx ) - F( p - e.yyx ) ) );
		float l = max( dot( n, normalize( vec3( .5, .8, .3 ) ) ), 0. );
		c = mix( vec3( .9, .3, .5 ), vec3( .2, .6, 1. ), .5 + .5 * n.y ) * ( .15 + .85 * l );
		c += pow( 1. - max( dot( n, -r ), 0. ), 4. ) * .5;
	}

	gl_FragColor = vec4( pow( c, vec3( .4545 ) ), 1. );

}
