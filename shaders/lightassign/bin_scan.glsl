// The scans of the light_binning pass (bin_scan_rows.comp, bin_scan_columns.comp): a
// workgroup of 64 scans four sums at once in shared memory (log2(64) rounds, no subgroup
// operations: their width differs between devices). Sums modulo 2^32: exact wherever the
// true value is below 2^32 (every count is; a layout whose total is not is refused before
// any frame, from the counts).
#ifndef TP_BIN_SCAN_GLSL
#define TP_BIN_SCAN_GLSL

layout(local_size_x = 64) in;

shared uvec4 scanSums[64];

// Exclusive prefix sum of v over the workgroup's invocations; total: the sum of all.
// Every invocation must call it (barriers).
uvec4 binScanExclusive(uvec4 v, out uvec4 total) {
    const uint lane = gl_LocalInvocationIndex;
    scanSums[lane] = v;
    barrier();
    for (uint step = 1u; step < 64u; step <<= 1u) {
        const uvec4 add = lane >= step ? scanSums[lane - step] : uvec4(0u);
        barrier();
        scanSums[lane] += add;
        barrier();
    }
    total = scanSums[63];
    const uvec4 inclusive = scanSums[lane];
    barrier(); // the next scan reuses scanSums
    return inclusive - v;
}

// This invocation's contiguous share [first, end) of `count` items.
uvec2 binScanShare(uint count) {
    const uint chunk = (count + 63u) / 64u, first = min(gl_LocalInvocationIndex * chunk, count);
    return uvec2(first, min(first + chunk, count));
}
#endif
