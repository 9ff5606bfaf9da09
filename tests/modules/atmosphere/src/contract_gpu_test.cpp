// The contract of atmosphere::Context as another engine relies on it, checked through the
// Vulkan function-table shim (vulkan_shim.h) and the validation layer, as the clouds module's:
//  - dispatch() and render() create and allocate nothing; a failing call records nothing;
//  - preparing what is prepared makes no Vulkan call;
//  - creation or prepare() failing at any of their Vulkan calls returns OutOfMemory and leaves
//    no object behind;
//  - memory depends on the settings only (no image the size of the screen) and is reported;
//  - every error has a code and names the field.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "atmosphere/atmosphere.h"
#include "engine/gfx/device.h"
#include "engine/gfx/resources.h"
#include "gpu_test.h"
#include "vulkan_shim.h"

namespace {

constexpr VkExtent2D kExtent{160, 90};

atmosphere::CreateInfo shimmedInfo(engine::gfx::Device& device) {
  atmosphere::CreateInfo info;
  info.instance = device.vkInstance();
  info.physicalDevice = device.physical();
  info.device = device.vk();
  info.getInstanceProcAddr = vkGetInstanceProcAddr;
  info.getDeviceProcAddr = test::shim::getDeviceProcAddr();
  info.maxRenderExtent = {640, 360};
  info.maxFramesInFlight = 2;
  info.skyPassColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // drawSky()'s pipeline too
  return info;
}

atmosphere::FrameInputs frame(VkCommandBuffer cmd, VkExtent2D extent, std::uint64_t index) {
  atmosphere::FrameInputs in;
  in.commandBuffer = cmd;
  in.renderExtent = extent;
  in.view = glm::rotate(glm::mat4(1.0f), 0.01f * float(index), glm::vec3(0, 1, 0));
  in.projection = glm::perspective(1.1f, float(extent.width) / float(extent.height), 0.5f, 1e5f);
  in.cameraPosition = {0.0, 300.0, 0.0};
  in.sunDirection = glm::normalize(glm::vec3(0.3f, 0.2f + 0.01f * float(index), -0.5f));
  in.sunIlluminance = glm::vec3(127.0f);
  in.frameIndex = index;
  return in;
}

// A host colour image render() may write.
engine::gfx::Image hostColour(engine::gfx::Device& device) {
  return engine::gfx::Image(device, engine::gfx::ImageDesc{VK_IMAGE_TYPE_2D,
                                                           VK_FORMAT_R16G16B16A16_SFLOAT,
                                                           {kExtent.width, kExtent.height, 1},
                                                           1,
                                                           1,
                                                           VK_IMAGE_USAGE_STORAGE_BIT,
                                                           "host colour"});
}

void toGeneral(VkCommandBuffer cmd, const engine::gfx::Image& image) {
  VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  barrier.dstAccessMask =
      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
  barrier.image = image.vk();
  barrier.subresourceRange = image.fullRange();
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

using Contract = test::GpuTest;

TEST_F(Contract, DispatchAndRenderCreateNothingAndAFailedCallRecordsNothing) {
  engine::gfx::Device& device = this->device();
  atmosphere::Error error;
  auto context = atmosphere::Context::create(shimmedInfo(device), &error);
  ASSERT_TRUE(context) << error.message;
  const atmosphere::Parameters earth;
  const atmosphere::Settings high = atmosphere::settingsFor(atmosphere::Quality::High);
  ASSERT_TRUE(context->prepare(earth, high, kExtent, &error)) << error.message;
  EXPECT_TRUE(context->prepared(earth, high, kExtent));
  engine::gfx::Image colour = hostColour(device);

  test::shim::resetCounts();
  for (std::uint64_t i = 0; i < 4; ++i) {
    device.immediateSubmit([&](VkCommandBuffer cmd) {
      if (i == 0) toGeneral(cmd, colour);
      ASSERT_TRUE(context->dispatch(frame(cmd, kExtent, i), earth, high, &error)) << error.message;
      // With and without the host's depth: both variants were made at creation.
      ASSERT_TRUE(context->render(cmd, colour.view(), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL,
                                  kExtent, &error))
          << error.message;
    });
  }
  EXPECT_EQ(test::shim::counts().creations, 0) << "dispatch() or render() created something";
  EXPECT_GT(test::shim::counts().commands, 0) << "the shim must see the frames' commands";

  // New parameters or settings must be prepared first; the failed dispatch records nothing.
  atmosphere::Parameters hazy = earth;
  hazy.mieScatteringPerMetre *= 4.0f;
  hazy.mieExtinctionPerMetre *= 4.0f;
  test::shim::resetCounts();
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    EXPECT_FALSE(context->dispatch(frame(cmd, kExtent, 4), hazy, high, &error));
    EXPECT_EQ(error.code, atmosphere::ErrorCode::NotPrepared) << error.message;
    EXPECT_NE(error.message.find("prepare()"), std::string::npos) << error.message;
    const atmosphere::Settings low = atmosphere::settingsFor(atmosphere::Quality::Low);
    EXPECT_FALSE(context->dispatch(frame(cmd, kExtent, 4), earth, low, &error));
    EXPECT_EQ(error.code, atmosphere::ErrorCode::NotPrepared) << error.message;
  });
  EXPECT_EQ(test::shim::counts().commands, 0) << "a failed dispatch recorded commands";

