// atmosphere::Context::Impl: creation, prepare(), images and reports. Recording is in
// record.cpp.
#include "context_impl.h"

#include <algorithm>
#include <map>
#include <vector>

#include "equality.h"

namespace atmosphere {

using detail::Program;

namespace {

constexpr VkFormat kLutFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkSamplerAddressMode kClamp = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;

const detail::DeviceContext& checkedDevice(const detail::DeviceContext& device) {
  if (!device.supportsStorage(kLutFormat)) {
    throw vkfx::Error(vkfx::Failure::Unsupported,
                      "the device cannot use RGBA16F as a storage image");
  }
  return device;
}

// Exactly the sets the context allocates: per frame slot one for each program and, when the host
// asked for the sky's draw, one for it; the descriptors are the programs' bindings.
detail::UniqueDescriptorPool makePool(const detail::DeviceContext& device,
                                      const detail::Programs& programs, bool skyDraw,
                                      std::uint32_t frames) {
  std::map<VkDescriptorType, std::uint32_t> descriptors;
  std::uint32_t sets = 0;
  for (std::size_t p = 0; p < static_cast<std::size_t>(detail::Program::Count); ++p) {
    ++sets;
    for (const vkfx::Binding& binding : programs[detail::Program(p)].bindings()) {
      ++descriptors[binding.type];
    }
  }
  if (skyDraw) {
    ++sets;
    for (const auto& binding : detail::SkyDraw::kBindings) ++descriptors[binding.type];
  }
  std::vector<VkDescriptorPoolSize> sizes;
  for (const auto& [type, count] : descriptors) sizes.push_back({type, count * frames});
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = sets * frames;
  info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  info.pPoolSizes = sizes.data();
  return device.createDescriptorPool(info, "descriptor pool");
}

VkExtent3D extent2(std::uint32_t w, std::uint32_t h) {
  return {w, h, 1};
}

}  // namespace

Context::Impl::Impl(const CreateInfo& info, const detail::VulkanFunctions& functions)
    : info_(info),
      device_(info.device, info.physicalDevice, info.debugUtils, functions, "atmosphere"),
      programs_(checkedDevice(device_), info.reversedZ),
      linearSampler_(device_.createSampler(VK_FILTER_LINEAR, kClamp, "linear sampler")),
      nearestSampler_(device_.createSampler(VK_FILTER_NEAREST, kClamp, "nearest sampler")),
      pool_(makePool(device_, programs_, info.skyPassColorFormat != VK_FORMAT_UNDEFINED,
                     info.maxFramesInFlight)) {
  if (info.skyPassColorFormat != VK_FORMAT_UNDEFINED) {
    skyDraw_ = std::make_unique<detail::SkyDraw>(device_, info.skyPassColorFormat, info.depthFormat,
                                                 info.reversedZ);
  }
  if (info.passTimings) {
    timer_ =
        std::make_unique<detail::PassTimer>(device_, info.maxFramesInFlight, detail::kPassNames);
  }
  environment_ =
      makeImage(VK_IMAGE_TYPE_2D, extent2(shader::kEnvironmentWidth, shader::kEnvironmentHeight),
                "environment");
  depthPlaceholder_ = detail::OwnedImage(device_, VK_IMAGE_TYPE_2D, VK_FORMAT_R32_SFLOAT, {1, 1, 1},
                                         VK_IMAGE_USAGE_SAMPLED_BIT, "no host depth");
  pendingLayouts_.push_back(depthPlaceholder_.image());
  slots_.resize(info.maxFramesInFlight);
  for (std::uint32_t i = 0; i < info.maxFramesInFlight; ++i) {
    Slot& slot = slots_[i];
    slot.uniforms =
        detail::OwnedBuffer(device_, sizeof(shader::AtmosphereUniforms),
                            VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            "uniforms " + std::to_string(i));
    slot.cloudShadow =
        detail::OwnedBuffer(device_, sizeof(FrameInputs::CloudShadow::parameters),
                            VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            "cloud shadow parameters " + std::to_string(i));
    slot.lighting = detail::OwnedBuffer(device_, sizeof(shader::SkyLighting),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                        "sky lighting " + std::to_string(i), /*hostVisible=*/true);
    for (std::size_t p = 0; p < kPrograms; ++p) {
      slot.sets[p] = allocateSet(programs_[Program(p)].setLayout());
    }
    if (skyDraw_) slot.skyDrawSet = allocateSet(skyDraw_->setLayout());
  }
}

VkDescriptorSet Context::Impl::allocateSet(VkDescriptorSetLayout layout) {
  VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  info.descriptorPool = pool_.get();
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  detail::check(device_.fn().vkAllocateDescriptorSets(device_.device(), &info, &set),
                "vkAllocateDescriptorSets");
  return set;
}

detail::OwnedImage Context::Impl::makeImage(VkImageType type, VkExtent3D extent,
                                            const std::string& name) {
  // Sampled by later passes and by hosts; read back by the module's tests.
  const VkImageUsageFlags usage =
      VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  detail::OwnedImage image(device_, type, kLutFormat, extent, usage, name);
  pendingLayouts_.push_back(image.image());
  return image;
}

void Context::Impl::replace(detail::OwnedImage& slot, detail::OwnedImage replacement) {
  if (slot) {
    const VkImage old = slot.image();
    std::erase(pendingLayouts_, old);
    retired_.push_back({std::move(slot), lastFrameIndex_});
  }
  slot = std::move(replacement);
}

void Context::Impl::releaseRetired(std::uint64_t frameIndex) {
  std::erase_if(retired_, [&](const Retired& r) {
    return !r.lastUse || frameIndex >= *r.lastUse + info_.maxFramesInFlight;
  });
}

void Context::Impl::prepare(const Parameters& parameters, const Settings& s) {
  const bool first = !sizedFor_.has_value();
  const Settings old = sizedFor_.value_or(Settings{});
  if (first || old.transmittanceWidth != s.transmittanceWidth ||
      old.transmittanceHeight != s.transmittanceHeight) {
    replace(transmittance_,
            makeImage(VK_IMAGE_TYPE_2D, extent2(s.transmittanceWidth, s.transmittanceHeight),
                      "transmittance LUT"));
  }
  if (first || old.multiScatteringSize != s.multiScatteringSize) {
    replace(multiScattering_,
            makeImage(VK_IMAGE_TYPE_2D, extent2(s.multiScatteringSize, s.multiScatteringSize),
                      "multiple-scattering LUT"));
  }
  if (first || old.skyViewWidth != s.skyViewWidth || old.skyViewHeight != s.skyViewHeight) {
    replace(skyView_,
            makeImage(VK_IMAGE_TYPE_2D, extent2(s.skyViewWidth, s.skyViewHeight), "sky-view LUT"));
    skyViewBuild_.reset();
  }
  if (first || old.aerialPerspectiveWidth != s.aerialPerspectiveWidth ||
      old.aerialPerspectiveHeight != s.aerialPerspectiveHeight ||
      old.aerialPerspectiveSlices != s.aerialPerspectiveSlices) {
    replace(aerialPerspective_, makeImage(VK_IMAGE_TYPE_3D,
                                          {s.aerialPerspectiveWidth, s.aerialPerspectiveHeight,
                                           s.aerialPerspectiveSlices},
                                          "aerial perspective"));
  }
  if (first || detail::parameterLutsChange(old, s) || !preparedFor_ ||
      !detail::same(*preparedFor_, parameters)) {
    lutsDirty_ = true;
  }
  // The sky-view LUT is made from the other two, with its own samples: rebuilt with either.
  if (lutsDirty_ || old.skyViewSamples != s.skyViewSamples) skyViewBuild_.reset();
  sizedFor_ = s;
  preparedFor_ = parameters;
  // Images no frame has used yet can go now.
  releaseRetired(lastFrameIndex_.value_or(0));
}

std::string Context::Impl::unprepared(const Parameters& parameters,
                                      const Settings& settings) const {
  if (!sizedFor_ || !detail::same(*sizedFor_, settings)) {
    return "the images and LUT recipe of these settings";
  }
  if (!preparedFor_ || !detail::same(*preparedFor_, parameters)) {
    return "the LUTs of these parameters";
  }
  return {};
}

Outputs Context::Impl::outputs() const {
  const auto out = [](const detail::OwnedImage& image) {
    return OutputImage{image.image(), image.view(), image.format(), image.extent()};
  };
  Outputs o;
  o.transmittance = out(transmittance_);
  o.multipleScattering = out(multiScattering_);
  o.skyView = out(skyView_);
  o.aerialPerspective = out(aerialPerspective_);
  o.aerialPerspectiveRangeMetres = sizedFor_ ? sizedFor_->aerialPerspectiveRangeMetres : 0.0f;
  o.environment = out(environment_);
  return o;
}

SkyLighting Context::Impl::skyLighting(std::uint64_t frameIndex) const {
  const Slot& slot = slots_[frameIndex % slots_.size()];
  SkyLighting lighting;
  if (slot.lightingFrame != frameIndex) return lighting;
  const auto* measured = static_cast<const shader::SkyLighting*>(slot.lighting.mapped());
  lighting.meanUpper = glm::vec3(measured->meanUpper);
  lighting.meanUpperLuminance = measured->meanUpper.w;
  lighting.zenith = glm::vec3(measured->zenith);
  lighting.horizon = glm::vec3(measured->horizon);
  lighting.lower = glm::vec3(measured->lower);
  lighting.valid = true;
  return lighting;
}

MemoryUsage Context::Impl::memoryUsage() const {
  MemoryUsage m;
  m.lutBytes = transmittance_.bytes() + multiScattering_.bytes() + skyView_.bytes();
  m.volumeBytes = aerialPerspective_.bytes();
  m.otherBytes = environment_.bytes() + depthPlaceholder_.bytes();
  for (const Slot& slot : slots_) m.otherBytes += slot.uniforms.bytes() + slot.lighting.bytes();
  for (const Retired& r : retired_) m.otherBytes += r.image.bytes();
  return m;
}

std::vector<PassTiming> Context::Impl::passTimings(std::uint64_t frameIndex) const {
  std::vector<PassTiming> timings;
  if (!timer_) return timings;
  for (const vkfx::PassTime& t :
       timer_->read(static_cast<std::uint32_t>(frameIndex % slots_.size()))) {
    timings.push_back(PassTiming{t.name, t.milliseconds});
  }
  return timings;
}

}  // namespace atmosphere
