// The atmosphere model, after Hillaire 2020 ("A Scalable and Production Ready Sky and
// Atmosphere Rendering Technique", EGSR): a spherical shell of air over a planet, with
// Rayleigh and Mie scattering falling off exponentially with altitude and an ozone layer
// absorbing in a tent; single scattering of the sun with Rayleigh and Cornette-Shanks phase
// functions, planet shadow and ground bounce, and multiple scattering from a small LUT that
// treats every further order as isotropic (Hillaire's equations 5 to 10).
//
// Compiled as GLSL (float) by the module's shaders and as C++ (double) by the CPU reference:
// see atmosphere_interop.h. Positions are planet-centred, Y up, in metres; "altitude" is above
// the bottom radius. Textures are read through two prototypes each side implements:
// sampleTransmittance(uv) and sampleMultiScattering(uv), bilinear, clamped to the edges.
//
// LUT parameterisations:
//   transmittance (W x H): Bruneton's, u = distance to the top between its minimum and the
//     horizon's, v = sqrt(r^2 - bottom^2) / sqrt(top^2 - bottom^2); only directions that miss
//     the ground (the planet's shadow is applied separately).
//   multiple scattering (N x N): u = 0.5 + 0.5 * sign(m) * sqrt(|m|) with m the cosine of the
//     sun's zenith angle, so texels crowd at the terminator, where the light of the upper air
//     changes fastest through twilight (linear in m, a 32-texel LUT put 3.7 degrees between
//     texels there and the twilight sky 7 dB below a 64-texel one, atmosphere_bench);
//     v = altitude / thickness; texel centres at the ends (fromUnitToSubUv).
//   sky view (W x H, for the camera's altitude): u = sqrt of the azimuth from the sun, v = the
//     view zenith angle, non-linear so the horizon gets most texels; upper half sky, lower half
//     the ground seen through the air (its sunlit albedo included).
#ifndef ATMOSPHERE_MODEL_H
#define ATMOSPHERE_MODEL_H

#include "atmosphere_interop.h"

// The share of the sun that reaches a point of the air at `relative` (metres from the camera,
// world axes; only along aerial-perspective rays), for an includer that knows what shadows the
// air (aerial_perspective.comp: the cloud shadow map). By default nothing does.
#ifndef ATMOSPHERE_SUN_VISIBILITY
#define ATMOSPHERE_SUN_VISIBILITY(relative) real(1.0)
#endif

ATMOSPHERE_MODEL_BEGIN

const real kPi = 3.14159265358979;

// The atmosphere's parameters, in metres and per metre.
struct AtmosphereModel {
  real bottomRadius;         // the planet
  real topRadius;            // the top of the atmosphere
  vec3 rayleighScattering;   // at the ground
  real rayleighScaleHeight;  // density = exp(-altitude / scale height)
  vec3 mieScattering;        // at the ground
  vec3 mieAbsorption;        // at the ground: Mie extinction minus scattering
  real mieScaleHeight;
  real miePhaseG;        // Cornette-Shanks asymmetry
  vec3 ozoneAbsorption;  // at the tent's peak
  real ozoneCentre;      // altitude of the peak
  real ozoneHalfWidth;   // the tent falls to 0 this far above and below the peak
  vec3 groundAlbedo;     // Lambertian
};

// What the air does at one point.
struct Medium {
  vec3 rayleigh;    // Rayleigh scattering
  vec3 mie;         // Mie scattering
  vec3 scattering;  // their sum
  vec3 extinction;  // scattering and absorption (Mie, ozone)
};

FX_INLINE Medium sampleMedium(real altitude, IN(AtmosphereModel) a) {
  const real h = max(altitude, 0.0);
  const real rayleighDensity = exp(-h / a.rayleighScaleHeight);
  const real mieDensity = exp(-h / a.mieScaleHeight);
  const real fromPeak = max(h - a.ozoneCentre, a.ozoneCentre - h);
  const real ozoneDensity = max(0.0, 1.0 - fromPeak / a.ozoneHalfWidth);
  Medium m;
  m.rayleigh = a.rayleighScattering * rayleighDensity;
  m.mie = a.mieScattering * mieDensity;
  m.scattering = m.rayleigh + m.mie;
  m.extinction = m.scattering + a.mieAbsorption * mieDensity + a.ozoneAbsorption * ozoneDensity;
  return m;
}

FX_INLINE real rayleighPhase(real cosTheta) {
  return 3.0 / (16.0 * kPi) * (1.0 + cosTheta * cosTheta);
}

