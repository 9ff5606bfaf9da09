#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include "engine/render/camera_math.h"

namespace {

using namespace engine::render;

glm::vec3 project(const glm::mat4& m, const glm::vec3& p) {
  const glm::vec4 clip = m * glm::vec4(p, 1.0f);
  return glm::vec3(clip) / clip.w;
}

TEST(CameraMath, ReversedZMapsNearToOneAndFarTowardsZero) {
  const glm::mat4 projection = perspectiveReversedZ(glm::radians(60.0f), 16.0f / 9.0f, 0.5f);
  EXPECT_NEAR(project(projection, {0, 0, -0.5f}).z, 1.0f, 1e-6f);
  EXPECT_NEAR(project(projection, {0, 0, -1000.0f}).z, 0.0005f, 1e-7f);
  EXPECT_GT(project(projection, {0, 0, -1.0f}).z, project(projection, {0, 0, -2.0f}).z);
  // Vulkan clip space: +Y up in view space goes to -Y in NDC.
  EXPECT_LT(project(projection, {0, 1, -5.0f}).y, 0.0f);
}

TEST(CameraMath, LookToPutsTheTargetOnTheNegativeZAxis) {
  const glm::vec3 eye(10.0f, 2.0f, -3.0f);
  const glm::vec3 forward = glm::normalize(glm::vec3(1.0f, 0.2f, 0.5f));
  const glm::mat4 view = lookTo(eye, forward, {0, 1, 0});
  const glm::vec3 ahead = glm::vec3(view * glm::vec4(eye + forward * 7.0f, 1.0f));
  EXPECT_NEAR(ahead.x, 0.0f, 1e-5f);
  EXPECT_NEAR(ahead.y, 0.0f, 1e-5f);
  EXPECT_NEAR(ahead.z, -7.0f, 1e-5f);
}

}  // namespace
