#include "viewer/gpu_composite.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/stand_ins.h"
#include "core/gpu/vk_check.h"
#include "core/image/difference.h"
#include "viewer/composite_shared.h"

namespace tp::view {
namespace {

constexpr uint32_t kBins = 65536;

const LedgerTag kTag{"viewer", "", "composite", "the viewer's scene area, composed on the GPU"};

Image createSampled(GpuContext& ctx, uint32_t w, uint32_t h, const char* name) {
    ImageDesc d;
    d.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    d.width = std::max(1u, w), d.height = std::max(1u, h);
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    return createImage(ctx, d, {"viewer", "", name, "an image on the CPU, for the composite"});
}

// `rgba` (w x h RGBA float) into `image`, left SHADER_READ_ONLY_OPTIMAL.
void upload(GpuContext& ctx, const Image& image, const float* rgba, uint32_t w, uint32_t h) {
    const VkDeviceSize size = VkDeviceSize(w) * h * 16;
    Buffer staging = createBuffer(ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::Upload,
                                  {"viewer", "", "staging", "upload"});
    std::memcpy(staging.mapped, rgba, size);
    ctx.submitAndWait([&](VkCommandBuffer cmd) { recordImageUpload(cmd, image, staging.buffer, 0); });
}

Buffer storage(GpuContext& ctx, VkDeviceSize size, MemoryKind kind, const char* name) {
    return createBuffer(ctx, size,
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                            VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        kind, {"viewer", "", name, kTag.purpose});
}

} // namespace

GpuComposite::GpuComposite(GpuContext& ctx) : ctx_(ctx) {
    sampler_ = createNearestClampSampler(ctx_); // texelFetch only
    // The composite writes the bytes and reads the ramp; the stats read the images only.
    std::vector<SetBinding> bindings = {
        {TP_VC_BINDING_LEFT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {TP_VC_BINDING_RIGHT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {TP_VC_BINDING_STATS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    statsSet_ = createPassSet(ctx_, bindings);
    statsSet_.bindings = bindings; // what the shaders are checked against
    bindings.push_back({TP_VC_BINDING_OUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    composeSet_ = createPassSet(ctx_, bindings);
    composeSet_.bindings = bindings;
    composeSet_.pass = statsSet_.pass = "viewer_composite";
    VkDescriptorSetLayoutCreateInfo empty{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    VK_CHECK(vkCreateDescriptorSetLayout(ctx_.device, &empty, nullptr, &emptySet_));
    composeLayout_ = createPassPipelineLayout(ctx_, emptySet_, composeSet_.layout,
                                              VK_SHADER_STAGE_COMPUTE_BIT, sizeof(gpu::CompositePush));
    statsLayout_ = createPassPipelineLayout(ctx_, emptySet_, statsSet_.layout,
                                            VK_SHADER_STAGE_COMPUTE_BIT, sizeof(gpu::CompositePush));
    compose_ = createComputePipeline(ctx_, "viewer_composite_comp", {}, composeLayout_, &composeSet_);
    logLuminance_ =
        createComputePipeline(ctx_, "viewer_composite_stats_0_comp", {}, statsLayout_, &statsSet_);
    highHistogram_ =
        createComputePipeline(ctx_, "viewer_composite_stats_1_comp", {}, statsLayout_, &statsSet_);
    lowHistogram_ =
        createComputePipeline(ctx_, "viewer_composite_stats_2_comp", {}, statsLayout_, &statsSet_);

    std::vector<float> ramp;
    for (const auto& c : heatRamp())
        ramp.insert(ramp.end(), {c[0], c[1], c[2], 1.0f});
    ramp_ = createBufferWithData(ctx_, ramp.data(), ramp.size() * 4,
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                 {"viewer", "", "heat_ramp", kTag.purpose});
    stats_ = storage(ctx_, (kBins + 1) * 4, MemoryKind::Readback, "composite_stats");
    placeholder_ = createSampled(ctx_, 1, 1, "placeholder");
    const float black[4] = {0, 0, 0, 1};
    upload(ctx_, placeholder_, black, 1, 1);
    writeBufferDescriptor(ctx_, composeSet_.set, TP_VC_BINDING_STATS, ramp_.buffer);
    writeBufferDescriptor(ctx_, statsSet_.set, TP_VC_BINDING_STATS, stats_.buffer);
}

GpuComposite::~GpuComposite() {
    ctx_.waitIdle();
    for (VkPipeline p : {compose_, logLuminance_, highHistogram_, lowHistogram_})
        vkDestroyPipeline(ctx_.device, p, nullptr);
    vkDestroyPipelineLayout(ctx_.device, composeLayout_, nullptr);
    vkDestroyPipelineLayout(ctx_.device, statsLayout_, nullptr);
    vkDestroyDescriptorSetLayout(ctx_.device, emptySet_, nullptr);
    destroyPassSet(ctx_, composeSet_);
    destroyPassSet(ctx_, statsSet_);
    vkDestroySampler(ctx_.device, sampler_, nullptr);
}

// The side's GPU image, or its CPU image uploaded into slot `slot` (once per serial); the
// placeholder when it is absent.
const Image& GpuComposite::resolve(const CompositeSide& side, int slot) {
    if (side.gpu) return *side.gpu;
    if (!side.cpu || side.cpu->width == 0) return placeholder_;
    Image& image = uploaded_[slot];
    if (uploadedSerial_[slot] != side.serial || !image.image ||
        image.desc.width != side.cpu->width || image.desc.height != side.cpu->height) {
        image = createSampled(ctx_, side.cpu->width, side.cpu->height,
                              slot == 0 ? "uploaded_a" : "uploaded_b");
        upload(ctx_, image, side.cpu->rgba.data(), side.cpu->width, side.cpu->height);
        uploadedSerial_[slot] = side.serial;
    }
    return image;
}

void GpuComposite::bindSides(const Image& left, const Image& right) {
    for (VkDescriptorSet set : {composeSet_.set, statsSet_.set}) {
        writeImageDescriptor(ctx_, set, TP_VC_BINDING_LEFT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                             left.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, sampler_);
        writeImageDescriptor(ctx_, set, TP_VC_BINDING_RIGHT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                             right.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, sampler_);
    }
}

// One dispatch over width x height, waited for; `stats`: into the stats buffer, left readable
// by the host; else into the composite, left for the UI frame's copy.
void GpuComposite::dispatch(VkPipeline pipeline, const gpu::CompositePush& push, uint32_t width,
                            uint32_t height, bool stats) {
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        // The stats start from zero; the composite from black (what a missing side shows, and
        // the legend rows of a difference that has none).
        vkCmdFillBuffer(cmd, stats ? stats_.buffer : out_.buffer, 0, VK_WHOLE_SIZE,
                        stats ? 0u : 0xff000000u);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        const VkPipelineLayout layout = stats ? statsLayout_ : composeLayout_;
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 1, 1,
                                stats ? &statsSet_.set : &composeSet_.set, 0, nullptr);
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdDispatch(cmd, (width + TP_VC_GROUP - 1) / TP_VC_GROUP,
                      (height + TP_VC_GROUP - 1) / TP_VC_GROUP, 1);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      stats ? VK_PIPELINE_STAGE_2_HOST_BIT : VK_PIPELINE_STAGE_2_COPY_BIT,
                      stats ? VK_ACCESS_2_HOST_READ_BIT : VK_ACCESS_2_TRANSFER_READ_BIT);
    });
}

float GpuComposite::autoExposureEv(const CompositeSide& side) {
    if (!side.present()) return 0.0f;
    const Image& image = resolve(side, 0);
    bindSides(image, image);
    gpu::CompositePush push{};
    push.width = side.width(), push.height = side.height();
    const uint32_t groupsX = (push.width + TP_VC_GROUP - 1) / TP_VC_GROUP;
    const uint32_t groups = groupsX * ((push.height + TP_VC_GROUP - 1) / TP_VC_GROUP);
    if (uint64_t(groups) * 8 > stats_.size) { // past 32,768 workgroups (8.4 M pixels: over 4K UHD)
        stats_ = storage(ctx_, uint64_t(groups) * 8, MemoryKind::Readback, "composite_stats");
        writeBufferDescriptor(ctx_, statsSet_.set, TP_VC_BINDING_STATS, stats_.buffer);
    }
    dispatch(logLuminance_, push, push.width, push.height, true);
    // The CPU rule's sums are in double: the partial sums (float, 256 pixels each) are added so.
    const auto* words = static_cast<const uint32_t*>(stats_.mapped);
    double logSum = 0.0;
    uint64_t count = 0;
    for (uint32_t g = 0; g < groups; ++g) {
        float sum;
        std::memcpy(&sum, &words[g * 2], 4);
        logSum += double(sum);
        count += words[g * 2 + 1];
    }
    if (count == 0) return 0.0f;
    return float(std::log2(0.18) - (logSum / double(count)) / std::log(2.0));
}

std::vector<uint32_t> GpuComposite::histogram(VkPipeline pipeline, gpu::CompositePush push,
                                              uint32_t words) {
    dispatch(pipeline, push, push.width, push.height, true);
    const auto* w = static_cast<const uint32_t*>(stats_.mapped);
    return std::vector<uint32_t>(w, w + words);
}

// differencePercentile99's value, exactly: the k-th smallest finite value (k from the count)
// is found bin by bin over its high, then its low 16 bits.
float GpuComposite::percentile99(uint32_t w, uint32_t h) {
    gpu::CompositePush push{};
    push.width = w, push.height = h;
    const std::vector<uint32_t> high = histogram(highHistogram_, push, kBins + 1);
    const uint64_t n = high[kBins];
    if (n == 0) return 0.0f;
    uint64_t k = std::min<uint64_t>(n - 1, uint64_t(std::ceil(0.99 * double(n))) - 1);
    uint32_t prefix = 0;
    for (; prefix < kBins && k >= high[prefix]; ++prefix)
        k -= high[prefix];
    push.prefix = prefix;
    const std::vector<uint32_t> low = histogram(lowHistogram_, push, kBins);
    uint32_t bits = 0;
    for (; bits < kBins && k >= low[bits]; ++bits)
        k -= low[bits];
    const uint32_t value = (prefix << 16) | bits;
    float v;
    std::memcpy(&v, &value, 4);
    return v;
}

Composite GpuComposite::compose(const CompositeInput& in, const CompositeSide& a,
                                const CompositeSide& b, uint32_t width, uint32_t height,
                                bool swapRB) {
    Composite out;
    out.width = width;
    const bool difference = in.mode == DisplayMode::Difference;
    out.height = height + (difference ? kLegendHeight : 0);
    const uint64_t bytes = std::max<uint64_t>(4, uint64_t(out.width) * out.height * 4);
    if (out_.size < bytes) out_ = storage(ctx_, bytes, MemoryKind::Device, "composite");
    writeBufferDescriptor(ctx_, composeSet_.set, TP_VC_BINDING_OUT, out_.buffer);
    gpu::CompositePush push{};
    push.width = width, push.height = height;
    push.swapRB = swapRB ? 1u : 0u;
    push.exposureEv = in.exposureEv;
    push.divider = 0xffffffffu;
    if (difference) {
        push.mode = TP_VC_DIFFERENCE;
        if (!a.present() || !b.present() || a.width() != b.width() || a.height() != b.height()) {
            out.note = "the difference needs both images at one size";
            bindSides(placeholder_, placeholder_);
            push.mode = TP_VC_SPLIT; // black
        } else {
            bindSides(resolve(a, 0), resolve(b, 1));
            out.diffScale = percentile99(width, height);
            if (!(out.diffScale > 0.0f)) out.diffScale = 1e-6f;
            push.diffScale = out.diffScale;
        }
    } else {
        const CompositeSide& left = in.flip ? b : a;
        const CompositeSide& right = in.flip ? a : b;
        bindSides(resolve(left, in.flip ? 1 : 0), resolve(right, in.flip ? 0 : 1));
        push.mode = TP_VC_SPLIT;
        push.boundary = std::min(width, uint32_t(std::floor(std::clamp(in.split, 0.0f, 1.0f) *
                                                            float(width))));
        push.sides = (left.present() ? 1u : 0u) | (right.present() ? 2u : 0u);
        if (!left.present() || !right.present()) out.note = "rendering...";
        if (in.split > 0.0f && in.split < 1.0f) push.divider = dividerColumn(in.split, width);
    }
    dispatch(compose_, push, width, height, false);
    if (difference && out.diffScale > 0.0f) { // the legend rows: the CPU's (their labels)
        ImageRGBA legend = heatMap(ImageRGBA(width, 0), out.diffScale, kLegendHeight);
        std::vector<uint32_t> rows(size_t(width) * kLegendHeight);
        for (size_t i = 0; i < rows.size(); ++i) {
            const float* p = &legend.rgba[i * 4];
            uint32_t c[3];
            for (int k = 0; k < 3; ++k)
                c[k] = uint32_t(std::lround(std::clamp(p[k], 0.0f, 1.0f) * 255.0f));
            rows[i] = swapRB ? (c[2] | c[1] << 8 | c[0] << 16 | 255u << 24)
                             : (c[0] | c[1] << 8 | c[2] << 16 | 255u << 24);
        }
        Buffer staging = createBuffer(ctx_, rows.size() * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                      MemoryKind::Upload, {"viewer", "", "staging", "upload"});
        std::memcpy(staging.mapped, rows.data(), rows.size() * 4);
        ctx_.submitAndWait([&](VkCommandBuffer cmd) {
            VkBufferCopy copy{0, VkDeviceSize(width) * height * 4, rows.size() * 4};
            vkCmdCopyBuffer(cmd, staging.buffer, out_.buffer, 1, &copy);
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        });
    }
    return out;
}

std::vector<uint8_t> GpuComposite::readBytes(const Composite& c) {
    const VkDeviceSize size = VkDeviceSize(c.width) * c.height * 4;
    Buffer staging = createBuffer(ctx_, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  MemoryKind::Readback, {"viewer", "", "staging", "readback"});
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy copy{0, 0, size};
        vkCmdCopyBuffer(cmd, out_.buffer, staging.buffer, 1, &copy);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    std::vector<uint8_t> bytes(size);
    std::memcpy(bytes.data(), staging.mapped, size);
    return bytes;
}

} // namespace tp::view
