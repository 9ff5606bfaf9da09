#pragma once
// The atmosphere's CPU reference: the module's model (shaders/atmosphere_model.h) compiled as
// C++ in double precision, building the same LUTs the GPU builds, from the same recipe, and
// integrating the sky directly. Ground truth for the module's tests (GPU against CPU) and a
// converged reference for the benchmark.
#include <cstdint>
#include <vector>

#include "atmosphere/atmosphere.h"
#include "atmosphere_model.h"

namespace atmosphere::reference {

// A 2D table of RGB values sampled like the GPU's textures: bilinear, clamped to the edges,
// texel centres at (i + 0.5) / size.
struct Lut {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<glm::dvec3> texels;  // row-major
  glm::dvec3 sample(glm::dvec2 uv) const;
  const glm::dvec3& at(std::uint32_t x, std::uint32_t y) const { return texels[y * width + x]; }
};

class Reference {
 public:
  // Builds the transmittance and multiple-scattering LUTs of `settings` (sizes and samples).
  Reference(const Parameters& parameters, const Settings& settings);

  const model::AtmosphereModel& model() const { return model_; }
  const Lut& transmittance() const { return transmittance_; }
  const Lut& multiScattering() const { return multiScattering_; }
  // Makes the model's texture prototypes (sampleTransmittance, sampleMultiScattering) read this
  // reference's LUTs on the calling thread, for calling atmosphere_model.h's integrals directly.
  void bindToThisThread() const;
  // The sky-view LUT for a camera at `altitudeMetres` with the sun at `sunZenithCos`.
  Lut skyView(double altitudeMetres, double sunZenithCos) const;
  // Radiance towards a camera at `altitudeMetres` from world direction `direction` (unit sun
  // illuminance): single scattering plus the multiple-scattering LUT, with `samples` samples,
  // up to `maxDistance` (the aerial perspective) or the end of the air; with `ground`, plus the
  // sunlit ground the ray ends on (the module's sky below the horizon).
  model::Scattering scattering(double altitudeMetres, glm::dvec3 direction, glm::dvec3 sun,
                               std::uint32_t samples, double maxDistance = 1e12,
                               bool ground = false) const;

 private:
  model::AtmosphereModel model_;
  Settings settings_;
  Lut transmittance_;
  Lut multiScattering_;
};

}  // namespace atmosphere::reference
