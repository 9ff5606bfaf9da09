// clouds::Context: the public API, recording the module's passes into the host's command
// buffer (order in context_impl.h). Barriers are compute-to-compute except for the outputs,
// which end visible to the host's compute and fragment shaders.
#include <cmath>
#include <cstring>

#include "clouds_shaders/cloud_march.comp.spv.h"
#include "clouds_shaders/composite.comp.spv.h"
#include "clouds_shaders/depth_downsample.comp.spv.h"
#include "clouds_shaders/noise_curl.comp.spv.h"
#include "clouds_shaders/noise_detail.comp.spv.h"
#include "clouds_shaders/noise_shape.comp.spv.h"
#include "clouds_shaders/reconstruct.comp.spv.h"
#include "clouds_shaders/sky_ambient.comp.spv.h"
#include "clouds_shaders/upsample.comp.spv.h"
#include "clouds_shaders/weather_max.comp.spv.h"
#include "clouds_shaders/weather_procedural.comp.spv.h"
#include "clouds_shaders/weather_resample.comp.spv.h"
#include "context_impl.h"

namespace clouds {

using detail::bits;
using detail::check;

namespace {

constexpr VkFormat kNoiseFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kRadianceFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kDepthOutputFormat = VK_FORMAT_R32G32_SFLOAT;
// Trace-resolution samples: radiance, transmittance and both depths packed in one texel
// (cloud_temporal.h).
constexpr VkFormat kSampleFormat = VK_FORMAT_R32G32B32A32_UINT;
constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr VkAccessFlags2 kStorageWrite = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
constexpr VkAccessFlags2 kStorageRead = VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
// Where host passes may read the outputs.
constexpr VkPipelineStageFlags2 kHostReadStages =
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkAccessFlags2 kHostReadAccess =
    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;

std::uint32_t groups(std::uint32_t size, std::uint32_t group) {
  return (size + group - 1) / group;
}

VkSampler createSampler(const detail::DeviceContext& device, VkFilter filter,
                        VkSamplerAddressMode address, const char* name) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = address;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSampler sampler = VK_NULL_HANDLE;
  check(device.fn().vkCreateSampler(device.device(), &info, nullptr, &sampler), "vkCreateSampler");
  device.name(VK_OBJECT_TYPE_SAMPLER, bits(sampler), name);
  return sampler;
}

}  // namespace

// Rows of the next period's weather map generated per frame: 1/16 of the map, ~3 ms on lavapipe,
// so a period of 16 frames or more has its map ready when it starts.
constexpr std::uint32_t kWeatherRowsAhead =
    static_cast<std::uint32_t>(shader::kWeatherMapSize) / 16;

