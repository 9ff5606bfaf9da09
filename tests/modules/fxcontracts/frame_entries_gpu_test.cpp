// The effects' per-frame entries (contracts/ecs/frame_entries.h) between the atmosphere's and the
// clouds' engine adapters, on a real device, in a frame graph built once the way a renderer
// builds it: a value one feature publishes is read by the other when its pass executes, so a
// change made at run time reaches the reader in the next frame without rebuilding the graph.
//
// The check: an app whose air changes at run time renders, in the frame of the change, what an
// app that had that air from the start renders (the camera cut in both, so neither carries
// history; the sky's measured light, which lags by the frames in flight, held the same in both).
// When the clouds read the haze's coefficients as they were when the graph was built, their
// god rays weigh the new haze's Mie share with the old coefficients and the frames differ.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "atmosphere/ecs/atmosphere_components.h"
#include "atmosphere/ecs/atmosphere_module.h"
#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/clouds_module.h"
#include "engine/assets/image_metrics.h"
#include "engine/ecs/app.h"
#include "engine/gfx/frame_ring.h"
#include "engine/render/frame_capture.h"
#include "engine/render/frame_graph.h"
#include "engine/render/render_feature.h"
#include "engine/render/scene_components.h"
#include "fxcontracts/ecs/frame_entries.h"
#include "gpu_test.h"

namespace {

namespace render = engine::render;
using FrameEntries = test::GpuTest;

constexpr VkExtent2D kExtent{160, 90};
constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// Earth's air, and a hazier one with more and more forward-scattering Mie.
atmosphere::Parameters clearAir() {
  return atmosphere::Parameters{};
}
atmosphere::Parameters hazyAir() {
  atmosphere::Parameters air;
  air.mieScatteringPerMetre *= 4.0f;
  air.mieExtinctionPerMetre *= 4.0f;
  air.miePhaseG = 0.9f;
  return air;
}

// A host with the atmosphere and the clouds, looking towards a low sun over the layer's base
// (god rays in view), rendering into its own frame graph as the sample's renderer does.
class Host {
 public:
  Host(engine::gfx::Device& device, const atmosphere::Parameters& air)
      : device_(device), ring_(device), capture_(device) {
    auto& world = app_.world();
    world.ctx().emplace<render::RenderDevice>(
        render::RenderDevice{&device, kHdrFormat, kDepthFormat, 2, kExtent});
    world.emplace<atmosphere::ecs::Atmosphere>(world.create(), atmosphere::ecs::Atmosphere{air});
    clouds::ecs::CloudLayer layer;
    layer.settings = clouds::settingsFor(clouds::Quality::Low, layer.settings);
    layer.settings.shadowCascades = 0;
    layer.settings.godRaySamples = 16;
    world.emplace<clouds::ecs::CloudLayer>(world.create(), layer);
    camera_ = world.create();
    render::Camera camera;
    camera.position = {0.0, 400.0, 0.0};  // looking down -Z, towards the sun
    world.emplace<render::Camera>(camera_, camera);
    render::Sun sun;
    sun.direction = glm::normalize(glm::dvec3(0.0, 0.12, -1.0));
    world.emplace<render::Sun>(world.create(), sun);
    EXPECT_TRUE(app_.addModule<atmosphere::ecs::AtmosphereModule>());
    EXPECT_TRUE(app_.addModule<clouds::ecs::CloudsModule>());
    features_ = world.ctx().get<render::RenderFeatures>().features;
  }
  ~Host() { ring_.drain(); }

  engine::ecs::World& world() { return app_.world(); }

  // Renders one frame; returns its HDR image when `capture` is set.
  std::optional<engine::assets::ImageRgba32f> renderFrame(bool cut, bool capture) {
    engine::gfx::FrameRing::Frame& frame = ring_.begin();
    world().get<render::Camera>(camera_).cut = cut;
    bool rebuild = !graph_;
    for (render::RenderFeature* feature : features_)
      rebuild |= feature->prepare(kExtent, frame.index);
    if (rebuild) {
      build();
      ++builds_;
    }
    // The sky's measured light lags by the frames in flight: the same in every host.
    world().ctx().emplaceOrReplace<render::SkyLight>(render::SkyLight{});
    if (capture) capture_.arm(std::filesystem::temp_directory_path() / "frame_entries_test");
    graph_->execute(frame);
    ring_.submit();
    if (!capture) return std::nullopt;
    ring_.drain();
    capture_.writePending();
    return capture_.lastHdr();
  }

  int graphBuilds() const { return builds_; }
  const render::FrameGraph& graph() const { return *graph_; }

