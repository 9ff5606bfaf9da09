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
#include "render/hud_draw_plan.h"
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

Hud::Hud(gfx::Device& device, VkFormat targetFormat, bool clearRectangles)
    : device_(device),
      sampler_(device, gfx::SamplerDesc{VK_FILTER_LINEAR, VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "hud font sampler"}),
      clearRectangles_(clearRectangles) {
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini next to the binary
  flattenOverWindows(ImGui::GetStyle());
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
    if (vertexOffset + vb > kVertexBytes || indexOffset + ib > kIndexBytes) {
      plan_ = {};  // more than the buffers hold (the panel takes a tenth): nothing drawn
      return;
    }
    std::memcpy(vertices + vertexOffset, list->VtxBuffer.Data, vb);
    std::memcpy(indices + indexOffset, list->IdxBuffer.Data, ib);
    vertexOffset += vb;
    indexOffset += ib;
  }
  plan_ = planHudDraws(*draw, io.Fonts->TexUvWhitePixel, extent, clearRectangles_);
}

void Hud::record(VkCommandBuffer cmd, gfx::DescriptorArena& descriptors,
                 const gfx::Device& device) const {
  ImGui::SetCurrentContext(context_);
  const ImDrawData* draw = ImGui::GetDrawData();
  if (draw == nullptr || draw->TotalVtxCount == 0) return;
  for (const HudClear& clear : plan_.clears) {
    VkClearAttachment attachment{VK_IMAGE_ASPECT_COLOR_BIT, 0, {}};
    attachment.clearValue.color = {{clear.color.r, clear.color.g, clear.color.b, clear.color.a}};
    const VkClearRect rect{clear.rect, 0, 1};
    vkCmdClearAttachments(cmd, 1, &attachment, 1, &rect);
  }
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
  for (const HudDraw& d : plan_.draws) {
    vkCmdSetScissor(cmd, 0, 1, &d.scissor);
    vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
  }
}

}  // namespace sample