Context::Impl::Impl(const CreateInfo& info, const detail::VulkanFunctions& functions)
    : info_(info),
      device_(info, functions),
      weatherSchedule_(static_cast<std::uint32_t>(shader::kWeatherMapSize), kWeatherRowsAhead) {
  using detail::OwnedImage;
  const VkImageUsageFlags storage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  const auto s = static_cast<std::uint32_t>(shader::kShapeNoiseSize);
  const auto d = static_cast<std::uint32_t>(shader::kDetailNoiseSize);
  const auto c = static_cast<std::uint32_t>(shader::kCurlNoiseSize);
  const auto w = static_cast<std::uint32_t>(shader::kWeatherMapSize);
  shapeNoise_ =
      OwnedImage(device_, VK_IMAGE_TYPE_3D, kNoiseFormat, {s, s, s}, storage, "shape noise");
  detailNoise_ =
      OwnedImage(device_, VK_IMAGE_TYPE_3D, kNoiseFormat, {d, d, d}, storage, "detail noise");
  curlNoise_ =
      OwnedImage(device_, VK_IMAGE_TYPE_2D, kNoiseFormat, {c, c, 1}, storage, "curl noise");
  for (std::uint32_t i = 0; i < 2; ++i) {
    weatherMaps_[i] = OwnedImage(device_, VK_IMAGE_TYPE_2D, kNoiseFormat, {w, w, 1}, storage,
                                 "weather map " + std::to_string(i));
  }
  const auto fine = static_cast<std::uint32_t>(shader::kWeatherMaxFineSize);
  const auto coarse = static_cast<std::uint32_t>(shader::kWeatherMaxCoarseSize);
  weatherMaxFine_ = OwnedImage(device_, VK_IMAGE_TYPE_2D, kNoiseFormat, {fine, fine, 1}, storage,
                               "weather maxima (fine)");
  weatherMaxCoarse_ = OwnedImage(device_, VK_IMAGE_TYPE_2D, kNoiseFormat, {coarse, coarse, 1},
                                 storage, "weather maxima (coarse)");
  const VkExtent3D maxExtent{info.maxRenderExtent.width, info.maxRenderExtent.height, 1};
  // Outputs also take clears (a provably clear sky is cleared, not marched).
  const VkImageUsageFlags output =
      storage | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  radiance_ = OwnedImage(device_, VK_IMAGE_TYPE_2D, kRadianceFormat, maxExtent, output, "radiance");
  depth_ =
      OwnedImage(device_, VK_IMAGE_TYPE_2D, kDepthOutputFormat, maxExtent, output, "cloud depth");
  // The trace resolution never exceeds the output's (traceScale <= 1).
  sceneDistance_ = OwnedImage(device_, VK_IMAGE_TYPE_2D, VK_FORMAT_R32_SFLOAT, maxExtent, storage,
                              "scene distance (trace)");
  traceSamples_ = OwnedImage(device_, VK_IMAGE_TYPE_2D, kSampleFormat, maxExtent, storage,
                             "marched samples (trace)");
  // History images also take transfers in, so the module's tests can poison them.
  const VkImageUsageFlags history = storage | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  for (std::uint32_t i = 0; i < 2; ++i) {
    history_[i] = OwnedImage(device_, VK_IMAGE_TYPE_2D, kSampleFormat, maxExtent, history,
                             "history " + std::to_string(i));
    outputHistory_[i] = OwnedImage(device_, VK_IMAGE_TYPE_2D, kSampleFormat, maxExtent, history,
                                   "output history " + std::to_string(i));
  }
  placeholder_ = OwnedImage(device_, VK_IMAGE_TYPE_2D, VK_FORMAT_R32_SFLOAT, {1, 1, 1},
                            VK_IMAGE_USAGE_SAMPLED_BIT, "placeholder input");

  nearestSampler_ = createSampler(device_, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                  "nearest sampler");
  linearSampler_ =
      createSampler(device_, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, "linear sampler");

  using detail::ComputeProgram;
  const VkDescriptorType img = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  const VkDescriptorType tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  shapeProgram_ =
      std::make_unique<ComputeProgram>(device_, noise_shape_comp_spv, std::vector{img},
                                       sizeof(shader::NoiseConstants), "shape noise generator");
  detailProgram_ =
      std::make_unique<ComputeProgram>(device_, noise_detail_comp_spv, std::vector{img},
                                       sizeof(shader::NoiseConstants), "detail noise generator");
  curlProgram_ =
      std::make_unique<ComputeProgram>(device_, noise_curl_comp_spv, std::vector{img},
                                       sizeof(shader::NoiseConstants), "curl noise generator");
  weatherProgram_ =
      std::make_unique<ComputeProgram>(device_, weather_procedural_comp_spv, std::vector{img},
                                       sizeof(shader::WeatherConstants), "weather generator");
  resampleProgram_ = std::make_unique<ComputeProgram>(
      device_, weather_resample_comp_spv, std::vector{img, tex}, 0u, "weather resample");
  skyAmbientProgram_ = std::make_unique<ComputeProgram>(
      device_, sky_ambient_comp_spv, std::vector{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, tex}, 0u,
      "sky ambient");
  const VkDescriptorType ubo = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;  // frame_uniforms.glsl
  const VkDescriptorType ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  weatherMaxProgram_ = std::make_unique<ComputeProgram>(
      device_, weather_max_comp_spv, std::vector{img, img}, 16u, "weather maxima");
  downsample_ = std::make_unique<ComputeProgram>(
      device_, depth_downsample_comp_spv, std::vector{ubo, tex, img}, 0u, "depth downsample");
  march_ = std::make_unique<ComputeProgram>(
      device_, cloud_march_comp_spv, std::vector{ubo, img, img, img, img, img, img, img, img, ssbo},
      0u, "march");
  reconstruct_ = std::make_unique<ComputeProgram>(
      device_, reconstruct_comp_spv, std::vector{ubo, img, img, img}, 0u, "reconstruct");
  upsample_ = std::make_unique<ComputeProgram>(device_, upsample_comp_spv,
                                               std::vector{ubo, img, tex, img, img, img, img, img},
                                               0u, "upsample");
  compositeProgram_ =
      std::make_unique<ComputeProgram>(device_, composite_comp_spv, std::vector{img, img},
                                       sizeof(shader::CompositeConstants), "composite");

  const std::uint32_t frames = info.maxFramesInFlight;
  const VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 16 + 32 * frames},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4 + 8 * frames},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 8 * frames},
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 4 * frames},
  };
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 8 + 8 * frames;
  poolInfo.poolSizeCount = static_cast<std::uint32_t>(std::size(sizes));
  poolInfo.pPoolSizes = sizes;
  check(device_.fn().vkCreateDescriptorPool(device_.device(), &poolInfo, nullptr, &pool_),
        "vkCreateDescriptorPool");
  device_.name(VK_OBJECT_TYPE_DESCRIPTOR_POOL, bits(pool_), "descriptor pool");

  shapeSet_ = allocateSet(shapeProgram_->setLayout());
  detailSet_ = allocateSet(detailProgram_->setLayout());
  curlSet_ = allocateSet(curlProgram_->setLayout());
  detail::SetWriter(device_, shapeSet_).storageImage(0, shapeNoise_.view()).commit();
  detail::SetWriter(device_, detailSet_).storageImage(0, detailNoise_.view()).commit();
  detail::SetWriter(device_, curlSet_).storageImage(0, curlNoise_.view()).commit();
  for (std::uint32_t i = 0; i < 2; ++i) {
    weatherSets_[i] = allocateSet(weatherProgram_->setLayout());
    detail::SetWriter(device_, weatherSets_[i]).storageImage(0, weatherMaps_[i].view()).commit();
    weatherMaxFineSets_[i] = allocateSet(weatherMaxProgram_->setLayout());
    detail::SetWriter(device_, weatherMaxFineSets_[i])
        .storageImage(0, weatherMaps_[i].view())
        .storageImage(1, weatherMaxFine_.view())
        .commit();
  }
  weatherMaxCoarseSet_ = allocateSet(weatherMaxProgram_->setLayout());
  detail::SetWriter(device_, weatherMaxCoarseSet_)
      .storageImage(0, weatherMaxFine_.view())
      .storageImage(1, weatherMaxCoarse_.view())
      .commit();

  if (info.passTimings)
    timer_ = std::make_unique<detail::PassTimer>(device_, info.physicalDevice, frames);
  slots_.resize(frames);
  for (std::uint32_t i = 0; i < frames; ++i) {
    Slot& slot = slots_[i];
    slot.uniforms = detail::OwnedBuffer(
        device_, sizeof(shader::CloudUniforms),
        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
            VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
        "uniforms " + std::to_string(i));
    slot.counters =
        detail::OwnedBuffer(device_, shader::kCounterCount * sizeof(std::uint32_t),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            "work counters " + std::to_string(i), /*hostVisible=*/true);
    slot.downsample = allocateSet(downsample_->setLayout());
    slot.march = allocateSet(march_->setLayout());
    slot.reconstruct = allocateSet(reconstruct_->setLayout());
    slot.upsample = allocateSet(upsample_->setLayout());
    slot.composite = allocateSet(compositeProgram_->setLayout());
    slot.skyAmbient = allocateSet(skyAmbientProgram_->setLayout());
    slot.weatherResample = allocateSet(resampleProgram_->setLayout());
  }
}

