#include "uniforms.h"

#include <algorithm>
#include <cmath>

#include "atmosphere_model.h"
#include "model_from_parameters.h"

namespace atmosphere::detail {

shader::AtmosphereUniforms buildUniforms(const FrameInputs& in, const Parameters& p,
                                         const Settings& s, bool reversedZ) {
  shader::AtmosphereUniforms u{};
  u.inverseProjection = glm::inverse(in.projection);
  // The view's rotation only: view -> world for directions.
  u.viewToWorld = glm::mat4(glm::transpose(glm::mat3(in.view)));
  u.clipToWorldRay = u.viewToWorld * u.inverseProjection;

  u.rayleighScattering = p.rayleighScatteringPerMetre;
  u.rayleighScaleHeight = p.rayleighScaleHeightMetres;
  u.mieScattering = p.mieScatteringPerMetre;
  u.mieScaleHeight = p.mieScaleHeightMetres;
  u.mieAbsorption = p.mieExtinctionPerMetre - p.mieScatteringPerMetre;
  u.miePhaseG = p.miePhaseG;
  u.ozoneAbsorption = p.ozoneAbsorptionPerMetre;
  u.ozoneCentre = p.ozoneCentreMetres;
  u.groundAlbedo = p.groundAlbedo;
  u.ozoneHalfWidth = p.ozoneHalfWidthMetres;
  u.bottomRadius = p.bottomRadiusMetres;
  u.topRadius = p.topRadiusMetres;
  // At least a metre above the ground: a camera on or below it would see the sky-view LUT's
  // horizon collapse.
  u.cameraRadius =
      static_cast<float>(double(p.bottomRadiusMetres) + std::max(in.cameraPosition.y, 1.0));
  u.sunAngularRadius = p.sunAngularRadiusRadians;
  // 2 sin^2(r / 2): 1 - cos(r) without the cancellation of cosines near 1.
  const double halfRadiusSine = std::sin(0.5 * double(p.sunAngularRadiusRadians));
  u.sunRadiusVersine = static_cast<float>(2.0 * halfRadiusSine * halfRadiusSine);
  const float sunLength = glm::length(in.sunDirection);
  u.sunDirection = sunLength > 1e-6f ? in.sunDirection / sunLength : glm::vec3(0, 1, 0);
  u.sunIlluminance = in.sunIlluminance;
  // The disc is small enough to be seen through one transmittance, its centre's.
  u.sunDiscIlluminance =
      in.sunIlluminance * sunTransmittance(p, double(u.cameraRadius) - double(p.bottomRadiusMetres),
                                           glm::dvec3(u.sunDirection));
  u.maxRadiance = kMaxRadiance;

  u.transmittanceSize = glm::uvec2(s.transmittanceWidth, s.transmittanceHeight);
  u.transmittanceSamples = s.transmittanceSamples;
  u.multiScatteringSize = s.multiScatteringSize;
  u.multiScatteringDirections = s.multiScatteringDirections;
  u.multiScatteringSamples = s.multiScatteringSamples;
  u.skyViewSize = glm::uvec2(s.skyViewWidth, s.skyViewHeight);
  u.skyViewSamples = s.skyViewSamples;
  u.flags = reversedZ ? shader::kFlagReversedZ : 0u;
  if (in.cloudShadow.view != VK_NULL_HANDLE) u.flags |= shader::kFlagCloudShadow;
  u.outputExtent = glm::uvec2(in.renderExtent.width, in.renderExtent.height);
  u.aerialPerspectiveSize =
      glm::uvec4(s.aerialPerspectiveWidth, s.aerialPerspectiveHeight, s.aerialPerspectiveSlices,
                 s.aerialPerspectiveSamplesPerSlice);
  u.aerialPerspectiveRange = s.aerialPerspectiveRangeMetres;
  // In double, once: the sky-view LUT is built and read with the same horizon.
  u.horizonDip =
      static_cast<float>(model::horizonDip(double(u.cameraRadius), detail::modelFrom(p)));
  return u;
}

}  // namespace atmosphere::detail