  // New parameters need no new object (the LUTs are rebuilt in place); preparing again is free.
  ASSERT_TRUE(context->prepare(hazy, high, kExtent, &error)) << error.message;
  EXPECT_EQ(test::shim::counts().creations, 0);
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    EXPECT_TRUE(context->dispatch(frame(cmd, kExtent, 4), hazy, high, &error)) << error.message;
  });
  EXPECT_EQ(test::shim::counts().creations, 0);
  device.waitIdle();
}

// Creates a context on a fresh device with the `n`-th Vulkan creation failing and prepares
// it, then destroys the device: returns whether both succeeded, checking that a failure left
// nothing.
bool createWithFailure(int n, std::string& failureReport) {
  engine::gfx::Device fresh(test::GpuTest::instance(), engine::gfx::DeviceDesc{});
  test::shim::counts().live.clear();
  test::shim::failCreation(n);
  atmosphere::Error error;
  auto context = atmosphere::Context::create(shimmedInfo(fresh), &error);
  const bool prepared =
      context &&
      context->prepare({}, atmosphere::settingsFor(atmosphere::Quality::Medium), kExtent, &error);
  const bool injected = test::shim::failed();
  test::shim::failCreation(0);
  if (prepared) {
    EXPECT_FALSE(injected) << "creation " << n << " failed but create() and prepare() succeeded";
  } else {
    EXPECT_TRUE(injected) << "failed without an injected failure: " << error.message;
    EXPECT_EQ(error.code, atmosphere::ErrorCode::OutOfMemory) << n << ": " << error.message;
  }
  context.reset();
  for (const auto& [handle, call] : test::shim::counts().live) {
    failureReport +=
        "creation " + std::to_string(n) + " failing leaked an object of " + call + "\n";
  }
  test::shim::counts().live.clear();
  // The device goes here: the validation layer reports any object still alive on it.
  return prepared || !injected;
}

TEST_F(Contract, CreationOrPrepareFailingAtAnyVulkanCallLeavesNothingBehind) {
  std::string leaks;
  int n = 1;
  for (; n < 500; ++n) {
    if (createWithFailure(n, leaks)) break;  // every creation call has been failed once
  }
  EXPECT_GT(n, 20) << "creation makes fewer Vulkan objects than expected";
  EXPECT_LT(n, 500);
  EXPECT_EQ(leaks, "");
  // TearDown fails the test on any validation message: a leak on a destroyed device is one.
}

TEST_F(Contract, MemoryDependsOnTheSettingsNotTheScreenAndIsReported) {
  engine::gfx::Device& device = this->device();
  atmosphere::CreateInfo info = shimmedInfo(device);
  info.maxRenderExtent = {3840, 2160};
  atmosphere::Error error;
  auto context = atmosphere::Context::create(info, &error);
  ASSERT_TRUE(context) << error.message;
  EXPECT_EQ(context->memoryUsage().lutBytes, 0u) << "no LUT before prepare()";
  const atmosphere::Settings medium = atmosphere::settingsFor(atmosphere::Quality::Medium);
  ASSERT_TRUE(context->prepare({}, medium, {3840, 2160}, &error)) << error.message;
  const atmosphere::MemoryUsage m = context->memoryUsage();
  const auto texels2 = [](std::uint64_t w, std::uint64_t h) { return w * h * 8u; };  // RGBA16F
  EXPECT_GE(m.lutBytes, texels2(medium.transmittanceWidth, medium.transmittanceHeight) +
                            texels2(medium.multiScatteringSize, medium.multiScatteringSize) +
                            texels2(medium.skyViewWidth, medium.skyViewHeight));
  EXPECT_GE(m.volumeBytes, texels2(medium.aerialPerspectiveWidth, medium.aerialPerspectiveHeight) *
                               medium.aerialPerspectiveSlices);
  EXPECT_LT(m.totalBytes(), 4u * 1024u * 1024u) << "a few MiB at most, whatever the screen";
  // Higher settings grow it; the replaced images are freed once no frame can use them.
  ASSERT_TRUE(context->prepare({}, atmosphere::settingsFor(atmosphere::Quality::High), {3840, 2160},
                               &error));
  EXPECT_GT(context->memoryUsage().totalBytes(), m.totalBytes());
  device.waitIdle();
}