// Cornette-Shanks: Henyey-Greenstein's shape with Rayleigh's (1 + cos^2), normalised.
FX_INLINE real miePhase(real g, real cosTheta) {
  const real k = 3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g);
  const real denominator = 1.0 + g * g - 2.0 * g * cosTheta;
  return k * (1.0 + cosTheta * cosTheta) / (denominator * sqrt(denominator));
}

// --- Geometry ---------------------------------------------------------------------------------
// Distance along a ray from radius r, with zenith cosine mu, to the sphere of radius R: the
// first intersection ahead, or -1 when there is none. The discriminant is in its
// radius-difference form, (R - r)(R + r) + r^2 mu^2, which keeps float precision at planet
// scale (r^2 (mu^2 - 1) + R^2 cancels catastrophically).
FX_INLINE real raySphere(real r, real mu, real R) {
  const real discriminant = (R - r) * (R + r) + r * r * mu * mu;
  if (discriminant < 0.0) return -1.0;
  const real root = sqrt(discriminant);
  const real nearHit = -r * mu - root;
  const real farHit = -r * mu + root;
  if (nearHit >= 0.0) return nearHit;
  return farHit >= 0.0 ? farHit : -1.0;
}

// Whether a ray from radius r with zenith cosine mu hits the ground.
FX_INLINE bool rayHitsGround(real r, real mu, IN(AtmosphereModel) a) {
  return mu < 0.0 && (a.bottomRadius - r) * (a.bottomRadius + r) + r * r * mu * mu >= 0.0;
}

// --- Texture coordinates -----------------------------------------------------------------------
// Texel centres on a texture of `size` texels: [0, 1] to [0.5 / size, 1 - 0.5 / size] and back.
// (Hillaire's reference code maps [0, 1] with (u + 0.5 / size) * size / (size + 1), which is not
// the inverse of the second function: its lookups land up to a texel off.)
FX_INLINE real fromUnitToSubUv(real u, real size) {
  return 0.5 / size + u * ((size - 1.0) / size);
}
FX_INLINE real fromSubUvToUnit(real u, real size) {
  return (u - 0.5 / size) * (size / (size - 1.0));
}

FX_INLINE vec2 transmittanceUv(real r, real mu, IN(AtmosphereModel) a) {
  const real top = a.topRadius;
  const real bottom = a.bottomRadius;
  const real horizon = sqrt((top - bottom) * (top + bottom));  // to the top, from the ground
  const real rho = sqrt(max((r - bottom) * (r + bottom), 0.0));
  const real discriminant = (top - r) * (top + r) + r * r * mu * mu;
  const real d = max(0.0, -r * mu + sqrt(max(discriminant, 0.0)));
  const real dMin = top - r;
  const real dMax = rho + horizon;
  return vec2((d - dMin) / max(dMax - dMin, 1e-3), rho / horizon);
}

FX_INLINE void transmittanceParams(vec2 uv, IN(AtmosphereModel) a, OUT(real) r, OUT(real) mu) {
  const real top = a.topRadius;
  const real bottom = a.bottomRadius;
  const real horizon = sqrt((top - bottom) * (top + bottom));
  const real rho = horizon * uv.y;
  r = sqrt(rho * rho + bottom * bottom);
  const real dMin = top - r;
  const real dMax = rho + horizon;
  const real d = dMin + uv.x * (dMax - dMin);
  mu = d <= 0.0 ? 1.0 : (horizon * horizon - rho * rho - d * d) / (2.0 * r * d);
  mu = clamp(mu, -1.0, 1.0);
}

FX_INLINE vec2 multiScatteringUv(real r, real muSun, IN(AtmosphereModel) a, real size) {
  const real m = clamp(muSun, -1.0, 1.0);
  const real u = 0.5 + 0.5 * sign(m) * sqrt(abs(m));
  const real v = clamp((r - a.bottomRadius) / (a.topRadius - a.bottomRadius), 0.0, 1.0);
  return vec2(fromUnitToSubUv(u, size), fromUnitToSubUv(v, size));
}

// The inverse of multiScatteringUv: the altitude (m) and sun zenith cosine of a texel.
FX_INLINE void multiScatteringParams(vec2 uv, real size, IN(AtmosphereModel) a, OUT(real) altitude,
                                     OUT(real) muSun) {
  const real t = clamp(fromSubUvToUnit(uv.x, size), 0.0, 1.0) * 2.0 - 1.0;
  muSun = sign(t) * t * t;
  altitude = clamp(fromSubUvToUnit(uv.y, size), 0.0, 1.0) * (a.topRadius - a.bottomRadius);
}

