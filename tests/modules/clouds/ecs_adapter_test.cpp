// The clouds' ECS adapter without a GPU: the frame inputs come from the world's camera, sun,
// sky and time, and each camera's CloudQuality preset decides the settings it renders with.
#include <gtest/gtest.h>

#include "clouds/ecs/cloud_components.h"
#include "clouds/ecs/clouds_module.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/world.h"
#include "engine/render/scene_components.h"

namespace {

struct AdapterWorld {
  engine::ecs::World world;
  engine::ecs::Entity camera;
  clouds::Settings look;
  AdapterWorld() {
    world.ctx().emplace<engine::ecs::FrameTime>();
    look.coverage = 0.81f;
    look.cloudType = 0.3f;
    world.emplace<clouds::ecs::CloudLayer>(world.create(), clouds::ecs::CloudLayer{look, 1, {}});
    camera = world.create();
    engine::render::Camera c;
    c.position = {10.0, 2000.0, -30.0};
    world.emplace<engine::render::Camera>(camera, c);
  }
};

TEST(CloudsEcsAdapter, TheCamerasPresetDecidesTheSettings) {
  AdapterWorld w;
  clouds::FrameInputs inputs;
  clouds::Settings settings;
  clouds::ecs::updateFrameInputs(w.world, inputs, settings);
  EXPECT_EQ(settings.maxViewSteps, w.look.maxViewSteps) << "no preset: the layer as it is";
  EXPECT_EQ(settings.coverage, w.look.coverage);

  w.world.emplace<clouds::ecs::CloudQuality>(w.camera, clouds::ecs::CloudQuality{clouds::Quality::Ultra});
  clouds::ecs::updateFrameInputs(w.world, inputs, settings);
  const clouds::Settings ultra = clouds::settingsFor(clouds::Quality::Ultra, w.look);
  EXPECT_EQ(settings.maxViewSteps, ultra.maxViewSteps);
  EXPECT_EQ(settings.traceScale, ultra.traceScale);
  EXPECT_EQ(settings.coverage, w.look.coverage) << "the preset keeps the layer's look";
  EXPECT_EQ(settings.cloudType, w.look.cloudType);

  w.world.get<clouds::ecs::CloudQuality>(w.camera).preset = clouds::Quality::Low;
  clouds::ecs::updateFrameInputs(w.world, inputs, settings);
  EXPECT_EQ(settings.traceScale, clouds::settingsFor(clouds::Quality::Low).traceScale);
}

TEST(CloudsEcsAdapter, CameraMotionBecomesThePreviousCamera) {
  AdapterWorld w;
  clouds::FrameInputs inputs;
  clouds::Settings settings;
  clouds::ecs::updateFrameInputs(w.world, inputs, settings);
  EXPECT_TRUE(inputs.reset) << "the first frame is a cut";
  EXPECT_EQ(inputs.cameraPosition, glm::dvec3(10.0, 2000.0, -30.0));
  auto& time = w.world.ctx().get<engine::ecs::FrameTime>();
  time = time.next(0.5);
  w.world.get<engine::render::Camera>(w.camera).position.x += 100.0;
  clouds::ecs::updateFrameInputs(w.world, inputs, settings);
  EXPECT_FALSE(inputs.reset);
  EXPECT_EQ(inputs.previousCameraPosition.x, 10.0);
  EXPECT_EQ(inputs.cameraPosition.x, 110.0);
  EXPECT_DOUBLE_EQ(inputs.timeSeconds, 0.5);
  w.world.get<engine::render::Camera>(w.camera).cut = true;
  clouds::ecs::updateFrameInputs(w.world, inputs, settings);
  EXPECT_TRUE(inputs.reset) << "a teleport is a camera cut";
}

}  // namespace