TEST_F(Contract, EveryErrorHasACode) {
  engine::gfx::Device& device = this->device();
  atmosphere::Error error;
  EXPECT_FALSE(atmosphere::Context::create(atmosphere::CreateInfo{}, &error));
  EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidCreateInfo);
  atmosphere::CreateInfo info = shimmedInfo(device);
  info.maxFramesInFlight = 0;
  EXPECT_FALSE(atmosphere::Context::create(info, &error));
  EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidCreateInfo);
  EXPECT_NE(error.message.find("maxFramesInFlight"), std::string::npos);
  info = shimmedInfo(device);
  info.colorFormat = VK_FORMAT_R8G8B8A8_UNORM;
  EXPECT_FALSE(atmosphere::Context::create(info, &error));
  EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidCreateInfo);
  info = shimmedInfo(device);
  info.getDeviceProcAddr = [](VkDevice d, const char* name) -> PFN_vkVoidFunction {
    return std::string_view(name) == "vkCmdDispatch" ? nullptr : vkGetDeviceProcAddr(d, name);
  };
  EXPECT_FALSE(atmosphere::Context::create(info, &error));
  EXPECT_EQ(error.code, atmosphere::ErrorCode::MissingFunction);
  EXPECT_NE(error.message.find("vkCmdDispatch"), std::string::npos);

  auto context = atmosphere::Context::create(shimmedInfo(device), &error);
  ASSERT_TRUE(context);
  EXPECT_EQ(error.code, atmosphere::ErrorCode::None);
  atmosphere::Parameters badAir;
  badAir.miePhaseG = 1.5f;
  EXPECT_FALSE(context->prepare(badAir, {}, kExtent, &error));
  EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidParameters);
  EXPECT_NE(error.message.find("Parameters.miePhaseG"), std::string::npos);
  atmosphere::Settings badSettings;
  badSettings.skyViewSamples = 0;
  EXPECT_FALSE(context->prepare({}, badSettings, kExtent, &error));
  EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidSettings);
  EXPECT_NE(error.message.find("Settings.skyViewSamples"), std::string::npos);
  EXPECT_FALSE(context->prepare({}, {}, {4096, 16}, &error));
  EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidInputs);
  ASSERT_TRUE(context->prepare({}, {}, kExtent, &error));
  engine::gfx::Image colour = hostColour(device);
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    toGeneral(cmd, colour);
    EXPECT_FALSE(context->render(cmd, colour.view(), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL,
                                 kExtent, &error));
    EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidInputs) << "render() before dispatch()";
    EXPECT_FALSE(context->drawSky(cmd, &error));
    EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidInputs) << "drawSky() before dispatch()";
    atmosphere::FrameInputs in = frame(cmd, kExtent, 0);
    in.sunIlluminance = glm::vec3(-1.0f);
    EXPECT_FALSE(context->dispatch(in, {}, {}, &error));
    EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidInputs);
    EXPECT_NE(error.message.find("FrameInputs.sunIlluminance"), std::string::npos);
    in = frame(cmd, kExtent, 0);
    in.sunDirection = glm::vec3(0.0f);
    EXPECT_FALSE(context->dispatch(in, {}, {}, &error));
    EXPECT_NE(error.message.find("FrameInputs.sunDirection"), std::string::npos);
    EXPECT_FALSE(context->dispatch(frame(cmd, kExtent, 0), badAir, {}, &error));
    EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidParameters);
    ASSERT_TRUE(context->dispatch(frame(cmd, kExtent, 0), {}, {}, &error)) << error.message;
    EXPECT_FALSE(context->render(cmd, VK_NULL_HANDLE, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL,
                                 kExtent, &error));
    EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidInputs);
    EXPECT_FALSE(context->render(cmd, colour.view(), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL,
                                 {80, 45}, &error));
    EXPECT_NE(error.message.find("extent"), std::string::npos) << error.message;
    EXPECT_FALSE(context->drawSky(VK_NULL_HANDLE, &error));
    EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidInputs);
  });
  // A context made without a sky pass format has no drawSky().
  info = shimmedInfo(device);
  info.skyPassColorFormat = VK_FORMAT_UNDEFINED;
  auto computeOnly = atmosphere::Context::create(info, &error);
  ASSERT_TRUE(computeOnly) << error.message;
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    EXPECT_FALSE(computeOnly->drawSky(cmd, &error));
    EXPECT_EQ(error.code, atmosphere::ErrorCode::InvalidInputs);
    EXPECT_NE(error.message.find("skyPassColorFormat"), std::string::npos) << error.message;
  });
  for (atmosphere::ErrorCode code :
       {atmosphere::ErrorCode::None, atmosphere::ErrorCode::InvalidCreateInfo,
        atmosphere::ErrorCode::MissingFunction, atmosphere::ErrorCode::UnsupportedDevice,
        atmosphere::ErrorCode::OutOfMemory, atmosphere::ErrorCode::VulkanFailure,
        atmosphere::ErrorCode::InvalidParameters, atmosphere::ErrorCode::InvalidSettings,
        atmosphere::ErrorCode::InvalidInputs, atmosphere::ErrorCode::NotPrepared}) {
    EXPECT_STRNE(atmosphere::errorCodeName(code), "?");
  }
  device.waitIdle();
}

}  // namespace
