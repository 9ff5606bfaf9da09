// The contract of clouds::Context as another engine relies on it, checked through a Vulkan
// function-table shim (vulkan_shim.h) and the validation layer:
//  - dispatch() creates and allocates nothing; what it needs, prepare() made beforehand;
//  - a failing dispatch() records nothing;
//  - creation that fails at any of its Vulkan calls returns an OutOfMemory error and leaves no
//    object behind (the shim's live set is empty, and the validation layer reports no leaked
//    object when the device is destroyed), and so does a failing prepare();
//  - memory is sized to what is used, and reported;
//  - every error has a code.
#include <gtest/gtest.h>

#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "clouds/clouds.h"
#include "engine/gfx/device.h"
#include "gpu_test.h"
#include "vulkan_shim.h"

namespace {

constexpr VkExtent2D kExtent{160, 90};

clouds::CreateInfo shimmedInfo(engine::gfx::Device& device) {
  clouds::CreateInfo info;
  info.instance = device.vkInstance();
  info.physicalDevice = device.physical();
  info.device = device.vk();
  info.getInstanceProcAddr = vkGetInstanceProcAddr;
  info.getDeviceProcAddr = test::shim::getDeviceProcAddr();
  info.maxRenderExtent = {640, 360};
  info.maxFramesInFlight = 2;
  return info;
}

clouds::FrameInputs frame(VkCommandBuffer cmd, VkExtent2D extent, std::uint64_t index,
                          double yawRadians = 0.0) {
  clouds::FrameInputs in;
  in.commandBuffer = cmd;
  in.renderExtent = extent;
  in.view = glm::rotate(glm::mat4(1.0f), float(yawRadians), glm::vec3(0, 1, 0));
  in.projection = glm::perspective(1.1f, float(extent.width) / float(extent.height), 0.5f, 1e5f);
  in.cameraPosition = {0.0, 300.0, 0.0};
  in.sunDirection = glm::normalize(glm::vec3(0.3f, 0.7f, -0.5f));
  in.timeSeconds = double(index) / 30.0;
  in.frameIndex = index;
  return in;
}

using Contract = test::GpuTest;

TEST_F(Contract, DispatchCreatesNothingAndAFailedDispatchRecordsNothing) {
  engine::gfx::Device& device = this->device();
  clouds::Error error;
  auto context = clouds::Context::create(shimmedInfo(device), &error);
  ASSERT_TRUE(context) << error.message;
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  ASSERT_TRUE(context->prepare(high, kExtent, &error)) << error.message;
  EXPECT_TRUE(context->prepared(high, kExtent));

  // Frames that take every path a Settings selects: no history, history read in place (a
  // still camera and no wind), reprojected (turning), and the output history of each.
  clouds::Settings calm = high;
  calm.windSpeedMetresPerSecond = 0.0f;
  test::shim::resetCounts();
  for (std::uint64_t i = 0; i < 12; ++i) {
    device.immediateSubmit([&](VkCommandBuffer cmd) {
      clouds::FrameInputs in = frame(cmd, kExtent, i, i < 6 ? 0.0 : 0.001 * double(i));
      in.timeSeconds = 0.0;
      ASSERT_TRUE(context->dispatch(in, calm, &error)) << error.message;
    });
  }
  EXPECT_EQ(test::shim::counts().creations, 0) << "dispatch() created or allocated something";
  EXPECT_GT(test::shim::counts().commands, 0) << "the shim must see the frames' commands";

  // Settings with a different light-step count select a pipeline nobody prepared.
  clouds::Settings more = calm;
  more.lightSteps = 9;
  EXPECT_FALSE(context->prepared(more, kExtent));
  test::shim::resetCounts();
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    EXPECT_FALSE(context->dispatch(frame(cmd, kExtent, 12), more, &error));
  });
  EXPECT_EQ(error.code, clouds::ErrorCode::NotPrepared) << error.message;
  EXPECT_NE(error.message.find("prepare()"), std::string::npos) << error.message;
  EXPECT_EQ(test::shim::counts().commands, 0) << "a failed dispatch recorded commands";
  EXPECT_EQ(test::shim::counts().creations, 0);
  // So does a render extent larger than prepared.
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    EXPECT_FALSE(context->dispatch(frame(cmd, {320, 180}, 12), calm, &error));
  });
  EXPECT_EQ(error.code, clouds::ErrorCode::NotPrepared) << error.message;
  EXPECT_EQ(test::shim::counts().commands, 0);

  // prepare() makes the variant (once: preparing again is free), then the frame runs.
  ASSERT_TRUE(context->prepare(more, kExtent, &error)) << error.message;
  EXPECT_GT(test::shim::counts().creations, 0);
  test::shim::resetCounts();
  ASSERT_TRUE(context->prepare(more, kExtent, &error));
  EXPECT_EQ(test::shim::counts().creations, 0) << "preparing prepared settings is free";
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    EXPECT_TRUE(context->dispatch(frame(cmd, kExtent, 12), more, &error)) << error.message;
  });
  EXPECT_EQ(test::shim::counts().creations, 0);
  device.waitIdle();
}

