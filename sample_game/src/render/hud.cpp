#include "render/hud.h"

#include <imgui.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "bindings.h"
#include "engine/ecs/frame_time.h"
#include "engine/gfx/descriptors.h"
#include "engine/gfx/upload.h"
#include "engine/platform/input.h"
#include "render/hud_layout.h"
#include "render/settings_panel.h"
#include "sample_shaders/hud.frag.spv.h"
#include "sample_shaders/hud.vert.spv.h"

namespace sample {

using namespace engine;

namespace {

constexpr VkDeviceSize kVertexBytes = 512 * 1024;
constexpr VkDeviceSize kIndexBytes = 256 * 1024;

struct HudConstants {
  glm::vec2 scale;
  glm::vec2 translate;
};

}  // namespace

Hud::Hud(gfx::Device& device, VkFormat targetFormat)
    : device_(device),
      sampler_(device,
               gfx::SamplerDesc{VK_FILTER_LINEAR, VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "hud font sampler"}) {
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini next to the binary
  unsigned char* pixels = nullptr;
  int width = 0;
  int height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  font_ = gfx::Image(device,
                     gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                    VK_FORMAT_R8G8B8A8_UNORM,
                                    {std::uint32_t(width), std::uint32_t(height), 1},
                                    1,
                                    1,
                                    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                    "hud font atlas"});
  gfx::uploadToImage(device, font_,
                     std::span(reinterpret_cast<const std::byte*>(pixels),
                               std::size_t(width) * std::size_t(height) * 4),
                     gfx::kShaderRead);

  gfx::GraphicsPipelineDesc desc;
  desc.vertexSpirv = hud_vert_spv;
  desc.fragmentSpirv = hud_frag_spv;
  desc.bindings = {{shaders::kHudFontBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                    VK_FORMAT_R8G8B8A8_UNORM}};
  desc.pushConstantBytes = sizeof(HudConstants);
  desc.colorFormats = {targetFormat};
  desc.blend = gfx::BlendMode::Alpha;
  desc.vertexBindings = {{0, sizeof(ImDrawVert), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(ImDrawVert, pos)},
                           {1, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(ImDrawVert, uv)},
                           {2, 0, VK_FORMAT_R8G8B8A8_UNORM, offsetof(ImDrawVert, col)}};
  desc.debugName = "hud";
  pipeline_ = gfx::Pipeline(device, desc);

  for (std::size_t i = 0; i < buffers_.size(); ++i) {
    buffers_[i].vertices =
        gfx::Buffer(device, gfx::BufferDesc{kVertexBytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                            gfx::MemoryUsage::Upload, "hud vertices"});
    buffers_[i].indices =
        gfx::Buffer(device, gfx::BufferDesc{kIndexBytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                            gfx::MemoryUsage::Upload, "hud indices"});
  }
}

Hud::~Hud() {
  ImGui::DestroyContext(context_);
}