// The sky-view LUT for a camera at radius r. Its v splits at the horizon, which lies `beta`
// below the level (horizonDip()): the upper half holds the sky, the lower half the directions
// that hit the ground, each with its texels crowded towards the horizon; u holds the azimuth
// from the sun, crowded towards the sun (Hillaire 2020, section 5.3). Texture coordinates of a
// view direction (its zenith cosine and the cosine of its azimuth from the sun's) and back.
FX_INLINE real horizonDip(real r, IN(AtmosphereModel) a) {
  const real toHorizon = sqrt(max((r - a.bottomRadius) * (r + a.bottomRadius), 0.0));
  return acos(clamp(toHorizon / r, -1.0, 1.0));
}

FX_INLINE vec2 skyViewUv(real viewZenithCos, real lightViewCos, real beta, vec2 size) {
  const real zenithHorizonAngle = kPi - beta;
  const real viewZenith = acos(clamp(viewZenithCos, -1.0, 1.0));
  real v;
  if (viewZenith <= zenithHorizonAngle) {
    v = (1.0 - sqrt(max(1.0 - viewZenith / zenithHorizonAngle, 0.0))) * 0.5;
  } else {
    v = sqrt(max((viewZenith - zenithHorizonAngle) / max(beta, 1e-6), 0.0)) * 0.5 + 0.5;
  }
  const real u = sqrt(clamp(-lightViewCos * 0.5 + 0.5, 0.0, 1.0));
  return vec2(fromUnitToSubUv(u, size.x), fromUnitToSubUv(v, size.y));
}

FX_INLINE void skyViewParams(vec2 uv, real beta, vec2 size, OUT(real) viewZenithCos,
                             OUT(real) lightViewCos) {
  const real u = clamp(fromSubUvToUnit(uv.x, size.x), 0.0, 1.0);
  const real v = clamp(fromSubUvToUnit(uv.y, size.y), 0.0, 1.0);
  const real zenithHorizonAngle = kPi - beta;
  if (v < 0.5) {
    const real coord = 1.0 - 2.0 * v;
    viewZenithCos = cos(zenithHorizonAngle * (1.0 - coord * coord));
  } else {
    const real coord = 2.0 * v - 1.0;
    viewZenithCos = cos(zenithHorizonAngle + beta * coord * coord);
  }
  lightViewCos = -(2.0 * u * u - 1.0);
}

// --- Texture prototypes (each side implements them) ---------------------------------------------
vec3 sampleTransmittance(vec2 uv);
vec3 sampleMultiScattering(vec2 uv);

// --- Integrals ---------------------------------------------------------------------------------
// Optical depth from radius r along zenith cosine mu to the top of the atmosphere (midpoint
// rule; the ray is assumed not to hit the ground). The transmittance LUT is exp(-this).
FX_INLINE vec3 opticalDepthToTop(real r, real mu, uint samples, IN(AtmosphereModel) a) {
  const real pathLength = max(raySphere(r, mu, a.topRadius), 0.0);
  const real dt = pathLength / real(samples);
  vec3 depth = vec3(0.0);
  for (uint i = 0u; i < samples; ++i) {
    const real t = (real(i) + 0.5) * dt;
    // Radius at distance t along the ray: sqrt(r^2 + t^2 + 2 r mu t).
    const real radius = sqrt(r * r + t * t + 2.0 * r * mu * t);
    depth += sampleMedium(radius - a.bottomRadius, a).extinction * dt;
  }
  return depth;
}

// The sun's transmittance from radius r with the sun at zenith cosine muSun, from the LUT, with
// the planet's shadow.
FX_INLINE vec3 sunTransmittance(real r, real muSun, IN(AtmosphereModel) a) {
  if (rayHitsGround(r, muSun, a)) return vec3(0.0);
  return sampleTransmittance(transmittanceUv(r, muSun, a));
}

// Radiance scattered towards a ray's origin and the transmittance along it, for a sun of unit
// illuminance, and (for the multiple-scattering LUT) f_ms: the scattering integrated as if the
// radiance arriving from every direction were 1 (Hillaire's "MultiScatAs1").
struct Scattering {
  vec3 luminance;
  vec3 transmittance;
  vec3 multiScatteringAs1;
};

