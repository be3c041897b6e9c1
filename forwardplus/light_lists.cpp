#include "forwardplus/light_lists.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/lightassign/light_classes.h"
#include "core/renderer/renderer.h"
#include "forwardplus/forwardplus_shared.h"

namespace tp::fp {

ListSizes sizeLists(const GpuContext& ctx, const ListConfig& c) {
    ListSizes s;
    if (c.layout == TP_FP_LAYOUT_FIXED) {
        s.stride = c.tiles * c.capacity;
        s.slots = s.stride * c.numLists;
        s.bytes = s.slots * 4;
        s.purpose = "light indices, " + std::to_string(c.capacity) + " slots per tile" +
                    (c.numLists == 2 ? " and list" : "");
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
        throw RendererError(
            "the '" + c.layoutName + "' light lists need " + std::to_string(s.bytes) +
            " bytes, more than maxStorageBufferRange (" + std::to_string(limit) + ") of " +
            ctx.info.name + "; use a larger --tile, a lower --res, fewer lights" +
            (c.layout == TP_FP_LAYOUT_FIXED ? " or a smaller --tile-capacity" : ""));
    return s;
}

MaskLayout layoutMasks(const std::vector<uint32_t>& bound, uint32_t slices) {
    MaskLayout m;
    m.offsets.assign(bound.size() + 1, 0);
    for (size_t t = 0; t < bound.size(); ++t) {
        m.offsets[t] = uint32_t(std::min<uint64_t>(m.words, 0xffffffffu));
        m.words += uint64_t(slices) * ((bound[t] + 31) / 32);
    }
    m.offsets.back() = uint32_t(std::min<uint64_t>(m.words, 0xffffffffu));
    return m;
}

MaskLayout sizeMasks(const GpuContext& ctx, const std::vector<uint32_t>& bound, uint32_t slices) {
    MaskLayout m = layoutMasks(bound, slices);
    if (m.words * 4 > ctx.caps.maxStorageBufferRange)
        throw RendererError("the cluster bitmasks need " + std::to_string(m.words * 4) +
                            " bytes, more than maxStorageBufferRange (" +
                            std::to_string(ctx.caps.maxStorageBufferRange) + ") of " +
                            ctx.info.name +
                            "; use fewer --slices, a larger --tile, a lower --res or fewer lights");
    return m;
}

PackedParams packParams(const GpuContext& ctx, const ParamsInput& in) {
    gpu::FpParams p{};
    p.tiles = glm::uvec4(in.grid.tilesX, in.grid.tilesY, in.grid.count(), in.grid.tileSize);
    const uint32_t dirCount = uint32_t(in.classes->directional.size());
    const uint32_t localCount = uint32_t(in.classes->local.size());
    std::vector<uint32_t> data;
    data.insert(data.end(), in.classes->directional.begin(), in.classes->directional.end());
    data.insert(data.end(), in.classes->local.begin(), in.classes->local.end());
    const uint32_t offsetBase = uint32_t(data.size());
    const bool offsets = in.layout == TP_FP_LAYOUT_COMPACT || in.binned;
    if (offsets) data.insert(data.end(), in.tileOffsets->begin(), in.tileOffsets->end());
    const uint32_t candidateBase = uint32_t(data.size());
    data.insert(data.end(), in.candidates->begin(), in.candidates->end());
    // The rest of the room: zeros (under gpu binning light_binning writes the runs there).
    data.resize(std::max<uint64_t>(data.size(), uint64_t(candidateBase) + in.candidateSlots), 0);
    const uint32_t maskOffsetBase = uint32_t(data.size());
    data.insert(data.end(), in.maskOffsets->begin(), in.maskOffsets->end());
    data.push_back(0); // never empty
    const uint64_t limit = ctx.caps.maxStorageBufferRange;
    if (sizeof(p) + data.size() * 4 > limit)
        throw RendererError(
            "fp_params (light classes, tile offsets, binned candidates) needs " +
            std::to_string(sizeof(p) + data.size() * 4) +
            " bytes, more than maxStorageBufferRange (" + std::to_string(limit) + ") of " +
            ctx.info.name +
            "; use a larger --tile, a lower --res, fewer lights or --light-cull all");
    p.lights = glm::uvec4(dirCount, localCount, offsetBase, in.tileCapacity);
    p.lists = glm::uvec4(uint32_t(in.lists.stride), uint32_t(in.lists.poolNodes), candidateBase,
                         maskOffsetBase);
    PackedParams out;
    out.candidateWord = sizeof(p) / 4 + candidateBase;
    out.offsetWord = sizeof(p) / 4 + offsetBase;
    out.maskOffsetWord = sizeof(p) / 4 + maskOffsetBase;
    out.bytes.resize(sizeof(p) + data.size() * 4);
    std::memcpy(out.bytes.data(), &p, sizeof(p));
    std::memcpy(out.bytes.data() + sizeof(p), data.data(), data.size() * 4);
    out.purpose = "tile grid, light classes" + std::string(offsets ? ", per-tile offsets" : "") +
                  std::string(in.binned ? ", binned candidates per tile" : "");
    return out;
}

} // namespace tp::fp
