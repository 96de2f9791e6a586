// The file's own picture: calls a whole Shadertoy shader's mainImage for each pixel, with the
// frame's Shadertoy inputs (renderer/ShadertoyPicture.h sets them), so the author's picture can be
// compared with sdfwb's tracer. Composed after the SDF; drawn with tracer/fullscreen.vert.
in vec2 sdfwb_ndc;
layout(location = 0) out vec4 sdfwb_fragColor;

void main() {
    vec4 color = vec4(0.0, 0.0, 0.0, 1.0);
    mainImage(color, gl_FragCoord.xy);
    sdfwb_fragColor = vec4(color.rgb, 1.0);
}