const uint kPhaseIsotropic = 0u;   // the multiple-scattering LUT's second-order integral
const uint kPhaseAtmosphere = 1u;  // Rayleigh and Mie

FX_INLINE Scattering noScattering() {
  Scattering s;
  s.luminance = vec3(0.0);
  s.transmittance = vec3(1.0);
  s.multiScatteringAs1 = vec3(0.0);
  return s;
}

// Accumulates the segment [t0, t1] of the ray from `origin` along `direction` (unit) into `s`,
// with `samples` samples at segment midpoints. Each step's in-scattering is integrated
// analytically against the step's extinction (energy-conserving for any step length).
FX_INLINE void scatterAlong(INOUT(Scattering) s, vec3 origin, vec3 direction, vec3 sun, real t0,
                            real t1, uint samples, uint phaseMode, uint multipleScattering,
                            real multiScatteringSize, IN(AtmosphereModel) a) {
  if (t1 <= t0 || samples == 0u) return;
  const real cosTheta = dot(direction, sun);
  const real phaseR = rayleighPhase(cosTheta);
  const real phaseM = miePhase(a.miePhaseG, cosTheta);
  const real dt = (t1 - t0) / real(samples);
  for (uint i = 0u; i < samples; ++i) {
    const real t = t0 + (real(i) + 0.5) * dt;
    const vec3 p = origin + direction * t;
    const real radius = length(p);
    const Medium m = sampleMedium(radius - a.bottomRadius, a);
    const real muSun = dot(p, sun) / radius;
    const vec3 toSun = sunTransmittance(radius, muSun, a);
    vec3 source = phaseMode == kPhaseIsotropic ? m.scattering * (1.0 / (4.0 * kPi))
                                               : m.rayleigh * phaseR + m.mie * phaseM;
    source *= toSun * ATMOSPHERE_SUN_VISIBILITY(direction * t);
    if (multipleScattering != 0u) {
      source += m.scattering *
                sampleMultiScattering(multiScatteringUv(radius, muSun, a, multiScatteringSize));
    }
    const vec3 extinction = max(m.extinction, vec3(1e-12));
    const vec3 stepTransmittance = exp(-m.extinction * dt);
    const vec3 absorbed = (vec3(1.0) - stepTransmittance) / extinction;
    s.luminance += s.transmittance * source * absorbed;
    s.multiScatteringAs1 += s.transmittance * m.scattering * absorbed;
    s.transmittance *= stepTransmittance;
  }
}

// The whole ray inside the atmosphere, from `origin` (planet-centred, inside or above it), up
// to `maxDistance`, the ground or the top; with `ground`, the sunlit ground it ends on bounces
// its light back (Lambertian).
FX_INLINE Scattering integrateScattering(vec3 origin, vec3 direction, vec3 sun, real maxDistance,
                                         uint samples, uint phaseMode, uint multipleScattering,
                                         real multiScatteringSize, uint ground,
                                         IN(AtmosphereModel) a) {
  Scattering s = noScattering();
  real r = length(origin);
  real mu = dot(origin, direction) / r;
  real start = 0.0;
  if (r > a.topRadius) {
    // Above the atmosphere: start where the ray enters it, if it does.
    const real entry = raySphere(r, mu, a.topRadius);
    if (entry < 0.0) return s;
    start = entry;
    origin += direction * entry;
    r = length(origin);
    mu = dot(origin, direction) / r;
  }
  const real toGround = rayHitsGround(r, mu, a) ? raySphere(r, mu, a.bottomRadius) : -1.0;
  const real toTop = max(raySphere(r, mu, a.topRadius), 0.0);
  const real end = min(toGround >= 0.0 ? toGround : toTop, max(maxDistance - start, 0.0));
  scatterAlong(s, origin, direction, sun, 0.0, end, samples, phaseMode, multipleScattering,
               multiScatteringSize, a);
  if (ground != 0u && toGround >= 0.0 && end >= toGround) {
    const vec3 p = origin + direction * toGround;
    const real muSun = dot(p, sun) / length(p);
    const vec3 toSun = sunTransmittance(a.bottomRadius, muSun, a);
    s.luminance += s.transmittance * toSun * max(muSun, 0.0) * a.groundAlbedo / kPi;
  }
  return s;
}

