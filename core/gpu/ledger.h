#pragma once
// The memory ledger: every buffer and image the program allocates, tagged with who owns it
// (pipeline, pass), what it is for, its format, extent, samples and the bytes the driver
// actually asked for (VkMemoryRequirements::size). Memory reports come from here only.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace tp {

struct LedgerTag {
    std::string
        owner; // "scene" (shared by every pipeline), "reference" or the pipeline's registered name
    std::string pass;    // pass that first writes it, or "" for shared data
    std::string name;    // e.g. "hdr", "depth_msaa", "light_lists"
    std::string purpose; // one line for the report
};

struct LedgerEntry {
    uint64_t id = 0;
    LedgerTag tag;
    bool isImage = false;
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t width = 0, height = 0, mipLevels = 1, samples = 1;
    uint64_t requestedBytes = 0; // buffer size / image texel bytes
    uint64_t bytes = 0;          // what the driver required
};

class MemoryLedger {
  public:
    uint64_t add(LedgerEntry entry);
    void remove(uint64_t id);
    std::vector<LedgerEntry> entries() const { return entries_; }
    std::vector<LedgerEntry> entriesOf(const std::string& owner) const;
    uint64_t totalBytes(const std::string& owner) const;

  private:
    std::vector<LedgerEntry> entries_;
    uint64_t nextId_ = 1;
};

uint32_t formatBytesPerTexel(VkFormat format);
const char* formatName(VkFormat format);

} // namespace tp
