#pragma once
// Exact equality of parameters and settings: what decides whether prepare() has work to do.
#include <tuple>

#include "atmosphere/atmosphere.h"

namespace atmosphere::detail {

inline auto fieldsOf(const Parameters& p) {
  return std::tie(p.bottomRadiusMetres, p.topRadiusMetres, p.rayleighScatteringPerMetre,
                  p.rayleighScaleHeightMetres, p.mieScatteringPerMetre, p.mieExtinctionPerMetre,
                  p.mieScaleHeightMetres, p.miePhaseG, p.ozoneAbsorptionPerMetre,
                  p.ozoneCentreMetres, p.ozoneHalfWidthMetres, p.groundAlbedo,
                  p.sunAngularRadiusRadians);
}

inline auto fieldsOf(const Settings& s) {
  return std::tie(s.transmittanceWidth, s.transmittanceHeight, s.transmittanceSamples,
                  s.multiScatteringSize, s.multiScatteringDirections, s.multiScatteringSamples,
                  s.skyViewWidth, s.skyViewHeight, s.skyViewSamples, s.skyViewAltitudeTolerance,
                  s.aerialPerspectiveWidth, s.aerialPerspectiveHeight, s.aerialPerspectiveSlices,
                  s.aerialPerspectiveSamplesPerSlice, s.aerialPerspectiveRangeMetres);
}

inline bool same(const Parameters& a, const Parameters& b) {
  return fieldsOf(a) == fieldsOf(b);
}
inline bool same(const Settings& a, const Settings& b) {
  return fieldsOf(a) == fieldsOf(b);
}

// Whether the LUTs that depend only on the parameters must be recorded again for `next`.
inline bool parameterLutsChange(const Settings& previous, const Settings& next) {
  return std::tie(previous.transmittanceWidth, previous.transmittanceHeight,
                  previous.transmittanceSamples, previous.multiScatteringSize,
                  previous.multiScatteringDirections, previous.multiScatteringSamples) !=
         std::tie(next.transmittanceWidth, next.transmittanceHeight, next.transmittanceSamples,
                  next.multiScatteringSize, next.multiScatteringDirections,
                  next.multiScatteringSamples);
}

}  // namespace atmosphere::detail