Context::Impl::~Impl() {
  const auto& fn = device_.fn();
  fn.vkDestroyDescriptorPool(device_.device(), pool_, nullptr);
  fn.vkDestroySampler(device_.device(), nearestSampler_, nullptr);
  fn.vkDestroySampler(device_.device(), linearSampler_, nullptr);
}

VkDescriptorSet Context::Impl::allocateSet(VkDescriptorSetLayout layout) {
  VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  info.descriptorPool = pool_;
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  check(device_.fn().vkAllocateDescriptorSets(device_.device(), &info, &set),
        "vkAllocateDescriptorSets");
  return set;
}

void Context::Impl::beginPass(VkCommandBuffer cmd, detail::Pass pass, const char* label) {
  device_.beginLabel(cmd, label);
  if (timer_) timer_->begin(cmd, pass);
}

void Context::Impl::endPass(VkCommandBuffer cmd, detail::Pass pass) {
  if (timer_) timer_->end(cmd, pass);
  device_.endLabel(cmd);
}

void Context::Impl::recordInitialisation(VkCommandBuffer cmd) {
  const auto& fn = device_.fn();
  beginPass(cmd, detail::Pass::Noise, "clouds: noise generation");
  for (const detail::OwnedImage* image :
       {&shapeNoise_, &detailNoise_, &curlNoise_, &weatherMaps_[0], &weatherMaps_[1],
        &weatherMaxFine_, &weatherMaxCoarse_, &radiance_, &depth_, &sceneDistance_, &traceSamples_,
        &history_[0], &history_[1], &outputHistory_[0], &outputHistory_[1]}) {
    detail::barrier(device_, cmd, image->image(), VK_IMAGE_ASPECT_COLOR_BIT,
                    VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_NONE,
                    VK_ACCESS_2_NONE, kCompute, kStorageRead | kStorageWrite);
  }
  detail::barrier(device_, cmd, placeholder_.image(), VK_IMAGE_ASPECT_COLOR_BIT,
                  VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, kCompute,
                  VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);

  struct Job {
    detail::ComputeProgram* program;
    VkDescriptorSet set;
    std::uint32_t size;
    bool volume;
  };
  const Job jobs[] = {
      {shapeProgram_.get(), shapeSet_, static_cast<std::uint32_t>(shader::kShapeNoiseSize), true},
      {detailProgram_.get(), detailSet_, static_cast<std::uint32_t>(shader::kDetailNoiseSize),
       true},
      {curlProgram_.get(), curlSet_, static_cast<std::uint32_t>(shader::kCurlNoiseSize), false},
  };
  for (const Job& job : jobs) {
    fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, job.program->variant());
    fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, job.program->layout(), 0, 1,
                               &job.set, 0, nullptr);
    const shader::NoiseConstants constants{glm::uvec4(info_.noiseSeed, job.size, 0u, 0u)};
    fn.vkCmdPushConstants(cmd, job.program->layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                          sizeof(constants), &constants);
    if (job.volume) {
      const std::uint32_t n = groups(job.size, shader::kWorkgroupSize3D);
      fn.vkCmdDispatch(cmd, n, n, n);
    } else {
      const std::uint32_t n = groups(job.size, shader::kWorkgroupSize2D);
      fn.vkCmdDispatch(cmd, n, n, 1);
    }
  }
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  endPass(cmd, detail::Pass::Noise);
  initialised_ = true;
}

