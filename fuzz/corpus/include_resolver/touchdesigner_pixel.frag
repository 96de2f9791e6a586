// A TouchDesigner GLSL TOP pixel shader in its usual form (written for this corpus).
uniform float uTime;
uniform vec2 uResolution;
out vec4 fragColor;
float scene(vec3 p) { return length(p) - 0.5 + 0.05 * sin(uTime); }
void main()
{
	vec2 uv = vUV.st * 2.0 - 1.0;
	uv.x *= uTDOutputInfo.res.z / uTDOutputInfo.res.w;
	vec3 ro = vec3(0.0, 0.0, -3.0), rd = normalize(vec3(uv, 1.5));
	float t = 0.0;
	for (int i = 0; i < 64; i++) { float d = scene(ro + rd * t); if (d < 0.001) break; t += d; }
	fragColor = TDOutputSwizzle(vec4(TDHSVToRGB(vec3(t * 0.1, 0.6, 1.0)), 1.0));
}