void Hud::prepare(ecs::World& world, VkExtent2D extent, std::span<const gfx::TimedScope> gpuTimings,
                  const gfx::FrameRing::Frame& frame) {
  ImGui::SetCurrentContext(context_);
  const auto& input = world.ctx().get<platform::InputState>();
  if (input.wasPressed(platform::Key::F1)) full_ = !full_;
  if (input.wasPressed(platform::Key::F2)) panelOpen_ = !panelOpen_;
  slot_ = frame.slot;
  extent_ = extent;
  const auto& time = world.ctx().get<ecs::FrameTime>();
  if (time.deltaSeconds > 0.0) {
    smoothedFrameSeconds_ = smoothedFrameSeconds_ == 0.0
                                ? time.deltaSeconds
                                : smoothedFrameSeconds_ * 0.9 + time.deltaSeconds * 0.1;
  }
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(float(extent.width), float(extent.height));
  io.DeltaTime = time.deltaSeconds > 0.0 ? float(time.deltaSeconds) : 1.0f / 60.0f;
  // The free cursor drives the panel (a captured one flies the aircraft).
  io.MousePos = input.cursorX >= 0.0 ? ImVec2(float(input.cursorX), float(input.cursorY))
                                     : ImVec2(-FLT_MAX, -FLT_MAX);
  io.MouseDown[0] = input.leftButtonDown && input.cursorX >= 0.0;
  ImGui::NewFrame();
  layOutHud(world, gpuTimings, smoothedFrameSeconds_, full_);
  if (panelOpen_) layOutSettingsPanel(world, extent);
  ImGui::Render();

  const ImDrawData* draw = ImGui::GetDrawData();
  auto* vertices = buffers_[slot_].vertices.mapped();
  auto* indices = buffers_[slot_].indices.mapped();
  VkDeviceSize vertexOffset = 0;
  VkDeviceSize indexOffset = 0;
  for (int i = 0; i < draw->CmdListsCount; ++i) {
    const ImDrawList* list = draw->CmdLists[i];
    const VkDeviceSize vb = VkDeviceSize(list->VtxBuffer.Size) * sizeof(ImDrawVert);
    const VkDeviceSize ib = VkDeviceSize(list->IdxBuffer.Size) * sizeof(ImDrawIdx);
    if (vertexOffset + vb > kVertexBytes || indexOffset + ib > kIndexBytes)
      break;  // text only: never
    std::memcpy(vertices + vertexOffset, list->VtxBuffer.Data, vb);
    std::memcpy(indices + indexOffset, list->IdxBuffer.Data, ib);
    vertexOffset += vb;
    indexOffset += ib;
  }
}

void Hud::record(VkCommandBuffer cmd, gfx::DescriptorArena& descriptors,
                 const gfx::Device& device) const {
  ImGui::SetCurrentContext(context_);
  const ImDrawData* draw = ImGui::GetDrawData();
  if (draw == nullptr || draw->TotalVtxCount == 0) return;
  gfx::DescriptorWriter writer;
  writer.combinedImageSampler(shaders::kHudFontBinding, font_.view(), sampler_.vk());
  gfx::bindPipeline(device, cmd, pipeline_, descriptors, writer);
  const HudConstants constants{glm::vec2(2.0f / float(extent_.width), 2.0f / float(extent_.height)),
                               glm::vec2(-1.0f, -1.0f)};
  gfx::pushConstants(cmd, pipeline_, constants);
  const VkBuffer vertexBuffer = buffers_[slot_].vertices.vk();
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &zero);
  vkCmdBindIndexBuffer(cmd, buffers_[slot_].indices.vk(), 0,
                       sizeof(ImDrawIdx) == 2 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32);
  std::uint32_t firstIndex = 0;
  std::int32_t firstVertex = 0;
  for (int i = 0; i < draw->CmdListsCount; ++i) {
    const ImDrawList* list = draw->CmdLists[i];
    for (const ImDrawCmd& c : list->CmdBuffer) {
      const float x0 = std::max(c.ClipRect.x, 0.0f);
      const float y0 = std::max(c.ClipRect.y, 0.0f);
      const float x1 = std::min(c.ClipRect.z, float(extent_.width));
      const float y1 = std::min(c.ClipRect.w, float(extent_.height));
      if (x1 <= x0 || y1 <= y0) continue;
      const VkRect2D scissor{{std::int32_t(x0), std::int32_t(y0)},
                             {std::uint32_t(x1 - x0), std::uint32_t(y1 - y0)}};
      vkCmdSetScissor(cmd, 0, 1, &scissor);
      vkCmdDrawIndexed(cmd, c.ElemCount, 1, firstIndex + c.IdxOffset,
                       firstVertex + std::int32_t(c.VtxOffset), 0);
    }
    firstIndex += std::uint32_t(list->IdxBuffer.Size);
    firstVertex += list->VtxBuffer.Size;
  }
}

render::TextureHandle addHudPass(render::FrameGraph& graph, const Hud& hud,
                                 render::TextureHandle display) {
  struct Data {
    render::TextureHandle display;
  };
  const Data& data = graph.addPass<Data>(
      "hud", render::PassType::Graphics,
      [&](render::PassBuilder& builder, Data& d) {
        d.display = builder.colorAttachment(display, VK_ATTACHMENT_LOAD_OP_LOAD);
      },
      [&hud](const Data&, render::PassContext& context) {
        hud.record(context.cmd(), context.descriptors(), context.device());
      });
  return data.display;
}

}  // namespace sample