void Context::Impl::recordWeather(VkCommandBuffer cmd, const FrameInputs& inputs,
                                  const Settings& settings, Slot& slot) {
  if (inputs.weatherView != VK_NULL_HANDLE) {
    const auto& fn = device_.fn();
    const std::uint32_t n =
        groups(static_cast<std::uint32_t>(shader::kWeatherMapSize), shader::kWorkgroupSize2D);
    // A painted map: resampled every frame (the host may repaint it at any time).
    beginPass(cmd, detail::Pass::Weather, "clouds: weather resample");
    detail::SetWriter(device_, slot.weatherResample)
        .storageImage(0, weatherMap().view())
        .sampledImage(1, inputs.weatherView, linearSampler_, inputs.weatherLayout)
        .commit();
    detail::memoryBarrier(device_, cmd, kCompute, kStorageRead, kCompute, kStorageWrite);
    fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resampleProgram_->variant());
    fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resampleProgram_->layout(), 0,
                               1, &slot.weatherResample, 0, nullptr);
    fn.vkCmdDispatch(cmd, n, n, 1);
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
    recordWeatherMaxima(cmd);
    endPass(cmd, detail::Pass::Weather);
    weatherSchedule_.forget();  // returning to the procedural map regenerates it
    ++weatherUpdates_;
    return;
  }
  // The procedural map evolves slowly: one map per update period, a pure function of the
  // period (deterministic), prepared a few rows per frame ahead of its period.
  const double period = settings.weatherUpdateSeconds;
  const std::int64_t key = period > 0.0
                               ? static_cast<std::int64_t>(std::floor(inputs.timeSeconds / period))
                               : static_cast<std::int64_t>(inputs.frameIndex);
  weatherSchedule_.useRecipe(period, settings.weatherEvolutionPerSecond);
  const detail::WeatherWork work = weatherSchedule_.plan(key, period > 0.0);
  if (!work.generates() && !work.swap) return;
  beginPass(cmd, detail::Pass::Weather,
            work.swap ? "clouds: weather map" : "clouds: next weather map");
  if (work.generates()) {
    // A period's map is the weather at the period's start.
    const double mapTime =
        period > 0.0 ? static_cast<double>(work.key) * period : inputs.timeSeconds;
    recordWeatherRows(cmd, settings, work, mapTime);
  }
  if (work.swap) {
    currentWeather_ ^= 1u;
    recordWeatherMaxima(cmd);
    ++weatherUpdates_;
  }
  endPass(cmd, detail::Pass::Weather);
}

void Context::Impl::recordWeatherRows(VkCommandBuffer cmd, const Settings& settings,
                                      const detail::WeatherWork& work, double mapTimeSeconds) {
  const auto& fn = device_.fn();
  const double phase = mapTimeSeconds * settings.weatherEvolutionPerSecond;
  shader::WeatherConstants constants{};
  constants.params = glm::vec4(static_cast<float>(phase - std::floor(phase)), 0.0f, 0.0f, 0.0f);
  constants.seed = glm::uvec4(info_.noiseSeed, work.firstRow, 0u, 0u);
  const std::uint32_t spare = currentWeather_ ^ 1u;
  // The spare map may still be read by earlier frames' marches.
  detail::memoryBarrier(device_, cmd, kCompute, kStorageRead, kCompute, kStorageWrite);
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, weatherProgram_->variant());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, weatherProgram_->layout(), 0, 1,
                             &weatherSets_[spare], 0, nullptr);
  fn.vkCmdPushConstants(cmd, weatherProgram_->layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                        sizeof(constants), &constants);
  const auto width = static_cast<std::uint32_t>(shader::kWeatherMapSize);
  fn.vkCmdDispatch(cmd, groups(width, shader::kWorkgroupSize2D),
                   groups(work.endRow - work.firstRow, shader::kWorkgroupSize2D), 1);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
}

void Context::Impl::recordWeatherMaxima(VkCommandBuffer cmd) {
  const auto& fn = device_.fn();
  const auto weather = static_cast<std::uint32_t>(shader::kWeatherMapSize);
  const auto fine = static_cast<std::uint32_t>(shader::kWeatherMaxFineSize);
  const auto coarse = static_cast<std::uint32_t>(shader::kWeatherMaxCoarseSize);
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, weatherMaxProgram_->variant());
  const struct {
    VkDescriptorSet set;
    glm::uvec4 params;  // source size, cell, target size
  } levels[] = {{weatherMaxFineSets_[currentWeather_], {weather, weather / fine, fine, 0u}},
                {weatherMaxCoarseSet_, {fine, fine / coarse, coarse, 0u}}};
  for (const auto& level : levels) {
    fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, weatherMaxProgram_->layout(), 0,
                               1, &level.set, 0, nullptr);
    fn.vkCmdPushConstants(cmd, weatherMaxProgram_->layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                          sizeof(level.params), &level.params);
    const std::uint32_t n = groups(level.params.z, shader::kWorkgroupSize2D);
    fn.vkCmdDispatch(cmd, n, n, 1);
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  }
}

