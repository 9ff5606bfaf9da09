#pragma once
// The model (atmosphere_model.h, double precision) and the GPU uniforms' model fields, from the
// public Parameters: one conversion, used by the CPU transmittance, the reference and the
// uniforms.
#include "atmosphere/atmosphere.h"
#include "atmosphere_model.h"

namespace atmosphere::detail {

inline model::AtmosphereModel modelFrom(const Parameters& p) {
  model::AtmosphereModel a;
  a.bottomRadius = p.bottomRadiusMetres;
  a.topRadius = p.topRadiusMetres;
  a.rayleighScattering = glm::dvec3(p.rayleighScatteringPerMetre);
  a.rayleighScaleHeight = p.rayleighScaleHeightMetres;
  a.mieScattering = glm::dvec3(p.mieScatteringPerMetre);
  a.mieAbsorption = glm::dvec3(p.mieExtinctionPerMetre) - glm::dvec3(p.mieScatteringPerMetre);
  a.mieScaleHeight = p.mieScaleHeightMetres;
  a.miePhaseG = p.miePhaseG;
  a.ozoneAbsorption = glm::dvec3(p.ozoneAbsorptionPerMetre);
  a.ozoneCentre = p.ozoneCentreMetres;
  a.ozoneHalfWidth = p.ozoneHalfWidthMetres;
  a.groundAlbedo = glm::dvec3(p.groundAlbedo);
  return a;
}

}  // namespace atmosphere::detail
