// The walk of a bitmask light list, one 32-bit word at a time: every loop that reads a list
// stored as bits (the tiled lighting pass's clustered rows, the blended forward pass, Forward+'s
// slice masks, the visibility buffer's composite) walks its words with this.
//   TP_FOR_EACH_BIT(bits, lsb, body)
// runs `body` once for each set bit of the uint variable `bits`, lowest first, with `int lsb`
// the bit's index in its word (the caller's entry is 32 * word + lsb); the walk consumes
// `bits`. Lowest first is ascending list order, the order every pipeline sums its lights in,
// so two passes that walk one list add the same terms in the same order. At most 32 turns
// (a word's bits), ending at the last set bit.
#ifndef TP_LIGHT_LIST_WALK_GLSL
#define TP_LIGHT_LIST_WALK_GLSL
#define TP_FOR_EACH_BIT(bits, lsb, body)                        \
    for (uint tpBit = 0u; tpBit < 32u && bits != 0u; ++tpBit) { \
        int lsb = findLSB(bits);                                \
        bits &= bits - 1u;                                      \
        body                                                    \
    }
#endif
