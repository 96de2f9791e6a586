#iChannel0 "file://noise.png"
#iKeyboard
#iUniform float radius = 0.5 in { 0.1, 2.0 } step 0.05 // a slider
#iUniform color3 tint = color3(0.8, 0.5, 0.2)
#iUniform int steps = 96 in{16, 256 };
#iUniform vec2 offset = vec2(0.25)
float map(vec3 p) {
    #iUniform float wobble = 0.1 in {0.0, 1.0}
    return length(p - vec3(offset, 0.0)) - radius - wobble * sin(iTime);
}