// Sky-view LUT direction for its parameters: Y up at the camera, the sun in the XY plane.
FX_INLINE vec3 skyViewDirection(real viewZenithCos, real lightViewCos) {
  const real viewZenithSin = sqrt(max(1.0 - viewZenithCos * viewZenithCos, 0.0));
  const real lightViewSin = sqrt(max(1.0 - lightViewCos * lightViewCos, 0.0));
  return vec3(viewZenithSin * lightViewCos, viewZenithCos, viewZenithSin * lightViewSin);
}

FX_INLINE vec3 sunInSkyViewFrame(real sunZenithCos) {
  return vec3(sqrt(max(1.0 - sunZenithCos * sunZenithCos, 0.0)), sunZenithCos, 0.0);
}

// The cosine of a world direction's azimuth from the sun's (the planet's up is +Y at the
// camera); 1 when either is vertical.
FX_INLINE real azimuthCosineFromSun(vec3 direction, vec3 sun) {
  const vec2 d = vec2(direction.x, direction.z);
  const vec2 s = vec2(sun.x, sun.z);
  const real lengths = length(d) * length(s);
  return lengths > 1e-6 ? clamp(dot(d, s) / lengths, -1.0, 1.0) : 1.0;
}

// The multiple-scattering LUT's value at `uv` (Hillaire 2020, section 5.5): for the altitude
// and sun zenith angle of that texel, the luminance of every scattering order past the first,
// assuming each further order isotropic. Over a uniform grid of `directions` x `directions`
// directions on the sphere it averages the second order L2 (single scattering with the
// isotropic phase, the sunlit ground bouncing) and f_ms, the fraction the air around re-scatters;
// Psi = L2 / (1 - f_ms) sums the geometric series of all orders.
FX_INLINE vec3 multipleScatteringTexel(vec2 uv, real size, uint directions, uint samples,
                                       IN(AtmosphereModel) a) {
  real altitude = 0.0;
  real muSun = 0.0;
  multiScatteringParams(uv, size, a, altitude, muSun);
  // A little above the ground, so that rays along the horizon do not start inside it.
  const vec3 origin = vec3(0.0, a.bottomRadius + max(altitude, 1.0), 0.0);
  const vec3 sun = sunInSkyViewFrame(muSun);
  vec3 secondOrder = vec3(0.0);
  vec3 fractionRescattered = vec3(0.0);
  for (uint i = 0u; i < directions; ++i) {
    for (uint j = 0u; j < directions; ++j) {
      // Azimuth and cos(polar angle) in equal steps: equal solid angles.
      const real azimuth = 2.0 * kPi * (real(i) + 0.5) / real(directions);
      const real cosPolar = 1.0 - 2.0 * (real(j) + 0.5) / real(directions);
      const real sinPolar = sqrt(max(1.0 - cosPolar * cosPolar, 0.0));
      const vec3 direction = vec3(cos(azimuth) * sinPolar, cosPolar, sin(azimuth) * sinPolar);
      const Scattering s = integrateScattering(origin, direction, sun, 1e9, samples,
                                               kPhaseIsotropic, 0u, size, 1u, a);
      secondOrder += s.luminance;
      fractionRescattered += s.multiScatteringAs1;
    }
  }
  // Means over directions: integrals over the sphere times the isotropic phase 1 / (4 pi).
  const real count = real(directions * directions);
  secondOrder /= count;
  fractionRescattered /= count;
  return secondOrder / max(vec3(1.0) - fractionRescattered, vec3(1e-4));
}

// --- The sun disc ------------------------------------------------------------------------------
// Radiance of the sun's disc seen from the top of the atmosphere, for a sun of unit
// illuminance, at a direction `versine` = 1 - cos(angle from its centre) from it, for a disc of
// `radiusVersine` = 1 - cos(angular radius); 0 outside. Versines keep float precision where
// cosines of such small angles round to 1: for unit vectors a and b, 1 - dot(a, b) is exactly
// dot(a - b, a - b) / 2. Limb darkening after Neckel & Labs' linear law with coefficient 0.6,
// normalised so the disc integrates to 1; the distance from the centre in disc radii is
// sqrt(versine / radiusVersine), exact to (angular radius)^2 / 12.
FX_INLINE real sunDiscRadiance(real versine, real radiusVersine) {
  if (versine > radiusVersine) return 0.0;
  const real solidAngle = 2.0 * kPi * radiusVersine;
  const real mu = sqrt(max(1.0 - versine / radiusVersine, 0.0));
  const real darkening = 1.0 - 0.6 * (1.0 - mu);
  return darkening / (solidAngle * (1.0 - 0.6 / 3.0));
}

ATMOSPHERE_MODEL_END

#endif
