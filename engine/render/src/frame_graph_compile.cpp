// FrameGraph::compile(): culling, dependency ordering, barrier computation and transient
// resource creation. Everything but createTransients() is pure bookkeeping and is exercised by
// tests without a device.
#include <algorithm>
#include <cstring>
#include <map>
#include <string>

#include "engine/core/error.h"
#include "engine/gfx/formats.h"
#include "engine/render/frame_graph.h"

namespace engine::render {
namespace {

constexpr VkAccessFlags2 kWriteAccessBits =
    VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;

// Per-resource synchronisation state while walking the passes in execution order.
struct Track {
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags2 writeStages = VK_PIPELINE_STAGE_2_NONE;    // last write (or transition)
  VkAccessFlags2 writeAccess = VK_ACCESS_2_NONE;                   // its write accesses
  VkPipelineStageFlags2 readStages = VK_PIPELINE_STAGE_2_NONE;     // reads since then
  VkPipelineStageFlags2 visibleStages = VK_PIPELINE_STAGE_2_NONE;  // stages that see the write
};

// The merged use of one resource by one pass.
struct MergedUse {
  std::uint16_t resource;
  ResourceState state;
  bool write;
};

// Returns the barrier `use` needs after `track`, or nothing, and advances `track`.
std::optional<CompiledBarrier> advance(Track& track, const MergedUse& use, bool texture) {
  const ResourceState& to = use.state;
  const bool layoutChange = texture && to.layout != track.layout;
  std::optional<CompiledBarrier> barrier;
  if (layoutChange || use.write) {
    // Layout transitions and writes wait for every earlier access (RAW/WAW/WAR).
    const VkPipelineStageFlags2 src = track.writeStages | track.readStages;
    if (layoutChange || src != VK_PIPELINE_STAGE_2_NONE) {
      barrier = CompiledBarrier{use.resource, texture,
                                ResourceState{track.layout, src, track.writeAccess}, to};
    }
  } else if (track.writeStages != VK_PIPELINE_STAGE_2_NONE &&
             (to.stages & ~track.visibleStages) != 0) {
    // A read in a stage that has not yet been made to see the last write.
    barrier =
        CompiledBarrier{use.resource, texture,
                        ResourceState{track.layout, track.writeStages, track.writeAccess}, to};
  }
  if (layoutChange || use.write) {
    track.writeStages = to.stages;
    track.writeAccess = use.write ? (to.access & kWriteAccessBits) : VK_ACCESS_2_NONE;
    track.readStages = use.write ? VK_PIPELINE_STAGE_2_NONE : to.stages;
    track.visibleStages = to.stages;
  } else {
    track.readStages |= to.stages;
    if (barrier) track.visibleStages |= to.stages;
  }
  if (texture) track.layout = to.layout;
  return barrier;
}

}  // namespace

void FrameGraph::compile() {
  require(!compiled_, "FrameGraph::compile", "already compiled");
  cull();
  order();
  computeBarriers();
  if (device_ != nullptr) createTransients();
  prepareVulkanBarriers();
  compiled_ = true;
}

void FrameGraph::cull() {
  // readers[(resource, version)] counts passes that need that version: explicit reads, and
  // writers of the next version (a write may read-modify-write what was there).
  std::map<std::pair<std::uint16_t, std::uint16_t>, int> readers;
  std::map<std::pair<std::uint16_t, std::uint16_t>, std::uint16_t> producer;
  std::vector<int> refCount(passes_.size(), 0);
  auto implicitReads = [&](const Pass& pass, auto&& visit) {
    for (const Use& r : pass.reads) visit(r.resource, r.version);
    for (const Use& w : pass.writes) {
      if (w.version > 1 || resources_[w.resource].imported) visit(w.resource, w.version - 1);
    }
  };
  const auto passCount = static_cast<std::uint16_t>(passes_.size());
  for (std::uint16_t p = 0; p < passCount; ++p) {
    const Pass& pass = passes_[p];
    implicitReads(pass, [&](std::uint16_t r, std::uint16_t v) { ++readers[{r, v}]; });
    for (const Use& w : pass.writes) producer[{w.resource, w.version}] = p;
    refCount[p] = static_cast<int>(pass.writes.size()) + (pass.sideEffect ? 1 : 0);
  }

  std::vector<std::uint16_t> deadPasses;
  std::vector<std::pair<std::uint16_t, std::uint16_t>> unread;
  for (const auto& [key, pass] : producer) {
    if (!resources_[key.first].imported && readers[key] == 0) unread.push_back(key);
  }
  for (std::uint16_t p = 0; p < passCount; ++p) {
    if (refCount[p] == 0) deadPasses.push_back(p);
  }
  // Peel passes whose every output is unread, then what only they read, until stable.
  while (!unread.empty() || !deadPasses.empty()) {
    if (!unread.empty()) {
      const auto key = unread.back();
      unread.pop_back();
      const std::uint16_t p = producer[key];
      if (--refCount[p] == 0) deadPasses.push_back(p);
      continue;
    }
    const std::uint16_t p = deadPasses.back();
    deadPasses.pop_back();
    passes_[p].culled = true;
    implicitReads(passes_[p], [&](std::uint16_t r, std::uint16_t v) {
      const auto key = std::make_pair(r, v);
      if (--readers[key] == 0 && producer.count(key) != 0 && !resources_[r].imported) {
        unread.push_back(key);
      }
    });
  }
}

void FrameGraph::order() {
  // Kahn's algorithm over the live passes. Edges: producer of a version -> its readers;
  // readers of a version -> the writer of the next version (write-after-read). Among ready
  // passes the earliest declared goes first, so independent passes keep declaration order.
  const auto n = static_cast<std::uint16_t>(passes_.size());
  std::vector<std::vector<std::uint16_t>> successors(n);
  std::vector<int> inDegree(n, 0);
  std::map<std::pair<std::uint16_t, std::uint16_t>, std::uint16_t> producer;
  std::map<std::pair<std::uint16_t, std::uint16_t>, std::vector<std::uint16_t>> readersOf;
  for (std::uint16_t p = 0; p < n; ++p) {
    if (passes_[p].culled) continue;
    for (const Use& w : passes_[p].writes) producer[{w.resource, w.version}] = p;
    for (const Use& r : passes_[p].reads) readersOf[{r.resource, r.version}].push_back(p);
  }
  auto addEdge = [&](std::uint16_t from, std::uint16_t to) {
    if (from == to) return;
    successors[from].push_back(to);
    ++inDegree[to];
  };
  for (std::uint16_t p = 0; p < n; ++p) {
    if (passes_[p].culled) continue;
    for (const Use& r : passes_[p].reads) {
      if (auto it = producer.find({r.resource, r.version}); it != producer.end()) {
        addEdge(it->second, p);
      }
    }
    for (const Use& w : passes_[p].writes) {
      const std::pair<std::uint16_t, std::uint16_t> previous{
          w.resource, static_cast<std::uint16_t>(w.version - 1)};
      if (auto it = producer.find(previous); it != producer.end()) addEdge(it->second, p);
      if (auto it = readersOf.find(previous); it != readersOf.end()) {
        for (std::uint16_t reader : it->second) addEdge(reader, p);
      }
    }
  }
  order_.clear();
  std::vector<bool> done(n, false);
  for (;;) {
    std::optional<std::uint16_t> next;
    for (std::uint16_t p = 0; p < n; ++p) {
      if (!passes_[p].culled && !done[p] && inDegree[p] == 0) {
        next = p;
        break;
      }
    }
    if (!next) break;
    done[*next] = true;
    order_.push_back(*next);
    for (std::uint16_t s : successors[*next]) --inDegree[s];
  }
  for (std::uint16_t p = 0; p < n; ++p) {
    if (!passes_[p].culled && !done[p]) {
      throw Error(std::string("frame graph: dependency cycle through pass '") + passes_[p].name +
                  "'");
    }
  }
}

void FrameGraph::computeBarriers() {
  std::vector<Track> tracks(resources_.size());
  for (std::size_t i = 0; i < resources_.size(); ++i) {
    const Resource& r = resources_[i];
    if (!r.imported) continue;
    const ResourceState& initial = r.texture ? r.importedTexture.initial : r.importedBuffer.initial;
    tracks[i].layout = initial.layout;
    tracks[i].writeStages = initial.stages;
    tracks[i].writeAccess = initial.access & kWriteAccessBits;
  }
  for (std::uint16_t p : order_) {
    Pass& pass = passes_[p];
    pass.barriers.clear();
    std::vector<MergedUse> merged;
    auto merge = [&](const Use& use, bool write) {
      const Resource& r = resources_[use.resource];
      const bool depth = r.texture && gfx::isDepthFormat(r.textureDesc.format);
      const ResourceState state = stateFor(use.access, pass.type, depth);
      for (MergedUse& m : merged) {
        if (m.resource != use.resource) continue;
        if (r.texture && m.state.layout != state.layout) {
          throw Error(std::string("frame graph pass '") + pass.name + "' uses '" + r.name +
                      "' in two layouts");
        }
        m.state.stages |= state.stages;
        m.state.access |= state.access;
        m.write = m.write || write;
        return;
      }
      merged.push_back(MergedUse{use.resource, state, write});
    };
    for (const Use& use : pass.reads) merge(use, false);
    for (const Use& use : pass.writes) merge(use, true);
    for (const MergedUse& use : merged) {
      if (auto barrier = advance(tracks[use.resource], use, resources_[use.resource].texture)) {
        pass.barriers.push_back(*barrier);
      }
    }
  }
  finalBarriers_.clear();
  const auto resourceCount = static_cast<std::uint16_t>(resources_.size());
  for (std::uint16_t i = 0; i < resourceCount; ++i) {
    const Resource& r = resources_[i];
    if (!r.imported) continue;
    const auto& final = r.texture ? r.importedTexture.final : r.importedBuffer.final;
    if (!final) continue;
    const Track& t = tracks[i];
    const bool layoutChange = r.texture && t.layout != final->layout;
    const VkPipelineStageFlags2 src = t.writeStages | t.readStages;
    if (!layoutChange &&
        (src == VK_PIPELINE_STAGE_2_NONE || final->stages == VK_PIPELINE_STAGE_2_NONE)) {
      continue;
    }
    finalBarriers_.push_back(
        CompiledBarrier{i, r.texture, ResourceState{t.layout, src, t.writeAccess}, *final});
  }
}

void FrameGraph::createTransients() {
  for (Resource& r : resources_) {
    if (r.imported) continue;
    if (r.texture) {
      if (r.imageUsage == 0) continue;  // only used by culled passes
      gfx::ImageDesc desc;
      desc.type = r.textureDesc.type;
      desc.format = r.textureDesc.format;
      desc.extent = r.textureDesc.extent;
      desc.mipLevels = r.textureDesc.mipLevels;
      desc.arrayLayers = r.textureDesc.arrayLayers;
      desc.usage = r.imageUsage;
      desc.debugName = r.name;
      r.ownedImage = gfx::Image(*device_, desc);
    } else {
      if (r.bufferUsage == 0) continue;
      r.ownedBuffer = gfx::Buffer(*device_, gfx::BufferDesc{r.bufferDesc.sizeBytes, r.bufferUsage,
                                                            r.bufferDesc.memory, r.name});
    }
  }
}

void FrameGraph::fillVulkanBarriers(std::span<const CompiledBarrier> barriers,
                                    std::vector<VkImageMemoryBarrier2>& images,
                                    std::vector<VkBufferMemoryBarrier2>& buffers) const {
  images.clear();
  buffers.clear();
  for (const CompiledBarrier& b : barriers) {
    if (b.texture) {
      const Resource& r = resources_[b.resource];
      VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
      barrier.srcStageMask = b.from.stages;
      barrier.srcAccessMask = b.from.access;
      barrier.dstStageMask = b.to.stages;
      barrier.dstAccessMask = b.to.access;
      barrier.oldLayout = b.from.layout;
      barrier.newLayout = b.to.layout;
      barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      barrier.subresourceRange = {gfx::aspectMask(r.textureDesc.format), 0, r.textureDesc.mipLevels,
                                  0, r.textureDesc.arrayLayers};
      images.push_back(barrier);
    } else {
      VkBufferMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
      barrier.srcStageMask = b.from.stages;
      barrier.srcAccessMask = b.from.access;
      barrier.dstStageMask = b.to.stages;
      barrier.dstAccessMask = b.to.access;
      barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      barrier.size = VK_WHOLE_SIZE;
      buffers.push_back(barrier);
    }
  }
}

void FrameGraph::refreshBarrierHandles(std::span<const CompiledBarrier> barriers,
                                       std::vector<VkImageMemoryBarrier2>& images,
                                       std::vector<VkBufferMemoryBarrier2>& buffers) const {
  std::size_t image = 0;
  std::size_t buffer = 0;
  for (const CompiledBarrier& b : barriers) {
    if (b.texture) {
      images[image++].image = vkImage(b.resource);
    } else {
      buffers[buffer++].buffer = vkBuffer(b.resource);
    }
  }
}

void FrameGraph::prepareVulkanBarriers() {
  for (std::uint16_t p : order_) {
    Pass& pass = passes_[p];
    fillVulkanBarriers(pass.barriers, pass.imageBarriers, pass.bufferBarriers);
    pass.colorInfos.clear();
    for (const Attachment& a : pass.attachments) {
      VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
      info.loadOp = a.readOnly ? VK_ATTACHMENT_LOAD_OP_LOAD : a.load;
      info.storeOp = a.readOnly ? VK_ATTACHMENT_STORE_OP_NONE : VK_ATTACHMENT_STORE_OP_STORE;
      info.clearValue = a.clear;
      if (a.depth) {
        info.imageLayout = a.readOnly ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                                      : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        pass.depthInfo = info;
      } else {
        info.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        pass.colorInfos.push_back(info);
      }
    }
  }
  fillVulkanBarriers(finalBarriers_, finalImageBarriers_, finalBufferBarriers_);
}

std::vector<const char*> FrameGraph::executionOrder() const {
  std::vector<const char*> names;
  for (std::uint16_t p : order_) names.push_back(passes_[p].name);
  return names;
}

std::vector<const char*> FrameGraph::culledPasses() const {
  std::vector<const char*> names;
  for (const Pass& pass : passes_) {
    if (pass.culled) names.push_back(pass.name);
  }
  return names;
}

std::vector<const char*> FrameGraph::declaredPasses() const {
  std::vector<const char*> names;
  for (const Pass& pass : passes_) names.push_back(pass.name);
  return names;
}

std::span<const CompiledBarrier> FrameGraph::barriersBefore(const char* passName) const {
  for (const Pass& pass : passes_) {
    if (std::strcmp(pass.name, passName) == 0) return pass.barriers;
  }
  throw Error(std::string("frame graph: no pass named '") + passName + "'");
}

}  // namespace engine::render
