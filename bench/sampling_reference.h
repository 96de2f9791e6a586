#pragma once
// bench_sampling's C++ reference: what a demanding user would write to sample the benchmark's
// fields on the CPU. The fields are inlined into the loop (function objects, no indirection), the
// loop is an OpenMP `parallel for simd` over the rand sampler's points, and the file is compiled
// twice at -O3 -march=native: once strict (IEEE float) and once with -ffast-math (GLSL is not
// strict IEEE either). bench_sampling runs both at every thread count and reports the fastest.

#include <cstddef>

namespace sdfwb::bench {

enum class ReferenceField { Sphere, Csg, Mandelbulb };

// Value and 6-tap central-difference gradient (step 1e-3, as the sampler's default) at the rand
// sampler's points 0..n-1 of seed 0, on `threads` threads; returns the seconds it took.
double sampleReferenceStrict(ReferenceField field, std::size_t n, int threads, float* distances, float* gradients);
double sampleReferenceFastMath(ReferenceField field, std::size_t n, int threads, float* distances, float* gradients);

} // namespace sdfwb::bench
