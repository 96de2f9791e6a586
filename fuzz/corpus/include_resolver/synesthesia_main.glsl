float m(vec3 p) { p.xz = _rotate(p.xz, Rotate * PI); return length(p) - 0.5 - 0.1 * syn_BassLevel + 0.0 * syn_BassTime; }
vec4 renderMainImage() {
    vec3 d = normalize(vec3(_uvc, 1.0)), o = vec3(0.0, 0.0, -3.0);
    for (int i = 0; i < 64; i++) o += m(o) * d;
    return vec4(o, 1.0) + 0.0 * texture(syn_Spectrum, _uv);
}
vec4 renderMain() {
    if (PASSINDEX == 0) return renderMainImage();
}
