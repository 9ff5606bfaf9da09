// Recording the module's textures: the noise generation of the first frame, the weather map
// (procedural, prepared a band of rows per frame ahead of its period, or the host's painted
// one resampled) and its maxima for empty-space skipping.
#include <algorithm>
#include <cmath>

#include "context_impl.h"

namespace clouds {

using detail::Program;

namespace {

using detail::kStorageRead;
using detail::kStorageWrite;
constexpr VkPipelineStageFlags2 kCompute = detail::kComputeStage;

}  // namespace

void Context::Impl::recordNoise(VkCommandBuffer cmd) {
  const auto& fn = device_.fn();
  beginPass(cmd, detail::Pass::Noise, "clouds: noise generation");
  struct Job {
    Program program;
    VkDescriptorSet set;
    std::uint32_t size;
    bool volume;
  };
  const Job jobs[] = {
      {Program::ShapeNoise, shapeSet_, static_cast<std::uint32_t>(shader::kShapeNoiseSize), true},
      {Program::DetailNoise, detailSet_, static_cast<std::uint32_t>(shader::kDetailNoiseSize),
       true},
      {Program::CurlNoise, curlSet_, static_cast<std::uint32_t>(shader::kCurlNoiseSize), false},
  };
  for (const Job& job : jobs) {
    const detail::ComputeProgram& program = programs_[job.program];
    fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.find());
    fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1,
                               &job.set, 0, nullptr);
    shader::NoiseConstants constants{};
    constants.seed = info_.noiseSeed;
    constants.size = job.size;
    fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                          &constants);
    if (job.volume) {
      const std::uint32_t n = detail::groupsFor(job.size, shader::kWorkgroupSize3D);
      fn.vkCmdDispatch(cmd, n, n, n);
    } else {
      const std::uint32_t n = detail::groupsFor(job.size, shader::kWorkgroupSize2D);
      fn.vkCmdDispatch(cmd, n, n, 1);
    }
  }
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  recordNoiseMipChains(cmd);
  endPass(cmd, detail::Pass::Noise);
  noiseGenerated_ = true;
}

void Context::Impl::recordNoiseMipChains(VkCommandBuffer cmd) {
  const auto& fn = device_.fn();
  const detail::ComputeProgram& program = programs_[Program::NoiseMip];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.find());
  struct Chain {
    VkDescriptorSet set;
    int size;
    int levels;
  };
  const Chain chains[] = {{shapeMipSet_, shader::kShapeNoiseSize, shader::kShapeNoiseLevels},
                          {detailMipSet_, shader::kDetailNoiseSize, shader::kDetailNoiseLevels}};
  const auto dispatch = [&](const Chain& chain, std::uint32_t level, std::uint32_t parity,
                            std::uint32_t width, std::uint32_t depth) {
    fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), 0, 1,
                               &chain.set, 0, nullptr);
    const shader::NoiseMipConstants constants{static_cast<std::uint32_t>(chain.size), level, parity,
                                              0u};
    fn.vkCmdPushConstants(cmd, program.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                          &constants);
    const std::uint32_t groups = detail::groupsFor(width, shader::kWorkgroupSize3D);
    fn.vkCmdDispatch(cmd, groups, groups, detail::groupsFor(depth, shader::kWorkgroupSize3D));
  };
  // Level 0 packed in four passes, by the parity of x and y (no pass reads what it writes).
  for (std::uint32_t parity = 0; parity < 4; ++parity) {
    for (const Chain& chain : chains) {
      const auto n = static_cast<std::uint32_t>(chain.size);
      dispatch(chain, 0u, parity, n / 2, n);
    }
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite | kStorageRead, kCompute,
                          kStorageRead | kStorageWrite);
  }
  // Then level by level, each from the one below: both chains' level L, then a barrier.
  for (int level = 1; level < std::max(shader::kShapeNoiseLevels, shader::kDetailNoiseLevels);
       ++level) {
    for (const Chain& chain : chains) {
      if (level >= chain.levels) continue;
      const auto n = static_cast<std::uint32_t>(chain.size >> level);
      dispatch(chain, static_cast<std::uint32_t>(level), 0u, n, n);
    }
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  }
}

