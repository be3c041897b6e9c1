// The FMA loop of calibrate's two FMA ceilings, compute (TP_CAL_FMA) and fragment
// (calibrate.frag, TP_CAL_FRAGMENT_FMA): the same code on both stages, so their rates compare the stages.
// Eight independent vec4 chains, so that an FMA's latency hides behind the other seven's:
// 8 x 4 FMAs = 64 FLOPs per step.
#ifndef TP_CALIBRATE_FMA_GLSL
#define TP_CALIBRATE_FMA_GLSL

vec4 fmaChains(float seed, uint steps) {
    vec4 a[8];
    const vec4 m = vec4(0.999999), c = vec4(1.0e-7);
    for (uint i = 0u; i < 8u; ++i) a[i] = vec4(seed + float(i));
    for (uint k = 0u; k < steps; ++k)
        for (uint i = 0u; i < 8u; ++i) a[i] = fma(a[i], m, c);
    vec4 sum = vec4(0.0);
    for (uint i = 0u; i < 8u; ++i) sum += a[i];
    return sum;
}
#endif
