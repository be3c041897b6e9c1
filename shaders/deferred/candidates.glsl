// Binned culling's per-tile candidates (deferred_shared.h: TP_DEF_CAND_*), read by the tiled
// lighting pass and, for the transparent masks, by the blended pass. The includer declares
// `uint cand[]` (the light_candidates buffer) and the spec constant `kBinned`.
#ifndef TP_DEF_CANDIDATES_GLSL
#define TP_DEF_CANDIDATES_GLSL

// Tile t's candidates: the directional lights, then its run (binned); every light otherwise.
uint candidateCount(uint tileIndex) {
    if (!kBinned) return frame.viewport.z;
    uint offsets = cand[TP_DEF_CAND_OFFSETS];
    return cand[TP_DEF_CAND_DIRECTIONAL] + cand[offsets + tileIndex + 1u] - cand[offsets + tileIndex];
}

// Candidate p of tile t: a light index.
uint candidateLight(uint tileIndex, uint p) {
    if (!kBinned) return p;
    uint directional = cand[TP_DEF_CAND_DIRECTIONAL];
    if (p < directional) return cand[TP_DEF_CAND_HEADER + p];
    return cand[cand[TP_DEF_CAND_RUNS] + cand[cand[TP_DEF_CAND_OFFSETS] + tileIndex] + p - directional];
}
#endif
