// The march debugger's recorder (SDFWB_PROBE): composed before trace_core.glsl, it turns the
// tracer's SDFWB_RECORD hooks into rows of a storage buffer, so a probe replays the very march
// the picture was drawn with. The caller draws one pixel (a 1x1 scissor); each event writes two
// vec4: (kind, t, the scaled value d that was marched, |grad f| there) and (position, 0).
// Mirrored in C++ by renderer::ProbeEvent (OffscreenRenderer.h).
#define SDFWB_BINDING_PROBE 4

layout(std430, binding = SDFWB_BINDING_PROBE) buffer sdfwb_Probe {
    uint sdfwb_probeCount; // events recorded (may exceed the capacity: the rest were dropped)
    uint sdfwb_probePad0, sdfwb_probePad1, sdfwb_probePad2;
    vec4 sdfwb_probeRows[];
};

const int sdfwb_kProbeStep = 0;         // a plain step of d
const int sdfwb_kProbeRelaxedStep = 1;  // an over-relaxed step of omega * d
const int sdfwb_kProbeFallback = 2;     // the relaxed step went too far: back to plain steps
const int sdfwb_kProbeHit = 3;          // |f| fell below the pixel footprint
const int sdfwb_kProbeRefineKept = 4;   // a refining step after the hit that shrank |f|
const int sdfwb_kProbeRefineUndone = 5; // a refining step that would have grown |f|: not taken
const int sdfwb_kProbeLeftBox = 6;      // the ray passed the far side of the box
const int sdfwb_kProbeNotFinite = 7;    // f was NaN or Inf
const int sdfwb_kProbeOutOfSteps = 8;   // the step budget ran out
const int sdfwb_kProbeMissedBox = 9;    // the ray never entered the box

float sdfwb_sceneMap(vec3 p);
vec3 sdfwb_gradientAt(vec3 p, float h);
float sdfwb_pixelAngle();

void sdfwb_record(int kind, float t, vec3 position, float d) {
    uint row = atomicAdd(sdfwb_probeCount, 1u);
    if (2u * row + 1u >= uint(sdfwb_probeRows.length())) return;
    // The |grad f| estimate with the step the shading normal uses at this distance.
    float h = max(sdfwb_pixelAngle() * t, 1e-5 * max(1.0, length(position)));
    float slope = (kind == sdfwb_kProbeNotFinite || kind == sdfwb_kProbeMissedBox) ? 0.0 : length(sdfwb_gradientAt(position, h));
    sdfwb_probeRows[2u * row] = vec4(float(kind), t, d, slope);
    sdfwb_probeRows[2u * row + 1u] = vec4(position, 0.0);
}

#define SDFWB_RECORD(kind, t, position, d) sdfwb_record(kind, t, position, d)