// Creates a context on a fresh device with the `n`-th Vulkan creation failing, then destroys
// the device: returns whether creation succeeded, checking that a failure left nothing.
bool createWithFailure(int n, std::string& failureReport) {
  engine::gfx::Device fresh(test::GpuTest::instance(), engine::gfx::DeviceDesc{});
  test::shim::counts().live.clear();
  test::shim::failCreation(n);
  clouds::Error error;
  auto context = clouds::Context::create(shimmedInfo(fresh), &error);
  const bool injected = test::shim::failed();
  test::shim::failCreation(0);
  if (context) {
    EXPECT_FALSE(injected) << "creation " << n << " failed but create() succeeded";
    context.reset();
  } else {
    EXPECT_TRUE(injected) << "create() failed without an injected failure: " << error.message;
    EXPECT_EQ(error.code, clouds::ErrorCode::OutOfMemory) << n << ": " << error.message;
  }
  for (const auto& [handle, call] : test::shim::counts().live) {
    failureReport +=
        "creation " + std::to_string(n) + " failing leaked an object of " + call + "\n";
  }
  test::shim::counts().live.clear();
  // The device goes here: the validation layer reports any object still alive on it.
  return context != nullptr || !injected;
}

TEST_F(Contract, CreationFailingAtAnyVulkanCallLeavesNothingBehind) {
  // Negative control: a leaked object on a destroyed device is reported by the validation
  // layer in this process (so the silence below means something).
  {
    engine::gfx::Device fresh(instance(), engine::gfx::DeviceDesc{});
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    VkSampler leaked = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateSampler(fresh.vk(), &info, nullptr, &leaked), VK_SUCCESS);
  }
  EXPECT_FALSE(takeMessages().empty()) << "the validation layer did not report a leak";

  std::string leaks;
  int n = 1;
  for (; n < 1000; ++n) {
    if (createWithFailure(n, leaks)) break;  // every creation call has been failed once
  }
  EXPECT_GT(n, 50) << "creation makes fewer Vulkan objects than expected";
  EXPECT_LT(n, 1000);
  EXPECT_EQ(leaks, "");
  // TearDown fails the test on any validation message: a leak on a destroyed device is one.
}

TEST_F(Contract, PrepareFailingHalfwayLeavesAUsableContext) {
  engine::gfx::Device& device = this->device();
  clouds::Error error;
  test::shim::counts().live.clear();
  auto context = clouds::Context::create(shimmedInfo(device), &error);
  ASSERT_TRUE(context) << error.message;
  const clouds::Settings high = clouds::settingsFor(clouds::Quality::High);
  // Fail each creation prepare() makes in turn; every failure is clean and a later prepare()
  // succeeds.
  int failures = 0;
  for (int n = 1; n < 200; ++n) {
    test::shim::failCreation(n);
    const bool ok = context->prepare(high, kExtent, &error);
    const bool injected = test::shim::failed();
    test::shim::failCreation(0);
    if (ok) break;
    ++failures;
    EXPECT_TRUE(injected);
    EXPECT_EQ(error.code, clouds::ErrorCode::OutOfMemory) << error.message;
  }
  EXPECT_GT(failures, 5);
  ASSERT_TRUE(context->prepared(high, kExtent));
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    EXPECT_TRUE(context->dispatch(frame(cmd, kExtent, 0), high, &error)) << error.message;
  });
  device.waitIdle();
  context.reset();
  EXPECT_TRUE(test::shim::counts().live.empty()) << "objects outlived their context";
}

