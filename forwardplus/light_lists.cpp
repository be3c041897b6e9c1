#include "forwardplus/light_lists.h"

#include <algorithm>

#include "core/gpu/context.h"
#include "core/render/renderer.h"
#include "forwardplus/forwardplus_shared.h"

namespace tp::fp {

ListSizes sizeLists(const GpuContext& ctx, const ListConfig& c) {
    ListSizes s;
    if (c.layout == TP_FP_LAYOUT_FIXED) {
        s.stride = c.tiles * c.capacity;
        s.slots = s.stride * c.numLists;
        s.bytes = s.slots * 4;
        s.purpose = "light indices, " + std::to_string(c.capacity) + " slots per tile" + (c.numLists == 2 ? " and list" : "");
    } else {
        s.stride = c.boundSlots;
        s.slots = c.boundSlots * c.numLists;
        if (c.layout == TP_FP_LAYOUT_COMPACT) {
            s.bytes = s.slots * 4;
            s.purpose = "light indices, packed per tile (offsets from a conservative bound)";
        } else {
            s.poolNodes = s.slots;
            s.bytes = s.poolNodes * 8;
            s.purpose = "linked-list node pool {light, next}, sized so it cannot overflow";
        }
    }
    s.bytes = std::max<uint64_t>(s.bytes, 16);
    const uint64_t limit = ctx.caps.maxStorageBufferRange;
    if (s.bytes > limit || s.slots > 0xffffffffull)
        throw RendererError("the '" + c.layoutName + "' light lists need " + std::to_string(s.bytes) +
                            " bytes, more than maxStorageBufferRange (" + std::to_string(limit) + ") of " +
                            ctx.info.name + "; use a larger --tile, a lower --res, fewer lights" +
                            (c.layout == TP_FP_LAYOUT_FIXED ? " or a smaller --tile-capacity" : ""));
    return s;
}

MaskLayout sizeMasks(const GpuContext& ctx, const std::vector<uint32_t>& bound, uint32_t slices) {
    MaskLayout m;
    m.offsets.assign(bound.size() + 1, 0);
    for (size_t t = 0; t < bound.size(); ++t) {
        m.offsets[t] = uint32_t(std::min<uint64_t>(m.words, 0xffffffffu));
        m.words += uint64_t(slices) * ((bound[t] + 31) / 32);
    }
    m.offsets.back() = uint32_t(std::min<uint64_t>(m.words, 0xffffffffu));
    if (m.words * 4 > ctx.caps.maxStorageBufferRange)
        throw RendererError("the cluster bitmasks need " + std::to_string(m.words * 4) +
                            " bytes, more than maxStorageBufferRange (" +
                            std::to_string(ctx.caps.maxStorageBufferRange) + ") of " + ctx.info.name +
                            "; use fewer --slices, a larger --tile, a lower --res or fewer lights");
    return m;
}

} // namespace tp::fp