void Context::Impl::recordWeather(VkCommandBuffer cmd, const FrameInputs& inputs,
                                  const Settings& settings, Slot& slot) {
  if (inputs.weatherView != VK_NULL_HANDLE) {
    const auto& fn = device_.fn();
    const std::uint32_t n = detail::groupsFor(static_cast<std::uint32_t>(shader::kWeatherMapSize),
                                              shader::kWorkgroupSize2D);
    // A painted map: resampled every frame (the host may repaint it at any time), blended
    // towards a second one when the host asks.
    const bool blending = inputs.weatherBlendView != VK_NULL_HANDLE;
    const shader::ResampleConstants constants{blending ? inputs.weatherBlend : 0.0f, 0u, 0u, 0u};
    beginPass(cmd, detail::Pass::Weather, "clouds: weather resample");
    detail::SetWriter(device_, slot.weatherResample)
        .storageImage(shader::kResampleTarget, weatherMap().view())
        .sampledImage(shader::kResampleSource, inputs.weatherView, linearSampler_.get(),
                      inputs.weatherLayout)
        .sampledImage(shader::kResampleBlendSource,
                      blending ? inputs.weatherBlendView : inputs.weatherView, linearSampler_.get(),
                      blending ? inputs.weatherBlendLayout : inputs.weatherLayout)
        .commit();
    detail::memoryBarrier(device_, cmd, kCompute, kStorageRead, kCompute, kStorageWrite);
    const detail::ComputeProgram& resample = programs_[Program::WeatherResample];
    fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resample.find());
    fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resample.layout(), 0, 1,
                               &slot.weatherResample, 0, nullptr);
    fn.vkCmdPushConstants(cmd, resample.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                          &constants);
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
  constants.evolutionPhase = static_cast<float>(phase - std::floor(phase));
  constants.seed = info_.noiseSeed;
  constants.firstRow = work.firstRow;
  const std::uint32_t spare = currentWeather_ ^ 1u;
  // The spare map may still be read by earlier frames' marches.
  detail::memoryBarrier(device_, cmd, kCompute, kStorageRead, kCompute, kStorageWrite);
  const detail::ComputeProgram& generator = programs_[Program::Weather];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, generator.find());
  fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, generator.layout(), 0, 1,
                             &weatherSets_[spare], 0, nullptr);
  fn.vkCmdPushConstants(cmd, generator.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(constants),
                        &constants);
  const auto width = static_cast<std::uint32_t>(shader::kWeatherMapSize);
  fn.vkCmdDispatch(cmd, detail::groupsFor(width, shader::kWorkgroupSize2D),
                   detail::groupsFor(work.endRow - work.firstRow, shader::kWorkgroupSize2D), 1);
  detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
}

void Context::Impl::recordWeatherMaxima(VkCommandBuffer cmd) {
  const auto& fn = device_.fn();
  const auto weather = static_cast<std::uint32_t>(shader::kWeatherMapSize);
  const auto fine = static_cast<std::uint32_t>(shader::kWeatherMaxFineSize);
  const auto coarse = static_cast<std::uint32_t>(shader::kWeatherMaxCoarseSize);
  const detail::ComputeProgram& maxima = programs_[Program::WeatherMaxima];
  fn.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, maxima.find());
  const struct {
    VkDescriptorSet set;
    shader::MaximaConstants constants;
  } levels[] = {{weatherMaxFineSets_[currentWeather_], {weather, weather / fine, fine, 0u}},
                {weatherMaxCoarseSet_, {fine, fine / coarse, coarse, 0u}}};
  for (const auto& level : levels) {
    fn.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, maxima.layout(), 0, 1,
                               &level.set, 0, nullptr);
    fn.vkCmdPushConstants(cmd, maxima.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                          sizeof(level.constants), &level.constants);
    const std::uint32_t n = detail::groupsFor(level.constants.targetSize, shader::kWorkgroupSize2D);
    fn.vkCmdDispatch(cmd, n, n, 1);
    detail::memoryBarrier(device_, cmd, kCompute, kStorageWrite, kCompute, kStorageRead);
  }
}

}  // namespace clouds
