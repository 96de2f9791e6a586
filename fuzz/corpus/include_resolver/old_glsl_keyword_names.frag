// GLSL 1.10 code naming things with words later GLSL took (written for this corpus).
uniform float time;
uniform vec2 resolution;
float sample(vec3 p, float smooth) { float filter = length(p) - 0.5; return filter * smooth; }
void main() {
  vec3 rd = normalize(vec3((gl_FragCoord.xy - 0.5 * resolution) / resolution.y, 1.0));
  float t = 0.0;
  for (int i = 0; i < 64; i++) { float d = sample(vec3(0.0, 0.0, -3.0) + rd * t, 1.0); if (d < 0.001) break; t += d; }
  gl_FragColor = vec4(vec3(t * 0.1), 1.0);
}
