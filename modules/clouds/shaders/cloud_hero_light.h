// How hero clouds shadow themselves (Settings::heroLight): the optical depth towards the sun
// through a hero cloud's own voxels, from a sample in its box. Shared by the march, the light
// volume's sweep (hero_light_volume.comp) and the CPU reference.
//
// The light volume (Schneider 2023, Nubis³: "calculate and store summed density" towards the
// sun, which gave the voxel clouds their long-distance self-shadowing and cut their render time
// by 40%) holds, per instance, that optical depth on a grid kHeroLightTexelVoxels voxels apart
// over the instance's box. It is swept slice by slice along the axis of the cloud's index space
// nearest the sun, from the sun's side: each texel takes the already swept slice one step
// sunwards, at the point where the texel's sun ray crosses it (bilinearly), and adds the
// integral of the fields between (Simpson's rule). So a refresh costs a few lookups per texel,
// not a march per texel; and a sample does the same from wherever it lies. Stored in voxel units
// (the integral of heroLightIntegrand() along voxel lengths), so that the instance's
// size, density, fade and the extinction scale it at the lookup and do not call for a new sweep;
// the sun, the asset and the cloud's life do.
#ifndef CLOUDS_CLOUD_HERO_LIGHT_H
#define CLOUDS_CLOUD_HERO_LIGHT_H

#include "cloud_hero.h"

FX_SHADER_BEGIN(clouds::shader)

// The includer's: a texel of the light volume (R16F: optical depth in voxel units), absolute in
// the volume (its slots lie in a 2 x 2 x 2 grid, each as large as the largest asset's light
// grid).
float fetchHeroLight(ivec3 texel);

// The straight integral's step (kHeroLightMarched), in voxels: the fields are trilinear within a
// voxel, so two midpoint samples per voxel leave an error well under the volume's.
const float kHeroLightMarchedStepVoxels = 0.5f;
const int kHeroLightMarchedMaxSteps = 4096;

// The light grid of an instance: texel j's centre lies at index coordinate j x
// kHeroLightTexelVoxels - 1, so the grid covers the box [-1, extent] the fields reach.
FX_INLINE ivec3 heroLightSize(IN(HeroCloudInstance) h) {
  return ivec3(ceil((vec3(h.extent) + 1.0f) / kHeroLightTexelVoxels)) + 1;
}

// The first texel of instance `index`'s slot in the light volume: slot s lies at (s & 1,
// s >> 1 & 1, s >> 2) slot extents, the extent packed in the header's z (heroLightSlotExtent()).
FX_INLINE ivec3 heroLightSlotOrigin(uint index) {
  const uvec4 header = heroCloudHeader();
  const uint slotMask = (1u << kHeroLightSlotBits) - 1u;
  const uint slot = (header.y >> (kHeroLightSlotBits * index)) & slotMask;
  const uvec3 extent = uvec3(header.z & 1023u, (header.z >> 10u) & 1023u, header.z >> 20u);
  return ivec3(uvec3(slot & 1u, (slot >> 1u) & 1u, slot >> 2u) * extent);
}

// The unit direction towards the sun in an instance's index space (voxels).
FX_INLINE vec3 heroSunIndexDirection(IN(HeroCloudInstance) h, vec3 sunDirection) {
  const vec3 d = vec3(dot(vec3(h.toIndex[0]), sunDirection), dot(vec3(h.toIndex[1]), sunDirection),
                      dot(vec3(h.toIndex[2]), sunDirection));
  return d / max(length(d), 1e-30f);
}

// What the light integrates at index coordinate `c`: the cloud's density at its coarse
// resolution (cloud_hero.h's heroCoarseDensity(): eroded by the detail noise's mean), the
// extinction in units of the instance's scales.x x extinctionPerMetre (0 beyond the box).
FX_INLINE float heroLightIntegrand(IN(HeroCloudInstance) h, vec3 c) {
  vec4 fields = heroFields(h, c);
  fields.x *= heroLifeCompiledIn() && h.scales.y > 0.0f ? heroLifeWeight(h, c, fields.w) : 1.0f;
  return heroCoarseDensity(fields).x;
}

