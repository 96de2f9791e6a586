// Lays the mesh overlay's own frame (drawn with its own depth buffer) over the traced frame:
// where no triangle was drawn, alpha is 0 and the traced frame shows.
in vec2 sdfwb_ndc;
out vec4 sdfwb_color;

uniform sampler2D sdfwb_overlayFrame;

void main() { sdfwb_color = texture(sdfwb_overlayFrame, sdfwb_ndc * 0.5 + 0.5); }