void Context::Impl::recordUniforms(VkCommandBuffer cmd, Slot& slot,
                                   const shader::CloudUniforms& uniforms) {
  // The previous frame of this slot has completed (host contract), but earlier commands in
  // this queue may still read it: order the update after them.
  detail::memoryBarrier(device_, cmd, kCompute, VK_ACCESS_2_UNIFORM_READ_BIT | kStorageRead,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  device_.fn().vkCmdUpdateBuffer(cmd, slot.uniforms.buffer(), 0, sizeof(uniforms), &uniforms);
  detail::memoryBarrier(device_, cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute,
                        VK_ACCESS_2_UNIFORM_READ_BIT | kStorageRead | kStorageWrite);
}

void Context::Impl::recordSkyAmbient(VkCommandBuffer cmd, const FrameInputs& inputs, Slot& slot) {
  const auto& fn = device_.fn();
  beginPass(cmd, detail::Pass::SkyAmbient, "clouds: sky ambient");
  detail::SetWriter(device_, slot.skyAmbient)
      .storageBuffer(0, slot.uniforms.buffer(), sizeof(shader::CloudUniforms))
      .sampledImage(1, inputs.skyView, linearSampler_, inputs.skyLayout)
      .commit();
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, skyAmbientProgram_->variant());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, skyAmbientProgram_->layout(), 0,
                             1, &slot.skyAmbient, 0, nullptr);
  fn.vkCmdDispatch(cmd, 1, 1, 1);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute,
                        VK_ACCESS_2_UNIFORM_READ_BIT);
  endPass(cmd, detail::Pass::SkyAmbient);
}

void Context::Impl::bindAndDispatch(VkCommandBuffer cmd, detail::ComputeProgram& program,
                                    VkPipeline pipeline, VkDescriptorSet set, std::uint32_t width,
                                    std::uint32_t height) {
  const auto& fn = device_.fn();
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1, &set, 0,
                             nullptr);
  fn.vkCmdDispatch(cmd, groups(width, shader::kWorkgroupSize2D),
                   groups(height, shader::kWorkgroupSize2D), 1);
}

