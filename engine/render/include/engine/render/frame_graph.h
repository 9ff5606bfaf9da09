#pragma once
// A frame graph in the style of Filament's: passes declare typed, versioned reads and writes in
// a setup callback and record commands in an execute callback. compile() culls passes whose
// outputs nobody reads, orders the rest by their dependencies, computes every barrier and
// layout transition, and creates the transient textures and buffers. The graph is built when
// the scene or the output size changes and executed every frame; executing records barriers,
// passes and GPU timestamps into the frame's command buffer without heap allocation.
//
// Pass and resource names must be string literals: GPU timings refer to them after the graph
// that named them has been rebuilt.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/gfx/descriptors.h"
#include "engine/gfx/device.h"
#include "engine/gfx/frame_ring.h"
#include "engine/gfx/resources.h"
#include "engine/render/blackboard.h"
#include "engine/render/resource_access.h"

namespace engine::render {

template <typename Tag>
struct ResourceHandle {
  static constexpr std::uint16_t kInvalid = 0xFFFF;
  std::uint16_t index = kInvalid;
  std::uint16_t version = 0;
  bool valid() const { return index != kInvalid; }
  bool operator==(const ResourceHandle&) const = default;
};
struct TextureTag;
struct BufferTag;
using TextureHandle = ResourceHandle<TextureTag>;
using BufferHandle = ResourceHandle<BufferTag>;

struct TextureDesc {
  VkExtent3D extent{1, 1, 1};
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkImageType type = VK_IMAGE_TYPE_2D;
  std::uint32_t mipLevels = 1;
  std::uint32_t arrayLayers = 1;
};

struct BufferDesc {
  VkDeviceSize sizeBytes = 0;
  gfx::MemoryUsage memory = gfx::MemoryUsage::GpuOnly;
};

// A texture owned outside the graph (swapchain image, history, a module's output). `initial`
// is its state when the frame's commands start; `final`, if set, is the state the graph leaves
// it in (e.g. PRESENT_SRC for the swapchain), so the next frame can rely on it.
struct ImportedTexture {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  TextureDesc desc;
  ResourceState initial;
  std::optional<ResourceState> final;
};

struct ImportedBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize sizeBytes = 0;
  ResourceState initial;
  std::optional<ResourceState> final;
};

struct CompiledBarrier {
  std::uint16_t resource = 0;
  bool texture = true;
  ResourceState from;
  ResourceState to;
};

class FrameGraph;

// Given to execute callbacks: the command buffer and the real objects behind handles.
class PassContext {
 public:
  VkCommandBuffer cmd() const { return frame_->cmd; }
  gfx::Device& device() const { return *device_; }
  gfx::DescriptorArena& descriptors() const { return *frame_->descriptors; }
  gfx::ConstantRing& constants() const { return *frame_->constants; }
  std::uint64_t frameIndex() const { return frame_->index; }
  // The graph's per-frame values: a publishing pass writes its entry here, a reader reads it.
  Blackboard& blackboard() const;

  VkImage image(TextureHandle h) const;
  VkImageView view(TextureHandle h) const;
  VkExtent3D extent(TextureHandle h) const;
  VkFormat format(TextureHandle h) const;
  VkBuffer buffer(BufferHandle h) const;

  // Binds `pipeline` with a per-frame descriptor set written by `writer`.
  void bind(const gfx::Pipeline& pipeline, const gfx::DescriptorWriter& writer) const;

 private:
  friend class FrameGraph;
  FrameGraph* graph_ = nullptr;
  gfx::Device* device_ = nullptr;
  const gfx::FrameRing::Frame* frame_ = nullptr;
};