 private:
  void build() {
    graph_ = std::make_unique<render::FrameGraph>(&device_);
    render::FrameGraph& graph = *graph_;
    render::SceneTextures scene;
    scene.extent = kExtent;
    for (render::RenderFeature* feature : features_) scene = feature->addShadowPasses(graph, scene);
    for (render::RenderFeature* feature : features_) {
      scene = feature->addPassesBeforeScene(graph, scene);
    }
    struct SceneData {
      render::TextureHandle hdr, depth;
    };
    const auto* sky = graph.blackboard().find<fxcontracts::ecs::SkyRadiance>();
    const SceneData& drawn = graph.addPass<SceneData>(
        "scene", render::PassType::Graphics,
        [&](render::PassBuilder& builder, SceneData& d) {
          render::TextureDesc desc;
          desc.extent = {kExtent.width, kExtent.height, 1};
          desc.format = kHdrFormat;
          d.hdr = builder.colorAttachment(builder.createTexture("scene hdr", desc),
                                          VK_ATTACHMENT_LOAD_OP_CLEAR);
          desc.format = kDepthFormat;
          d.depth = builder.depthAttachment(builder.createTexture("scene depth", desc),
                                            VK_ATTACHMENT_LOAD_OP_CLEAR);
          if (sky != nullptr) builder.read(sky->texture, render::Access::SampledReadGeneral);
        },
        [this](const SceneData&, render::PassContext& context) {
          for (render::RenderFeature* feature : features_) {
            if (feature->drawsSky()) feature->drawSkyInScenePass(context.cmd());
          }
        });
    scene.hdr = drawn.hdr;
    scene.depth = drawn.depth;
    for (render::RenderFeature* feature : features_) scene = feature->addPasses(graph, scene);
    capture_.addToGraph(graph, scene.hdr, addDisplay(graph));
    graph.compile();
  }

  // The 8-bit image the capture wants beside the HDR one (cleared: this host shows nothing).
  static render::TextureHandle addDisplay(render::FrameGraph& graph) {
    struct DisplayData {
      render::TextureHandle display;
    };
    return graph
        .addPass<DisplayData>(
            "display", render::PassType::Graphics,
            [&](render::PassBuilder& builder, DisplayData& d) {
              render::TextureDesc desc;
              desc.extent = {kExtent.width, kExtent.height, 1};
              desc.format = VK_FORMAT_R8G8B8A8_UNORM;
              d.display = builder.colorAttachment(builder.createTexture("display", desc),
                                                  VK_ATTACHMENT_LOAD_OP_CLEAR);
            },
            [](const DisplayData&, render::PassContext&) {})
        .display;
  }

  engine::gfx::Device& device_;
  engine::ecs::App app_;
  engine::ecs::Entity camera_{};
  std::vector<render::RenderFeature*> features_;
  engine::gfx::FrameRing ring_;
  render::FrameCapture capture_;
  std::unique_ptr<render::FrameGraph> graph_;
  int builds_ = 0;
};

constexpr int kFramesBefore = 4;

TEST_F(FrameEntries, AnAtmosphereChangedAtRunTimeReachesTheCloudsInTheNextFrame) {
  // The change, made at run time in a graph built for the air before it.
  Host changed(device(), clearAir());
  for (int i = 0; i < kFramesBefore; ++i) changed.renderFrame(false, false);
  changed.world().view<atmosphere::ecs::Atmosphere>().each(
      [](atmosphere::ecs::Atmosphere& a) { a.parameters = hazyAir(); });
  const auto afterChange = changed.renderFrame(true, true);
  EXPECT_EQ(changed.graphBuilds(), 1) << "a change of the air's parameters rebuilds nothing";
  // The haze's values on the blackboard are the new air's, as its pass wrote them.
  const auto& haze = changed.graph().blackboard().get<fxcontracts::ecs::AerialPerspective>();
  EXPECT_EQ(haze.mieScatteringPerMetre, hazyAir().mieScatteringPerMetre);
  EXPECT_EQ(haze.miePhaseG, hazyAir().miePhaseG);

  // The same frame of a host that had the new air all along.
  Host hazy(device(), hazyAir());
  for (int i = 0; i < kFramesBefore; ++i) hazy.renderFrame(false, false);
  const auto fromTheStart = hazy.renderFrame(true, true);

  // And the old air's frame, to show the change is visible at all.
  Host clear(device(), clearAir());
  for (int i = 0; i < kFramesBefore; ++i) clear.renderFrame(false, false);
  const auto unchanged = clear.renderFrame(true, true);

  ASSERT_TRUE(afterChange && fromTheStart && unchanged);
  const auto& a = afterChange->pixels;
  const auto& b = fromTheStart->pixels;
  ASSERT_EQ(a.size(), b.size());
  const double changeFromOldAir =
      engine::assets::compareImages(unchanged->pixels, fromTheStart->pixels, 4, 3).meanAbs;
  const double changeFromNewAir = engine::assets::compareImages(a, b, 4, 3).meanAbs;
  EXPECT_GT(changeFromOldAir, 0.0) << "the two airs must look different";
  EXPECT_EQ(changeFromNewAir, 0.0)
      << "the frame after the change must be the new air's (mean "
      << "absolute difference " << changeFromNewAir << "; the old air's frame differs by "
      << changeFromOldAir << ")";
}

}  // namespace