void Context::Impl::recordTrace(VkCommandBuffer cmd, const FrameInputs& inputs,
                                const Settings& settings, const detail::TemporalFrame& temporal,
                                VkExtent2D traceExtent, Slot& slot) {
  const auto& fn = device_.fn();
  const bool hasDepth = inputs.depthView != VK_NULL_HANDLE;
  const VkImageView depthView = hasDepth ? inputs.depthView : placeholder_.view();
  const VkImageLayout depthLayout =
      hasDepth ? inputs.depthLayout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  const VkDeviceSize uniformBytes = sizeof(shader::CloudUniforms);
  const detail::OwnedImage& historyIn = history_[temporal.readHistory];
  const detail::OwnedImage& historyOut = history_[temporal.writeHistory];

  detail::SetWriter(device_, slot.downsample)
      .uniformBuffer(0, slot.uniforms.buffer(), uniformBytes)
      .sampledImage(1, depthView, nearestSampler_, depthLayout)
      .storageImage(2, sceneDistance_.view())
      .commit();
  detail::SetWriter(device_, slot.march)
      .uniformBuffer(0, slot.uniforms.buffer(), uniformBytes)
      .storageImage(1, shapeNoise_.view())
      .storageImage(2, detailNoise_.view())
      .storageImage(3, weatherMap().view())
      .storageImage(4, curlNoise_.view())
      .storageImage(5, sceneDistance_.view())
      .storageImage(6, traceSamples_.view())
      .storageImage(7, weatherMaxFine_.view())
      .storageImage(8, weatherMaxCoarse_.view())
      .storageBuffer(9, slot.counters.buffer(), slot.counters.size())
      .commit();
  detail::SetWriter(device_, slot.reconstruct)
      .uniformBuffer(0, slot.uniforms.buffer(), uniformBytes)
      .storageImage(1, traceSamples_.view())
      .storageImage(2, historyIn.view())
      .storageImage(3, historyOut.view())
      .commit();
  detail::SetWriter(device_, slot.upsample)
      .uniformBuffer(0, slot.uniforms.buffer(), uniformBytes)
      .storageImage(1, historyOut.view())
      .sampledImage(2, depthView, nearestSampler_, depthLayout)
      .storageImage(3, radiance_.view())
      .storageImage(4, depth_.view())
      .storageImage(5, traceSamples_.view())
      .storageImage(6, outputHistory_[temporal.readHistory].view())
      .storageImage(7, outputHistory_[temporal.writeHistory].view())
      .commit();

  // Everything these passes write may still be read by earlier commands (last frame's
  // reconstruction and upsample, the host's reads of the outputs).
  detail::memoryBarrier(device_, cmd, kHostReadStages, kHostReadAccess | kStorageRead, kCompute,
                        kStorageWrite);
  if (info_.workCounters) {
    fn.vkCmdFillBuffer(cmd, slot.counters.buffer(), 0, VK_WHOLE_SIZE, 0u);
    detail::memoryBarrier(device_, cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute, kStorageRead | kStorageWrite);
  }

  beginPass(cmd, detail::Pass::SceneDistance, "clouds: scene distance");
  bindAndDispatch(cmd, *downsample_, downsample_->variant(), slot.downsample, traceExtent.width,
                  traceExtent.height);
  // The barrier is part of the pass: on lavapipe a dispatch only starts the work, and the
  // barrier waits for it.
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  endPass(cmd, detail::Pass::SceneDistance);

  const detail::MarchVariant v = detail::marchVariant(settings);
  detail::SpecializationKey key;
  key.values = {v.jitter,        v.detail,
                v.cheapSampling, v.multipleScattering,
                v.lightSteps,    info_.workCounters ? 1u : 0u,
                v.emptySpace};
  key.count = 7;
  const std::uint32_t k = temporal.tileSize;
  beginPass(cmd, detail::Pass::March, "clouds: march");
  // One invocation per tile: only the pixels marched this frame.
  bindAndDispatch(cmd, *march_, march_->variant(key), slot.march, (traceExtent.width + k - 1) / k,
                  (traceExtent.height + k - 1) / k);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  endPass(cmd, detail::Pass::March);

  if (info_.workCounters) {
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, VK_PIPELINE_STAGE_2_HOST_BIT,
                          VK_ACCESS_2_HOST_READ_BIT);
  }
  // History variants (kSpecHistory, kSpecOutputHistory): none, read in place, reprojected.
  const auto historyVariant = [&](bool use) { return !use ? 0u : temporal.still ? 1u : 2u; };
  beginPass(cmd, detail::Pass::Reconstruct, "clouds: reconstruct");
  detail::SpecializationKey reconstructKey;
  reconstructKey.values = {historyVariant(temporal.useHistory)};
  reconstructKey.count = 1;
  bindAndDispatch(cmd, *reconstruct_, reconstruct_->variant(reconstructKey), slot.reconstruct,
                  traceExtent.width, traceExtent.height);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  endPass(cmd, detail::Pass::Reconstruct);

  beginPass(cmd, detail::Pass::Upsample, "clouds: upsample");
  detail::SpecializationKey upsampleKey;
  const std::uint32_t outputHistory = historyVariant(temporal.useOutputHistory);
  upsampleKey.values = {temporal.upsampleTemporally ? 1u : 0u, outputHistory};
  upsampleKey.count = 2;
  bindAndDispatch(cmd, *upsample_, upsample_->variant(upsampleKey), slot.upsample,
                  inputs.renderExtent.width, inputs.renderExtent.height);
  for (const detail::OwnedImage* image : {&radiance_, &depth_}) {
    detail::barrier(device_, cmd, image->image(), VK_IMAGE_ASPECT_COLOR_BIT,
                    VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, kCompute, kStorageWrite,
                    kHostReadStages, kHostReadAccess);
  }
  endPass(cmd, detail::Pass::Upsample);
}

bool Context::Impl::skyIsClear(const Settings& s) {
  // Coverage = weather texel + 2 coverage - 1 <= 0 for every texel when coverage is 0; no
  // extinction, no cloud. Anything else may hold cloud somewhere the camera sees.
  return s.coverage <= 0.0f || s.densityMultiplier <= 0.0f || s.extinctionPerMetre <= 0.0f;
}