class PassBuilder {
 public:
  TextureHandle createTexture(const char* name, const TextureDesc& desc);
  BufferHandle createBuffer(const char* name, const BufferDesc& desc);
  // Reads keep the version; writes return the next version, which later passes must use.
  TextureHandle read(TextureHandle texture, Access access = Access::SampledRead);
  TextureHandle write(TextureHandle texture, Access access = Access::StorageWrite);
  BufferHandle read(BufferHandle buffer, Access access = Access::StorageBufferRead);
  BufferHandle write(BufferHandle buffer, Access access = Access::StorageBufferWrite);
  // Graphics passes: the graph begins and ends dynamic rendering around execute, with the
  // viewport and scissor covering the first attachment.
  TextureHandle colorAttachment(TextureHandle texture, VkAttachmentLoadOp load,
                                VkClearColorValue clear = {});
  TextureHandle depthAttachment(TextureHandle texture, VkAttachmentLoadOp load,
                                float clearDepth = 0.0f /* reversed-Z far plane */);
  void depthReadOnlyAttachment(TextureHandle texture);
  // The pass has effects outside the graph (e.g. a readback); it is never culled.
  void sideEffect();

 private:
  friend class FrameGraph;
  PassBuilder(FrameGraph& graph, std::uint16_t pass) : graph_(graph), pass_(pass) {}
  FrameGraph& graph_;
  std::uint16_t pass_;
};

class FrameGraph {
 public:
  // Without a device the graph can still be built and compiled (tests of ordering, culling
  // and barriers); it cannot execute.
  explicit FrameGraph(gfx::Device* device = nullptr);
  ~FrameGraph();
  FrameGraph(const FrameGraph&) = delete;
  FrameGraph& operator=(const FrameGraph&) = delete;

  TextureHandle importTexture(const char* name, const ImportedTexture& texture);
  BufferHandle importBuffer(const char* name, const ImportedBuffer& buffer);
  // Points an imported texture at another image with the same description (e.g. this frame's
  // swapchain image). Valid after compile().
  void updateImportedTexture(TextureHandle texture, VkImage image, VkImageView view);
  void updateImportedBuffer(BufferHandle buffer, VkBuffer vkBuffer);

  // Setup runs now: `setup(PassBuilder&, Data&)`. Execute runs per frame:
  // `execute(const Data&, PassContext&)`.
  template <typename Data, typename Setup, typename Execute>
  const Data& addPass(const char* name, PassType type, Setup&& setup, Execute&& execute);

  void compile();
  void execute(const gfx::FrameRing::Frame& frame);

  // Per-frame values passes publish for each other (blackboard.h): put while building,
  // written and read by passes when they execute (PassContext::blackboard()).
  Blackboard& blackboard() { return blackboard_; }
  const Blackboard& blackboard() const { return blackboard_; }

  // Exact per-pass GPU times (default on): each pass's end timestamp waits behind a full
  // execution barrier, so a pass's time is its own work. Without it, work a device defers
  // (lavapipe rasterises a render pass at the next synchronisation) is billed to whichever
  // later pass waits for it. Costs the overlap of consecutive passes on GPUs that overlap.
  void setExactPassTimes(bool exact) { exactPassTimes_ = exact; }

  // --- Introspection (tests, debugging, the sample's pass list) -------------------------
  std::vector<const char*> executionOrder() const;
  std::vector<const char*> culledPasses() const;
  std::vector<const char*> declaredPasses() const;
  std::span<const CompiledBarrier> barriersBefore(const char* passName) const;
  std::span<const CompiledBarrier> finalBarriers() const { return finalBarriers_; }
  const char* resourceName(std::uint16_t resource) const;
  // Real objects behind handles (after compile()); used by callers to read back outputs.
  VkImage image(TextureHandle h) const;
  VkImageView view(TextureHandle h) const;
  VkBuffer buffer(BufferHandle h) const;
  const TextureDesc& textureDesc(TextureHandle h) const;
  bool compiled() const { return compiled_; }

 private:
  friend class PassBuilder;
  friend class PassContext;

  struct ExecutorBase {
    virtual ~ExecutorBase() = default;
    virtual void run(PassContext& context) = 0;
  };
  template <typename Data, typename Execute>
  struct Executor final : ExecutorBase {
    Data data;
    Execute execute;
    explicit Executor(Execute e) : execute(std::move(e)) {}
    void run(PassContext& context) override { execute(static_cast<const Data&>(data), context); }
  };