TEST_F(Contract, MemoryIsSizedToWhatIsUsedAndReported) {
  engine::gfx::Device& device = this->device();
  clouds::CreateInfo info = shimmedInfo(device);
  info.maxRenderExtent = {3840, 2160};  // a bound, not an allocation
  clouds::Error error;
  auto context = clouds::Context::create(info, &error);
  ASSERT_TRUE(context) << error.message;
  const std::uint64_t created = context->memoryUsage().totalBytes();
  EXPECT_EQ(context->memoryUsage().outputBytes, 0u) << "nothing extent-sized before prepare()";

  constexpr std::uint64_t kMiB = 1024 * 1024;
  const VkExtent2D hd{640, 360};
  const clouds::Settings low = clouds::settingsFor(clouds::Quality::Low);
  ASSERT_TRUE(context->prepare(low, hd, &error)) << error.message;
  clouds::MemoryUsage m = context->memoryUsage();
  EXPECT_LT(m.totalBytes(), 64 * kMiB) << "640x360 Low, noise included";
  EXPECT_GT(m.noiseBytes, 8 * kMiB) << "the 128^3 RGBA8 shape noise alone is 8 MiB";
  EXPECT_GE(m.outputBytes, 640u * 360u * (8 + 8)) << "radiance RGBA16F + depth RG32F";
  EXPECT_LT(m.outputBytes, 2 * 640u * 360u * (8 + 8));
  EXPECT_EQ(m.upsamplingBytes, 0u) << "Low does not upsample temporally";
  EXPECT_GT(m.totalBytes(), created);

  // High upsamples temporally: its output-resolution histories appear, the rest stays.
  ASSERT_TRUE(context->prepare(clouds::settingsFor(clouds::Quality::High), hd, &error));
  m = context->memoryUsage();
  EXPECT_GE(m.upsamplingBytes, 2u * 640u * 360u * 8u) << "two RG32UI output histories";
  EXPECT_GT(m.traceBytes, 0u);

  // A larger extent grows the images; the replaced ones wait for the frames in flight.
  std::uint64_t frameIndex = 0;
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    ASSERT_TRUE(context->dispatch(frame(cmd, hd, frameIndex++), low, &error)) << error.message;
  });
  ASSERT_TRUE(context->prepare(low, {1280, 720}, &error));
  m = context->memoryUsage();
  EXPECT_GT(m.retiredBytes, 0u) << "images a frame may still use are kept";
  EXPECT_GE(m.outputBytes, 1280u * 720u * 16u);
  for (int i = 0; i < 3; ++i) {
    device.immediateSubmit([&](VkCommandBuffer cmd) {
      ASSERT_TRUE(context->dispatch(frame(cmd, {1280, 720}, frameIndex++), low, &error))
          << error.message;
    });
  }
  EXPECT_EQ(context->memoryUsage().retiredBytes, 0u) << "freed once no frame can use them";
  // Smaller extents reuse the larger images.
  const std::uint64_t grown = context->memoryUsage().totalBytes();
  ASSERT_TRUE(context->prepare(low, hd, &error));
  EXPECT_EQ(context->memoryUsage().totalBytes(), grown);
  device.waitIdle();
}

// The cloud depth output exists while something reads it: the host (Settings::depthOutput)
// or the module's own bolts (lightningBoltSegments > 0). Without it dispatch() runs as before
// (the validation layer sees every binding filled) and the image, once no frame can use it,
// is freed.
TEST_F(Contract, TheDepthOutputExistsWhileSomethingReadsIt) {
  engine::gfx::Device& device = this->device();
  clouds::Error error;
  auto context = clouds::Context::create(shimmedInfo(device), &error);
  ASSERT_TRUE(context) << error.message;
  std::uint64_t frameIndex = 0;
  const auto run = [&](const clouds::Settings& settings) {
    ASSERT_TRUE(context->prepare(settings, kExtent, &error)) << error.message;
    for (int i = 0; i < 3; ++i) {
      device.immediateSubmit([&](VkCommandBuffer cmd) {
        ASSERT_TRUE(context->dispatch(frame(cmd, kExtent, frameIndex++), settings, &error))
            << error.message;
      });
    }
  };
  const auto hasDepth = [&] { return context->outputs().depth.image != VK_NULL_HANDLE; };
  clouds::Settings read = clouds::settingsFor(clouds::Quality::High);
  ASSERT_TRUE(read.depthOutput) << "hosts get the depth unless they say otherwise";
  run(read);
  EXPECT_TRUE(hasDepth());
  EXPECT_EQ(context->outputs().depth.format, VK_FORMAT_R32G32_SFLOAT);
  const std::uint64_t withDepth = context->memoryUsage().outputBytes;

  clouds::Settings unread = read;
  unread.depthOutput = false;
  run(unread);
  EXPECT_FALSE(hasDepth());
  EXPECT_LT(context->memoryUsage().outputBytes, withDepth);
  EXPECT_EQ(context->memoryUsage().retiredBytes, 0u) << "freed once no frame can use it";

  clouds::Settings bolts = unread;
  bolts.lightningBoltSegments = 4;
  run(bolts);
  EXPECT_TRUE(hasDepth()) << "the bolts' pass reads the clouds' depth";
  EXPECT_EQ(context->memoryUsage().outputBytes, withDepth);

  // A clear sky clears only the outputs there are.
  unread.coverage = 0.0f;
  run(unread);
  EXPECT_FALSE(hasDepth());
  EXPECT_EQ(std::string(context->lastFrameReport().resetReason), "clear sky: nothing to march");
  device.waitIdle();
}