void Context::Impl::recordClearSky(VkCommandBuffer cmd, Slot& slot) {
  const auto& fn = device_.fn();
  beginPass(cmd, detail::Pass::ClearSky, "clouds: clear sky");
  const VkPipelineStageFlags2 transfer = VK_PIPELINE_STAGE_2_CLEAR_BIT;
  // The outputs (and the counters) may still be read by earlier commands.
  detail::memoryBarrier(device_, cmd, kHostReadStages, kHostReadAccess | kStorageRead, transfer,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT);
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkClearColorValue noCloud{};
  noCloud.float32[3] = 1.0f;  // transmittance 1, no radiance
  fn.vkCmdClearColorImage(cmd, radiance_.image(), VK_IMAGE_LAYOUT_GENERAL, &noCloud, 1, &range);
  const VkClearColorValue noDepth{};
  fn.vkCmdClearColorImage(cmd, depth_.image(), VK_IMAGE_LAYOUT_GENERAL, &noDepth, 1, &range);
  if (info_.workCounters) fn.vkCmdFillBuffer(cmd, slot.counters.buffer(), 0, VK_WHOLE_SIZE, 0u);
  for (const detail::OwnedImage* image : {&radiance_, &depth_}) {
    detail::barrier(device_, cmd, image->image(), VK_IMAGE_ASPECT_COLOR_BIT,
                    VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, transfer,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, kHostReadStages, kHostReadAccess);
  }
  if (info_.workCounters) {
    detail::memoryBarrier(device_, cmd, transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  }
  endPass(cmd, detail::Pass::ClearSky);
}

void Context::Impl::dispatch(const FrameInputs& inputs, const Settings& settings) {
  const VkCommandBuffer cmd = inputs.commandBuffer;
  const auto slotIndex = static_cast<std::uint32_t>(inputs.frameIndex % slots_.size());
  Slot& slot = slots_[slotIndex];
  device_.beginLabel(cmd, "clouds");
  if (timer_) timer_->beginFrame(cmd, slotIndex);
  if (!initialised_) recordInitialisation(cmd);
  recordWeather(cmd, inputs, settings, slot);

  const VkExtent2D traceExtent = detail::traceExtentFor(inputs.renderExtent, settings.traceScale);
  const detail::TemporalFrame temporal = temporal_.plan(inputs, settings, traceExtent);
  detail::UniformContext uniformContext;
  uniformContext.reversedZ = info_.reversedZ;
  uniformContext.hasDepth = inputs.depthView != VK_NULL_HANDLE;
  uniformContext.traceExtent = traceExtent;
  uniformContext.fullExtent = inputs.renderExtent;
  uniformContext.temporalIndex = temporal.temporalIndex;
  uniformContext.tileSize = temporal.tileSize;
  uniformContext.phase = temporal.phase;
  uniformContext.useHistory = temporal.useHistory;
  uniformContext.useOutputHistory = temporal.useOutputHistory;
  uniformContext.cameraDelta = temporal.cameraDelta;
  uniformContext.deltaSeconds = temporal.deltaSeconds;
  lastUniforms_ = detail::buildUniforms(inputs, settings, uniformContext);
  lastUniforms_.frame.z |= debugFlags_;
  if (skyIsClear(settings)) {
    // Nothing can be marched: the outputs are the empty sky, and the next frame starts afresh.
    recordClearSky(cmd, slot);
    device_.endLabel(cmd);
    temporal_.forget();
    report_ = FrameReport{{0, 0}, 0, false, temporal.insideLayer, "clear sky: nothing to march"};
  } else {
    recordUniforms(cmd, slot, lastUniforms_);
    if (inputs.skyView != VK_NULL_HANDLE) recordSkyAmbient(cmd, inputs, slot);
    recordTrace(cmd, inputs, settings, temporal, traceExtent, slot);
    device_.endLabel(cmd);
    temporal_.commit(temporal, inputs, settings, traceExtent);
    report_ = FrameReport{traceExtent, temporal.tileSize, temporal.useHistory, temporal.insideLayer,
                          temporal.resetReason};
  }
  lastSlot_ = slotIndex;
  lastExtent_ = inputs.renderExtent;
}

WorkCounters Context::Impl::workCounters(std::uint64_t frameIndex) const {
  const Slot& slot = slots_[frameIndex % slots_.size()];
  const auto* values = static_cast<const std::uint32_t*>(slot.counters.mapped());
  WorkCounters counters;
  if (values == nullptr || !info_.workCounters) return counters;
  counters.viewSamples = values[shader::kCounterViewSamples];
  counters.lightSamples = values[shader::kCounterLightSamples];
  counters.tracedPixels = values[shader::kCounterTracedPixels];
  counters.earlyExits = values[shader::kCounterEarlyExits];
  counters.skippedCells = values[shader::kCounterSkippedCells];
  return counters;
}

std::vector<PassTiming> Context::Impl::passTimings(std::uint64_t frameIndex) const {
  if (!timer_) return {};
  return timer_->read(static_cast<std::uint32_t>(frameIndex % slots_.size()));
}

void Context::Impl::composite(VkCommandBuffer cmd, VkImageView color, VkExtent2D extent) {
  const auto& fn = device_.fn();
  Slot& slot = slots_[lastSlot_];
  detail::SetWriter(device_, slot.composite)
      .storageImage(0, color)
      .storageImage(1, radiance_.view())
      .commit();
  device_.beginLabel(cmd, "clouds: composite");
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compositeProgram_->variant());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compositeProgram_->layout(), 0, 1,
                             &slot.composite, 0, nullptr);
  const shader::CompositeConstants constants{glm::uvec4(extent.width, extent.height, 0u, 0u)};
  fn.vkCmdPushConstants(cmd, compositeProgram_->layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                        sizeof(constants), &constants);
  fn.vkCmdDispatch(cmd, groups(extent.width, shader::kWorkgroupSize2D),
                   groups(extent.height, shader::kWorkgroupSize2D), 1);
  device_.endLabel(cmd);
}

Outputs Context::Impl::outputs() const {
  Outputs out;
  out.radiance = {radiance_.image(), radiance_.view(), radiance_.format()};
  out.depth = {depth_.image(), depth_.view(), depth_.format()};
  out.extent = lastExtent_;
  return out;
}

// --- Public API ------------------------------------------------------------------------

