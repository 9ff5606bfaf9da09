// Building the graph (handles, versions, uses) and executing it. Compilation is in
// frame_graph_compile.cpp.
#include "engine/render/frame_graph.h"

#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "engine/gfx/formats.h"

namespace engine::render {

// --- PassContext -------------------------------------------------------------------------

VkImage PassContext::image(TextureHandle h) const {
  return graph_->vkImage(h.index);
}
VkImageView PassContext::view(TextureHandle h) const {
  return graph_->vkView(h.index);
}
VkExtent3D PassContext::extent(TextureHandle h) const {
  return graph_->resourceOf(h.index, true).textureDesc.extent;
}
VkFormat PassContext::format(TextureHandle h) const {
  return graph_->resourceOf(h.index, true).textureDesc.format;
}
VkBuffer PassContext::buffer(BufferHandle h) const {
  return graph_->vkBuffer(h.index);
}

Blackboard& PassContext::blackboard() const {
  return graph_->blackboard_;
}

void PassContext::bind(const gfx::Pipeline& pipeline, const gfx::DescriptorWriter& writer) const {
  gfx::bindPipeline(*device_, cmd(), pipeline, descriptors(), writer);
}

// --- PassBuilder -------------------------------------------------------------------------

TextureHandle PassBuilder::createTexture(const char* name, const TextureDesc& desc) {
  FrameGraph::Resource resource;
  resource.name = name;
  resource.texture = true;
  resource.textureDesc = desc;
  return TextureHandle{graph_.addResource(std::move(resource)), 0};
}

BufferHandle PassBuilder::createBuffer(const char* name, const BufferDesc& desc) {
  FrameGraph::Resource resource;
  resource.name = name;
  resource.texture = false;
  resource.bufferDesc = desc;
  return BufferHandle{graph_.addResource(std::move(resource)), 0};
}

TextureHandle PassBuilder::read(TextureHandle texture, Access access) {
  require(!isWrite(access), graph_.passes_[pass_].name, "read() with a write access");
  graph_.recordUse(pass_, texture.index, texture.version, access, false, true);
  return texture;
}

TextureHandle PassBuilder::write(TextureHandle texture, Access access) {
  require(isWrite(access), graph_.passes_[pass_].name, "write() with a read-only access");
  const auto use = graph_.recordUse(pass_, texture.index, texture.version, access, true, true);
  return TextureHandle{texture.index, use.version};
}

BufferHandle PassBuilder::read(BufferHandle buffer, Access access) {
  require(!isWrite(access), graph_.passes_[pass_].name, "read() with a write access");
  graph_.recordUse(pass_, buffer.index, buffer.version, access, false, false);
  return buffer;
}

BufferHandle PassBuilder::write(BufferHandle buffer, Access access) {
  require(isWrite(access), graph_.passes_[pass_].name, "write() with a read-only access");
  const auto use = graph_.recordUse(pass_, buffer.index, buffer.version, access, true, false);
  return BufferHandle{buffer.index, use.version};
}

TextureHandle PassBuilder::colorAttachment(TextureHandle texture, VkAttachmentLoadOp load,
                                           VkClearColorValue clear) {
  auto& pass = graph_.passes_[pass_];
  require(pass.type == PassType::Graphics, pass.name, "attachments need a graphics pass");
  const TextureHandle written = write(texture, Access::ColorAttachment);
  FrameGraph::Attachment attachment;
  attachment.resource = texture.index;
  attachment.load = load;
  attachment.clear.color = clear;
  pass.attachments.push_back(attachment);
  return written;
}

TextureHandle PassBuilder::depthAttachment(TextureHandle texture, VkAttachmentLoadOp load,
                                           float clearDepth) {
  auto& pass = graph_.passes_[pass_];
  require(pass.type == PassType::Graphics, pass.name, "attachments need a graphics pass");
  const TextureHandle written = write(texture, Access::DepthAttachment);
  FrameGraph::Attachment attachment;
  attachment.resource = texture.index;
  attachment.load = load;
  attachment.clear.depthStencil = {clearDepth, 0};
  attachment.depth = true;
  pass.attachments.push_back(attachment);
  return written;
}

void PassBuilder::depthReadOnlyAttachment(TextureHandle texture) {
  auto& pass = graph_.passes_[pass_];
  require(pass.type == PassType::Graphics, pass.name, "attachments need a graphics pass");
  read(texture, Access::DepthReadOnlyAttachment);
  FrameGraph::Attachment attachment;
  attachment.resource = texture.index;
  attachment.depth = true;
  attachment.readOnly = true;
  pass.attachments.push_back(attachment);
}

void PassBuilder::sideEffect() {
  graph_.passes_[pass_].sideEffect = true;
}

// --- FrameGraph: building ----------------------------------------------------------------

FrameGraph::FrameGraph(gfx::Device* device) : device_(device) {}
FrameGraph::~FrameGraph() = default;

std::uint16_t FrameGraph::addResource(Resource resource) {
  require(!compiled_, "FrameGraph", "resources cannot be added after compile()");
  require(resources_.size() < TextureHandle::kInvalid, "FrameGraph", "too many resources");
  resources_.push_back(std::move(resource));
  return static_cast<std::uint16_t>(resources_.size() - 1);
}

std::uint16_t FrameGraph::beginPass(const char* name, PassType type,
                                    std::unique_ptr<ExecutorBase> executor) {
  require(!compiled_, "FrameGraph", std::string("pass '") + name + "' added after compile()");
  Pass pass;
  pass.name = name;
  pass.type = type;
  pass.executor = std::move(executor);
  passes_.push_back(std::move(pass));
  return static_cast<std::uint16_t>(passes_.size() - 1);
}

FrameGraph::Use FrameGraph::recordUse(std::uint16_t pass, std::uint16_t resource,
                                      std::uint16_t version, Access access, bool write,
                                      bool texture) {
  const std::string context = std::string("frame graph pass '") + passes_[pass].name + "'";
  require(resource < resources_.size(), context, "uses an invalid resource handle");
  Resource& r = resources_[resource];
  require(r.texture == texture, context,
          std::string("uses '") + r.name + "' as the wrong kind of resource");
  require(version == r.version, context,
          std::string("uses version ") + std::to_string(version) + " of '" + r.name +
              "' but version " + std::to_string(r.version) +
              " exists: use the handle returned by the latest write");
  if (texture) {
    require(isTextureAccess(access), context, std::string("buffer access on texture ") + r.name);
    r.imageUsage |= imageUsageFor(access);
  } else {
    require(
        !isTextureAccess(access) || access == Access::TransferSrc || access == Access::TransferDst,
        context, std::string("texture access on buffer ") + r.name);
    r.bufferUsage |= bufferUsageFor(access);
  }
  Use use{resource, version, access};
  if (write) {
    passes_[pass].writes.push_back(use);
    use.version = ++r.version;
    passes_[pass].writes.back().version = use.version;
  } else {
    passes_[pass].reads.push_back(use);
  }
  return use;
}

TextureHandle FrameGraph::importTexture(const char* name, const ImportedTexture& texture) {
  Resource resource;
  resource.name = name;
  resource.texture = true;
  resource.imported = true;
  resource.textureDesc = texture.desc;
  resource.importedTexture = texture;
  return TextureHandle{addResource(std::move(resource)), 0};
}

BufferHandle FrameGraph::importBuffer(const char* name, const ImportedBuffer& buffer) {
  Resource resource;
  resource.name = name;
  resource.texture = false;
  resource.imported = true;
  resource.bufferDesc.sizeBytes = buffer.sizeBytes;
  resource.importedBuffer = buffer;
  return BufferHandle{addResource(std::move(resource)), 0};
}

void FrameGraph::updateImportedTexture(TextureHandle texture, VkImage image, VkImageView view) {
  Resource& r = resources_.at(texture.index);
  require(r.imported && r.texture, "FrameGraph::updateImportedTexture",
          std::string("'") + r.name + "' is not an imported texture");
  r.importedTexture.image = image;
  r.importedTexture.view = view;
}

void FrameGraph::updateImportedBuffer(BufferHandle buffer, VkBuffer vkBuffer) {
  Resource& r = resources_.at(buffer.index);
  require(r.imported && !r.texture, "FrameGraph::updateImportedBuffer",
          std::string("'") + r.name + "' is not an imported buffer");
  r.importedBuffer.buffer = vkBuffer;
}

const FrameGraph::Resource& FrameGraph::resourceOf(std::uint16_t index, bool texture) const {
  const Resource& r = resources_.at(index);
  (void)texture;
  return r;
}

VkImage FrameGraph::vkImage(std::uint16_t resource) const {
  const Resource& r = resources_[resource];
  return r.imported ? r.importedTexture.image : r.ownedImage.vk();
}
VkImageView FrameGraph::vkView(std::uint16_t resource) const {
  const Resource& r = resources_[resource];
  return r.imported ? r.importedTexture.view : r.ownedImage.view();
}
VkBuffer FrameGraph::vkBuffer(std::uint16_t resource) const {
  const Resource& r = resources_[resource];
  return r.imported ? r.importedBuffer.buffer : r.ownedBuffer.vk();
}

VkImage FrameGraph::image(TextureHandle h) const {
  return vkImage(h.index);
}
VkImageView FrameGraph::view(TextureHandle h) const {
  return vkView(h.index);
}
VkBuffer FrameGraph::buffer(BufferHandle h) const {
  return vkBuffer(h.index);
}
const TextureDesc& FrameGraph::textureDesc(TextureHandle h) const {
  return resources_.at(h.index).textureDesc;
}

const char* FrameGraph::resourceName(std::uint16_t resource) const {
  return resources_.at(resource).name;
}

// --- FrameGraph: execution ---------------------------------------------------------------

void FrameGraph::recordBarriers(VkCommandBuffer cmd, std::vector<VkImageMemoryBarrier2>& images,
                                std::vector<VkBufferMemoryBarrier2>& buffers) const {
  if (images.empty() && buffers.empty()) return;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = static_cast<std::uint32_t>(images.size());
  dependency.pImageMemoryBarriers = images.data();
  dependency.bufferMemoryBarrierCount = static_cast<std::uint32_t>(buffers.size());
  dependency.pBufferMemoryBarriers = buffers.data();
  vkCmdPipelineBarrier2(cmd, &dependency);
}

void FrameGraph::beginRendering(VkCommandBuffer cmd, Pass& pass) const {
  VkExtent3D extent{0, 0, 1};
  std::size_t color = 0;
  bool hasDepth = false;
  for (const Attachment& a : pass.attachments) {
    const Resource& r = resources_[a.resource];
    if (extent.width == 0) extent = r.textureDesc.extent;
    if (a.depth) {
      pass.depthInfo.imageView = vkView(a.resource);
      hasDepth = true;
    } else {
      pass.colorInfos[color++].imageView = vkView(a.resource);
    }
  }
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, {extent.width, extent.height}};
  info.layerCount = 1;
  info.colorAttachmentCount = static_cast<std::uint32_t>(pass.colorInfos.size());
  info.pColorAttachments = pass.colorInfos.data();
  info.pDepthAttachment = hasDepth ? &pass.depthInfo : nullptr;
  vkCmdBeginRendering(cmd, &info);
  const VkViewport viewport{
      0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {extent.width, extent.height}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

namespace {

// An execution dependency from everything recorded so far to everything after.
void waitForPriorWork(VkCommandBuffer cmd) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.memoryBarrierCount = 1;
  dependency.pMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace

void FrameGraph::execute(const gfx::FrameRing::Frame& frame) {
  require(compiled_, "FrameGraph::execute", "compile() first");
  require(device_ != nullptr, "FrameGraph::execute", "the graph was built without a device");
  PassContext context;
  context.graph_ = this;
  context.device_ = device_;
  context.frame_ = &frame;
  for (std::uint16_t index : order_) {
    Pass& pass = passes_[index];
    // Imported images can change between frames (swapchain): patch handles into the
    // preallocated barrier structs.
    refreshBarrierHandles(pass.barriers, pass.imageBarriers, pass.bufferBarriers);
    device_->beginLabel(frame.cmd, pass.name);
    if (exactPassTimes_) waitForPriorWork(frame.cmd);
    const std::uint32_t scope = frame.timer->begin(frame.cmd, pass.name);
    // lavapipe realises a timestamp at its next synchronisation: make that now.
    if (exactPassTimes_) waitForPriorWork(frame.cmd);
    recordBarriers(frame.cmd, pass.imageBarriers, pass.bufferBarriers);
    const bool rendering = pass.type == PassType::Graphics && !pass.attachments.empty();
    if (rendering) beginRendering(frame.cmd, pass);
    pass.executor->run(context);
    if (rendering) vkCmdEndRendering(frame.cmd);
    if (exactPassTimes_) waitForPriorWork(frame.cmd);
    frame.timer->end(frame.cmd, scope);
    if (exactPassTimes_) waitForPriorWork(frame.cmd);
    device_->endLabel(frame.cmd);
  }
  refreshBarrierHandles(finalBarriers_, finalImageBarriers_, finalBufferBarriers_);
  recordBarriers(frame.cmd, finalImageBarriers_, finalBufferBarriers_);
}

}  // namespace engine::render
