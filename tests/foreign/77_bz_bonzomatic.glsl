#version 410 core

// Imitates: a Bonzomatic live-coding shader as demoscene shader showdowns leave them: the tool's
// `#version 410 core` and its uniform block pasted at the top (fGlobalTime, v2Resolution,
// fFrameTime, the three FFT sampler1Ds, texPreviousFrame, texChecker, texNoise, texTex1, most
// of them unused), `layout(location = 0) out vec4 out_color;`, `void main(void)` with uv from
// gl_FragCoord and v2Resolution, a `mat2 rot(float a)` helper, a box() and `float map(vec3 p)`
// turned by fGlobalTime, a march with a glow term, normals, a fake light, the FFT read once in
// the colouring (`texture(texFFTSmoothed, .1).r`, the bass) and a feedback blend with the
// previous frame.
//
// Host support: sdfwb treats `void main(void)` as Shadertoy's mainImage, fGlobalTime as the
// time and v2Resolution as the frame size; the samplers only colour the picture. The entry is
// `map`, a conventional name.
//
// Why the audit should find it clean: the point is turned about two axes by angles of
// fGlobalTime (rotations, isometries), then a cube (IQ's exact box, half side 0.42) is hollowed
// by a ball (radius 0.56) with max(box, -ball), and a core ball (radius 0.22) is added with
// min(): max and min of 1-Lipschitz fields are 1-Lipschitz and continuous. The pieces lie
// within |p| <= 0.73 (the box's corner), so the field grows outside; no NaN. fGlobalTime is in
// the field: animated.
// expect: entry=map flags=none animated=yes

uniform float fGlobalTime; // in seconds
uniform vec2 v2Resolution; // viewport resolution (in pixels)
uniform float fFrameTime; // duration of the last frame, in seconds

uniform sampler1D texFFT; // towards 0.0 is bass / lower freq, towards 1.0 is higher / treble freq
uniform sampler1D texFFTSmoothed; // this one has longer falloff and less harsh transients
uniform sampler1D texFFTIntegrated; // this is continually increasing
uniform sampler2D texPreviousFrame; // screenshot of the previous frame
uniform sampler2D texChecker;
uniform sampler2D texNoise;
uniform sampler2D texTex1;

layout(location = 0) out vec4 out_color; // out_color must be written in order to see anything

float t = fGlobalTime;

mat2 rot(float a) { float c = cos(a), s = sin(a); return mat2(c, s, -s, c); }

float box(vec3 p, vec3 b) {
  vec3 q = abs(p) - b;
  return length(max(q, 0.)) + min(max(q.x, max(q.y, q.z)), 0.);
}

float glow = 0.;

float map(vec3 p) {
  p.xz *= rot(fGlobalTime * .5);
  p.xy *= rot(fGlobalTime * .3);
  float d = box(p, vec3(.42));
  d = max(d, -(length(p) - .56)); // dig the ball out of the cube
  float core = length(p) - .22;
  d = min(d, core);
  return d;
}

vec3 norm(vec3 p) {
  vec2 e = vec2(.001, 0.);
  return normalize(map(p) - vec3(map(p - e.xyy), map(p - e.yxy), map(p - e.yyx)));
}

void main(void)
{
  vec2 uv = vec2(gl_FragCoord.x / v2Resolution.x, gl_FragCoord.y / v2Resolution.y);
  uv -= 0.5;
  uv /= vec2(v2Resolution.y / v2Resolution.x, 1);

  vec3 ro = vec3(0., .8, -3.), rd = normalize(vec3(uv, 1.4));
  rd.yz *= rot(-.25);
  ro.xz *= rot(t * .1); rd.xz *= rot(t * .1);

  float d, z = 0.;
  vec3 p;
  for (int i = 0; i < 100; i++) {
    p = ro + rd * z;
    d = map(p);
    glow += .02 / (.1 + abs(d));
    if (d < .001 || z > 10.) break;
    z += d;
  }

  float bass = texture(texFFTSmoothed, .1).r;
  vec3 col = vec3(.05, .02, .1) + glow * vec3(.02, .05, .1) * (1. + 20. * bass);
  if (z < 10.) {
    vec3 n = norm(p);
    vec3 l = normalize(vec3(-1., 2., -3.));
    float dif = max(0., dot(n, l));
    float spe = pow(max(0., dot(reflect(-l, n), -rd)), 20.);
    col = mix(vec3(1., .3, .1), vec3(.1, .8, 1.), step(.3, length(p))) * (.2 + dif) + spe;
    col *= 1. + 4. * bass * step(length(p), .3); // the core pumps with the bass
  }

  vec2 fb = gl_FragCoord.xy / v2Resolution;
  col = mix(col, texture(texPreviousFrame, fb).rgb, .3);
  out_color = vec4(col, 1.);
}