namespace {

bool fail(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

std::string checkInputs(const FrameInputs& in, const CreateInfo& info) {
  if (in.commandBuffer == VK_NULL_HANDLE) return "FrameInputs.commandBuffer: must not be null";
  if (in.renderExtent.width == 0 || in.renderExtent.height == 0 ||
      in.renderExtent.width > info.maxRenderExtent.width ||
      in.renderExtent.height > info.maxRenderExtent.height) {
    return "FrameInputs.renderExtent = " + std::to_string(in.renderExtent.width) + "x" +
           std::to_string(in.renderExtent.height) + ": must be non-zero and within " +
           "CreateInfo.maxRenderExtent (" + std::to_string(info.maxRenderExtent.width) + "x" +
           std::to_string(info.maxRenderExtent.height) + ")";
  }
  if (!finite(in.view) || !finite(in.projection)) {
    return "FrameInputs.view/projection: must be finite";
  }
  if (std::abs(glm::determinant(in.projection)) < 1e-30f) {
    return "FrameInputs.projection: must be invertible";
  }
  for (double c : {in.cameraPosition.x, in.cameraPosition.y, in.cameraPosition.z}) {
    if (!std::isfinite(c)) return "FrameInputs.cameraPosition: must be finite";
  }
  for (const glm::vec3& v : {in.sunDirection, in.sunIlluminance, in.ambientTop, in.ambientBottom}) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      return "FrameInputs: sun and ambient values must be finite";
    }
  }
  if (in.sunIlluminance.x < 0 || in.sunIlluminance.y < 0 || in.sunIlluminance.z < 0 ||
      in.ambientTop.x < 0 || in.ambientTop.y < 0 || in.ambientTop.z < 0 || in.ambientBottom.x < 0 ||
      in.ambientBottom.y < 0 || in.ambientBottom.z < 0) {
    return "FrameInputs: sun illuminance and ambient radiance must not be negative";
  }
  if (!std::isfinite(in.timeSeconds) || in.timeSeconds < 0.0) {
    return "FrameInputs.timeSeconds = " + std::to_string(in.timeSeconds) + ": must be >= 0";
  }
  return {};
}

}  // namespace

std::unique_ptr<Context> Context::create(const CreateInfo& info, std::string* error) {
  if (info.device == VK_NULL_HANDLE || info.physicalDevice == VK_NULL_HANDLE ||
      info.instance == VK_NULL_HANDLE || info.getDeviceProcAddr == nullptr ||
      info.getInstanceProcAddr == nullptr) {
    fail(error,
         "CreateInfo: instance, physicalDevice, device and both proc-addr functions are required");
    return nullptr;
  }
  if (info.maxFramesInFlight < 1 || info.maxFramesInFlight > 8) {
    fail(error, "CreateInfo.maxFramesInFlight = " + std::to_string(info.maxFramesInFlight) +
                    ": must be in [1, 8]");
    return nullptr;
  }
  if (info.maxRenderExtent.width == 0 || info.maxRenderExtent.height == 0 ||
      info.maxRenderExtent.width > 16384 || info.maxRenderExtent.height > 16384) {
    fail(error, "CreateInfo.maxRenderExtent: must be in [1, 16384] per side");
    return nullptr;
  }
  if (info.compositeColorFormat != VK_FORMAT_UNDEFINED &&
      info.compositeColorFormat != VK_FORMAT_R16G16B16A16_SFLOAT) {
    fail(error,
         "CreateInfo.compositeColorFormat: only R16G16B16A16_SFLOAT (or UNDEFINED) is supported");
    return nullptr;
  }
  detail::VulkanFunctions functions;
  if (!functions.load(info, error)) return nullptr;
  try {
    auto impl = std::make_unique<Impl>(info, functions);
    return std::unique_ptr<Context>(new Context(std::move(impl)));
  } catch (const detail::ModuleError& e) {
    fail(error, e.what());
    return nullptr;
  }
}

Context::Context(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Context::~Context() = default;

bool Context::dispatch(const FrameInputs& inputs, const Settings& settings, std::string* error) {
  if (const std::string problem = checkInputs(inputs, impl_->createInfo()); !problem.empty()) {
    return fail(error, problem);
  }
  if (const std::string problem = validateSettings(settings); !problem.empty()) {
    return fail(error, problem);
  }
  try {
    impl_->dispatch(inputs, settings);
  } catch (const detail::ModuleError& e) {
    return fail(error, e.what());
  }
  return true;
}

bool Context::composite(VkCommandBuffer commandBuffer, VkImageView color, VkExtent2D extent,
                        std::string* error) {
  if (impl_->createInfo().compositeColorFormat == VK_FORMAT_UNDEFINED) {
    return fail(error, "composite: CreateInfo.compositeColorFormat was UNDEFINED");
  }
  if (commandBuffer == VK_NULL_HANDLE || color == VK_NULL_HANDLE) {
    return fail(error, "composite: command buffer and colour view are required");
  }
  const Outputs out = impl_->outputs();
  if (extent.width != out.extent.width || extent.height != out.extent.height) {
    return fail(error, "composite: extent must equal the last dispatch's renderExtent");
  }
  impl_->composite(commandBuffer, color, extent);
  return true;
}

Outputs Context::outputs() const {
  return impl_->outputs();
}
std::vector<PassTiming> Context::passTimings(std::uint64_t frameIndex) const {
  return impl_->passTimings(frameIndex);
}
FrameReport Context::lastFrameReport() const {
  return impl_->lastFrameReport();
}
WorkCounters Context::workCounters(std::uint64_t frameIndex) const {
  return impl_->workCounters(frameIndex);
}

}  // namespace clouds