// The light volume on one of its slices along `axis` (g[axis], an integer) at light-grid
// coordinate `g` (texel centres at integers) of a slot starting at texel `slotOrigin`, filtered
// bilinearly across the slice; texels beyond the grid read 0 (the sun's rays there have not
// crossed the box). Only the slice's own texels are read: the sweep is writing the next one.
FX_INLINE float heroLightOnSlice(vec3 g, int axis, ivec3 size, ivec3 slotOrigin) {
  const int across = (axis + 1) % 3;
  const int up = (axis + 2) % 3;
  const vec2 p = vec2(g[across], g[up]);
  const vec2 base = floor(p);
  const vec2 f = p - base;
  const ivec2 i0 = ivec2(base);
  float sum = 0.0f;
  for (int corner = 0; corner < 4; ++corner) {
    const ivec2 o = ivec2(corner & 1, corner >> 1);
    const vec2 weights = mix(vec2(1.0f) - f, f, vec2(o));
    ivec3 at;
    at[axis] = int(g[axis]);
    at[across] = i0.x + o.x;
    at[up] = i0.y + o.y;
    // Texels beyond the grid are not fetched at all: clamped, they could be the slice the sweep
    // is writing.
    const bool inGrid = all(equal(at, clamp(at, ivec3(0), size - 1)));
    for (int fetch = 0; fetch < (inGrid ? 1 : 0); ++fetch) {
      sum += fetchHeroLight(at + slotOrigin) * (weights.x * weights.y);
    }
  }
  return sum;
}

// The axis of index space nearest the sun direction `sunIndex`: the sweep's.
FX_INLINE int heroLightAxis(vec3 sunIndex) {
  const vec3 m = abs(sunIndex);
  return m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
}

// The optical depth towards the sun (voxel units) from index coordinate `c`: the light volume's
// slice `slice` (a light-grid coordinate along `axis`, on c's sun side) bilinearly where c's sun
// ray crosses it, plus the fields' integral up to there by Simpson's rule. `sunIndex` is the
// unit sun direction in index space, `axis` heroLightAxis()'s, so the crossing lies within a
// texel sideways of c. The sweep takes it at texel centres from the slice before; a sample takes
// it from the nearest slice towards the sun, so that the steep change of the optical depth
// under a sunlit face (a voxel of dense cloud hides most of the sun) is integrated, not
// interpolated across a texel.
FX_INLINE float heroLightFromSlice(IN(HeroCloudInstance) h, vec3 c, vec3 sunIndex, int axis,
                                   float slice, ivec3 size, ivec3 slotOrigin, bool simpson) {
  const float planeIndex = slice * kHeroLightTexelVoxels - 1.0f;
  const float along = abs(planeIndex - c[axis]) / abs(sunIndex[axis]);
  const vec3 crossing = c + sunIndex * along;
  vec3 g = (crossing + 1.0f) / kHeroLightTexelVoxels;
  g[axis] = slice;  // exactly on the slice
  const float before = heroLightOnSlice(g, axis, size, slotOrigin);
  const float middle = heroLightIntegrand(h, c + sunIndex * (0.5f * along));
  float ends = 0.0f;
  CLOUDS_WHEN(simpson) {
    ends = heroLightIntegrand(h, c) + heroLightIntegrand(h, crossing);
  }
  return before + (simpson ? (ends + 4.0f * middle) / 6.0f : middle) * along;
}

// The light texel `t` (x fastest across the slice) of the sweep's `s`-th slice, counted from
// the sun's side along `axis` of a grid of `size`, for the unit sun direction `sunIndex`.
FX_INLINE ivec3 heroLightSweepTexelAt(ivec3 size, vec3 sunIndex, int axis, int s, int t) {
  const int across = (axis + 1) % 3;
  const int up = (axis + 2) % 3;
  ivec3 j;
  j[axis] = sunIndex[axis] > 0.0f ? size[axis] - 1 - s : s;
  j[across] = t % size[across];
  j[up] = t / size[across];
  return j;
}

