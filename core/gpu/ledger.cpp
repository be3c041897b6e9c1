#include "core/gpu/ledger.h"

#include <algorithm>

namespace tp {

uint64_t MemoryLedger::add(LedgerEntry entry) {
    entry.id = nextId_++;
    entries_.push_back(entry);
    return entry.id;
}

void MemoryLedger::remove(uint64_t id) {
    std::erase_if(entries_, [id](const LedgerEntry& e) { return e.id == id; });
}

std::vector<LedgerEntry> MemoryLedger::entriesOf(const std::string& owner) const {
    std::vector<LedgerEntry> out;
    for (const LedgerEntry& e : entries_)
        if (e.tag.owner == owner) out.push_back(e);
    return out;
}

uint64_t MemoryLedger::totalBytes(const std::string& owner) const {
    uint64_t total = 0;
    for (const LedgerEntry& e : entries_)
        if (e.tag.owner == owner) total += e.bytes;
    return total;
}

uint32_t formatBytesPerTexel(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R8_UNORM:
        return 1;
    case VK_FORMAT_R8G8_UNORM:
        return 2;
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
    case VK_FORMAT_E5B9G9R9_UFLOAT_PACK32:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R16G16_UNORM:
    case VK_FORMAT_R16G16_SNORM:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_D32_SFLOAT:
        return 4;
    case VK_FORMAT_D32_SFLOAT_S8_UINT: // the data: depth and stencil are two planes on GPUs
        return 5;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT:
    case VK_FORMAT_R32G32_UINT:
        return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_UINT:
        return 16;
    default:
        return 0;
    }
}

const char* formatName(VkFormat format) {
    switch (format) {
    case VK_FORMAT_UNDEFINED:
        return "buffer";
    case VK_FORMAT_R8_UNORM:
        return "R8_UNORM";
    case VK_FORMAT_R8G8_UNORM:
        return "RG8_UNORM";
    case VK_FORMAT_R8G8B8A8_UNORM:
        return "RGBA8_UNORM";
    case VK_FORMAT_R8G8B8A8_SRGB:
        return "RGBA8_SRGB";
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
        return "RGB10A2_UNORM";
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
        return "RG11B10_UFLOAT";
    case VK_FORMAT_E5B9G9R9_UFLOAT_PACK32:
        return "RGB9E5_UFLOAT";
    case VK_FORMAT_R16G16_SFLOAT:
        return "RG16_SFLOAT";
    case VK_FORMAT_R16G16_UNORM:
        return "RG16_UNORM";
    case VK_FORMAT_R16G16_SNORM:
        return "RG16_SNORM";
    case VK_FORMAT_R32_SFLOAT:
        return "R32_SFLOAT";
    case VK_FORMAT_R32_UINT:
        return "R32_UINT";
    case VK_FORMAT_D32_SFLOAT:
        return "D32_SFLOAT";
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
        return "D32_SFLOAT_S8_UINT";
    case VK_FORMAT_R16G16B16A16_SFLOAT:
        return "RGBA16_SFLOAT";
    case VK_FORMAT_R32G32_SFLOAT:
        return "RG32_SFLOAT";
    case VK_FORMAT_R32G32_UINT:
        return "RG32_UINT";
    case VK_FORMAT_R32G32B32A32_SFLOAT:
        return "RGBA32_SFLOAT";
    case VK_FORMAT_R32G32B32A32_UINT:
        return "RGBA32_UINT";
    default:
        return "other";
    }
}

} // namespace tp