  struct Resource {
    const char* name = "";
    bool texture = true;
    bool imported = false;
    std::uint16_t version = 0;  // latest version handed out
    TextureDesc textureDesc;
    BufferDesc bufferDesc;
    ImportedTexture importedTexture;
    ImportedBuffer importedBuffer;
    VkImageUsageFlags imageUsage = 0;
    VkBufferUsageFlags bufferUsage = 0;
    gfx::Image ownedImage;
    gfx::Buffer ownedBuffer;
  };
  struct Use {
    std::uint16_t resource = 0;
    std::uint16_t version = 0;
    Access access = Access::SampledRead;
  };
  struct Attachment {
    std::uint16_t resource = 0;
    VkAttachmentLoadOp load = VK_ATTACHMENT_LOAD_OP_LOAD;
    VkClearValue clear{};
    bool depth = false;
    bool readOnly = false;
  };
  struct Pass {
    const char* name = "";
    PassType type = PassType::Compute;
    std::vector<Use> reads;
    std::vector<Use> writes;
    std::vector<Attachment> attachments;
    bool sideEffect = false;
    bool culled = false;
    std::unique_ptr<ExecutorBase> executor;
    // Filled by compile():
    std::vector<CompiledBarrier> barriers;
    std::vector<VkImageMemoryBarrier2> imageBarriers;
    std::vector<VkBufferMemoryBarrier2> bufferBarriers;
    std::vector<VkRenderingAttachmentInfo> colorInfos;
    VkRenderingAttachmentInfo depthInfo{};
  };

  std::uint16_t addResource(Resource resource);
  std::uint16_t beginPass(const char* name, PassType type, std::unique_ptr<ExecutorBase> executor);
  ExecutorBase& executorOf(std::uint16_t pass) { return *passes_[pass].executor; }
  Use recordUse(std::uint16_t pass, std::uint16_t resource, std::uint16_t version, Access access,
                bool write, bool texture);
  const Resource& resourceOf(std::uint16_t index, bool texture) const;

  void cull();
  void order();
  void computeBarriers();
  void createTransients();
  void prepareVulkanBarriers();
  void fillVulkanBarriers(std::span<const CompiledBarrier> barriers,
                          std::vector<VkImageMemoryBarrier2>& images,
                          std::vector<VkBufferMemoryBarrier2>& buffers) const;
  void refreshBarrierHandles(std::span<const CompiledBarrier> barriers,
                             std::vector<VkImageMemoryBarrier2>& images,
                             std::vector<VkBufferMemoryBarrier2>& buffers) const;
  void recordBarriers(VkCommandBuffer cmd, std::vector<VkImageMemoryBarrier2>& images,
                      std::vector<VkBufferMemoryBarrier2>& buffers) const;
  void beginRendering(VkCommandBuffer cmd, Pass& pass) const;
  VkImage vkImage(std::uint16_t resource) const;
  VkImageView vkView(std::uint16_t resource) const;
  VkBuffer vkBuffer(std::uint16_t resource) const;

  gfx::Device* device_;
  Blackboard blackboard_;
  std::vector<Resource> resources_;
  std::vector<Pass> passes_;
  std::vector<std::uint16_t> order_;
  std::vector<CompiledBarrier> finalBarriers_;
  std::vector<VkImageMemoryBarrier2> finalImageBarriers_;
  std::vector<VkBufferMemoryBarrier2> finalBufferBarriers_;
  bool compiled_ = false;
  bool exactPassTimes_ = true;
};

template <typename Data, typename Setup, typename Execute>
const Data& FrameGraph::addPass(const char* name, PassType type, Setup&& setup, Execute&& execute) {
  static_assert(std::is_invocable_v<Execute, const Data&, PassContext&>,
                "execute must be callable as execute(const Data&, PassContext&)");
  auto executor =
      std::make_unique<Executor<Data, std::decay_t<Execute>>>(std::forward<Execute>(execute));
  auto* typed = executor.get();
  const std::uint16_t pass = beginPass(name, type, std::move(executor));
  PassBuilder builder(*this, pass);
  setup(builder, typed->data);
  return typed->data;
}

}  // namespace engine::render