TEST_F(Contract, EveryErrorHasACode) {
  engine::gfx::Device& device = this->device();
  clouds::Error error;
  EXPECT_FALSE(clouds::Context::create(clouds::CreateInfo{}, &error));
  EXPECT_EQ(error.code, clouds::ErrorCode::InvalidCreateInfo);
  clouds::CreateInfo info = shimmedInfo(device);
  info.maxFramesInFlight = 9;
  EXPECT_FALSE(clouds::Context::create(info, &error));
  EXPECT_EQ(error.code, clouds::ErrorCode::InvalidCreateInfo);
  EXPECT_NE(error.message.find("maxFramesInFlight"), std::string::npos);
  info = shimmedInfo(device);
  info.compositeColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
  EXPECT_FALSE(clouds::Context::create(info, &error));
  EXPECT_EQ(error.code, clouds::ErrorCode::InvalidCreateInfo);
  info = shimmedInfo(device);
  info.getDeviceProcAddr = [](VkDevice d, const char* name) -> PFN_vkVoidFunction {
    return std::string_view(name) == "vkCmdDispatch" ? nullptr : vkGetDeviceProcAddr(d, name);
  };
  EXPECT_FALSE(clouds::Context::create(info, &error));
  EXPECT_EQ(error.code, clouds::ErrorCode::MissingFunction);
  EXPECT_NE(error.message.find("vkCmdDispatch"), std::string::npos);

  auto context = clouds::Context::create(shimmedInfo(device), &error);
  ASSERT_TRUE(context);
  EXPECT_EQ(error.code, clouds::ErrorCode::None);
  clouds::Settings bad;
  bad.coverage = 2.0f;
  EXPECT_FALSE(context->prepare(bad, kExtent, &error));
  EXPECT_EQ(error.code, clouds::ErrorCode::InvalidSettings);
  EXPECT_NE(error.message.find("Settings.coverage"), std::string::npos);
  EXPECT_FALSE(context->prepare({}, {4096, 16}, &error));
  EXPECT_EQ(error.code, clouds::ErrorCode::InvalidInputs);
  ASSERT_TRUE(context->prepare({}, kExtent, &error));
  device.immediateSubmit([&](VkCommandBuffer cmd) {
    clouds::FrameInputs in = frame(cmd, kExtent, 0);
    in.sunIlluminance = glm::vec3(-1.0f);
    EXPECT_FALSE(context->dispatch(in, {}, &error));
    EXPECT_EQ(error.code, clouds::ErrorCode::InvalidInputs);
    EXPECT_NE(error.message.find("FrameInputs.sunIlluminance"), std::string::npos);
    for (const glm::vec3 albedo : {glm::vec3(1.5f, 0.2f, 0.2f), glm::vec3(-0.1f),
                                   glm::vec3(std::numeric_limits<float>::quiet_NaN())}) {
      in = frame(cmd, kExtent, 0);
      in.groundAlbedo = albedo;
      EXPECT_FALSE(context->dispatch(in, {}, &error));
      EXPECT_EQ(error.code, clouds::ErrorCode::InvalidInputs);
      EXPECT_NE(error.message.find("FrameInputs.groundAlbedo"), std::string::npos);
    }
    EXPECT_FALSE(context->dispatch(frame(cmd, kExtent, 0), bad, &error));
    EXPECT_EQ(error.code, clouds::ErrorCode::InvalidSettings);
    ASSERT_TRUE(context->dispatch(frame(cmd, kExtent, 0), {}, &error));
    EXPECT_FALSE(context->composite(cmd, VK_NULL_HANDLE, kExtent, &error));
    EXPECT_EQ(error.code, clouds::ErrorCode::InvalidInputs);
  });
  for (clouds::ErrorCode code :
       {clouds::ErrorCode::None, clouds::ErrorCode::InvalidCreateInfo,
        clouds::ErrorCode::MissingFunction, clouds::ErrorCode::UnsupportedDevice,
        clouds::ErrorCode::OutOfMemory, clouds::ErrorCode::VulkanFailure,
        clouds::ErrorCode::InvalidSettings, clouds::ErrorCode::InvalidInputs,
        clouds::ErrorCode::NotPrepared}) {
    EXPECT_STRNE(clouds::errorCodeName(code), "?");
  }
  device.waitIdle();
}

}  // namespace
