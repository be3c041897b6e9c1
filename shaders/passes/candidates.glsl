// Binned culling's per-tile candidates (deferred_shared.h: TP_TL_CAND_*), read by the tiled
// lighting pass and, for the transparent masks, by the blended pass. The includer declares
// `uint cand[]` (the light_candidates buffer) and the spec constant `kBinned`.
#ifndef TP_TL_CANDIDATES_GLSL
#define TP_TL_CANDIDATES_GLSL

// Tile t's candidates: the directional lights, then its run (binned); every light otherwise.
uint candidateCount(uint tileIndex) {
    if (!kBinned) return frame.viewport.z;
    uint offsets = cand[TP_TL_CAND_OFFSETS];
    return cand[TP_TL_CAND_DIRECTIONAL] + cand[offsets + tileIndex + 1u] - cand[offsets + tileIndex];
}

// Candidate p of tile t: a light index.
uint candidateLight(uint tileIndex, uint p) {
    if (!kBinned) return p;
    uint directional = cand[TP_TL_CAND_DIRECTIONAL];
    if (p < directional) return cand[TP_TL_CAND_HEADER + p];
    return cand[cand[TP_TL_CAND_RUNS] + cand[cand[TP_TL_CAND_OFFSETS] + tileIndex] + p - directional];
}

// Binned: tile t's candidates read once, for a fragment that looks up many of them (one
// load per candidate instead of the four of candidateLight).
struct TlCandidates {
    uint count;       // directional lights + the tile's run
    uint directional; // candidates [0, directional): the directional lights
    uint run;         // candidate p >= directional is cand[run + p]
};

TlCandidates tlCandidates(uint tileIndex) {
    TlCandidates c;
    uint offsets = cand[TP_TL_CAND_OFFSETS];
    uint first = cand[offsets + tileIndex];
    c.directional = cand[TP_TL_CAND_DIRECTIONAL];
    c.count = c.directional + cand[offsets + tileIndex + 1u] - first;
    c.run = cand[TP_TL_CAND_RUNS] + first - c.directional;
    return c;
}

uint tlCandidateLight(TlCandidates c, uint p) {
    return p < c.directional ? cand[TP_TL_CAND_HEADER + p] : cand[c.run + p];
}
#endif