// The sweep's value of light texel `j`: from the slice one step towards the sun, which must hold
// its values already.
FX_INLINE float heroLightSweepTexel(IN(HeroCloudInstance) h, ivec3 j, vec3 sunIndex, int axis,
                                    ivec3 size, ivec3 slotOrigin) {
  const float slice = float(j[axis]) + (sunIndex[axis] > 0.0f ? 1.0f : -1.0f);
  return heroLightFromSlice(h, vec3(j) * kHeroLightTexelVoxels - 1.0f, sunIndex, axis, slice, size,
                            slotOrigin, true);
}

// A sample's lookup at index coordinate `c` in the box: from the nearest slice towards the sun.
FX_INLINE float heroLightLookup(IN(HeroCloudInstance) h, vec3 c, vec3 sunIndex, ivec3 slotOrigin) {
  const int axis = heroLightAxis(sunIndex);
  const float g = (c[axis] + 1.0f) / kHeroLightTexelVoxels;
  const float slice = sunIndex[axis] > 0.0f ? ceil(g) : floor(g);
  return heroLightFromSlice(h, c, sunIndex, axis, slice, heroLightSize(h), slotOrigin, false);
}

// The same optical depth (voxel units) from index coordinate `c` marched straight to the box's
// side at kHeroLightMarchedStepVoxels: the integral the volume approximates.
FX_INLINE float heroLightMarched(IN(HeroCloudInstance) h, vec3 c, vec3 sunIndex) {
  const vec3 d = mix(sunIndex, vec3(1e-30f), lessThan(abs(sunIndex), vec3(1e-30f)));
  const vec3 a = (vec3(-1.0f) - c) / d;
  const vec3 b = (vec3(h.extent) - c) / d;
  const vec3 far = max(a, b);
  const float exit = max(min(min(far.x, far.y), far.z), 0.0f);
  const int steps = min(int(ceil(exit / kHeroLightMarchedStepVoxels)), kHeroLightMarchedMaxSteps);
  const float step = exit / float(max(steps, 1));
  float sum = 0.0f;
  for (int i = 0; i < steps; ++i) {
    sum += heroLightIntegrand(h, c + sunIndex * ((float(i) + 0.5f) * step));
  }
  return sum * step;
}

// A sample's optical depth towards the sun through the hero clouds whose boxes hold it (1/m
// integrated over m), and those clouds (bit i: instance i), which the light cone then leaves
// out (sampleField()'s `heroExcluded`): it still reaches the layer and the other hero clouds.
struct HeroSunward {
  float opticalDepth;
  uint covered;
};

// `mode` kHeroLightVolume or kHeroLightMarched (kHeroLightCone: none covered).
FX_INLINE HeroSunward heroSunward(vec3 relative, IN(CloudUniforms) u, uint mode) {
  HeroSunward r;
  r.opticalDepth = 0.0f;
  r.covered = 0u;
  const uint count = mode == kHeroLightCone ? 0u : heroCloudCount();
  for (uint i = 0u; i < count; ++i) {
    const HeroCloudInstance h = heroCloud(i);
    const vec3 c = heroIndex(h, relative);
    const bool inBox =
        all(greaterThanEqual(c, vec3(-1.0f))) && all(lessThanEqual(c, vec3(h.extent)));
    float voxels = 0.0f;
    // The mode is a specialization constant in the march: plain ifs, so that each variant
    // compiles only its own (cloud_march.h's kHeroCompiledOut).
    if (mode == kHeroLightVolume) {
      CLOUDS_WHEN(inBox) {
        voxels =
            heroLightLookup(h, c, heroSunIndexDirection(h, u.sunDirection), heroLightSlotOrigin(i));
      }
    }
    if (mode == kHeroLightMarched) {
      CLOUDS_WHEN(inBox) {
        voxels = heroLightMarched(h, c, heroSunIndexDirection(h, u.sunDirection));
      }
    }
    r.opticalDepth += voxels * h.scales.x * u.extinctionPerMetre * h.scales.z;
    r.covered |= inBox ? 1u << i : 0u;
  }
  return r;
}

FX_SHADER_END

#endif
