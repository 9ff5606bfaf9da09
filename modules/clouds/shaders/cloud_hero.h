// Hero clouds (Schneider 2023, "Nubis³" voxel clouds): NVDF assets (clouds/nvdf.h) placed in
// the world, the march's second density source beside the layer (cloud_march.h's sampleField()
// adds them). Shared by the march shader and the CPU reference.
//
// An asset's voxels lie in one RGBA8 atlas (hero_clouds.h): R the dimensional profile, G the
// detail type, B the density scale, A the signed distance as a code rounded down (a conservative
// bound: where it reads d > 0 no cloud lies within d). Between voxel centres the fields are
// filtered trilinearly, fading to clear air over the voxel beyond the outermost centres.
// Positions are camera-relative metres on straight lines from the camera: the host's flat map,
// on which its terrain stands, not the layer's curved shell.
//
// A cloud's life (HeroCloud::growth, ::dissipation; beyond Nubis³'s "pseudomotion") shapes
// what its voxels hold without new data: a top that rises from its base as it grows, an edge
// eaten inwards along the signed distance as it grows or dissipates, and a fading density.
// All three only take cloud away, so the distance field stays a bound the march may jump by.
//
// Between the voxels, detail (Settings::heroDetail, Nubis³'s "up-rez"): the profile eroded by a
// half-metre noise that moves with the cloud, wispy or billowy by the voxel's detail type, read
// at the level of its mip chain that one pixel covers. Erosion too only takes cloud away. The
// light, the shadow map and the distance queries see the cloud at their own, coarser resolution:
// eroded by the noise's mean.
#ifndef CLOUDS_CLOUD_HERO_H
#define CLOUDS_CLOUD_HERO_H

#include "cloud_math.h"
#include "cloud_sampling.h"
#include "cloud_types.h"

FX_SHADER_BEGIN(clouds::shader)

// The includer's: this frame's hero clouds (0 where they are not compiled in) and the atlas.
uint heroCloudCount();
HeroCloudInstance heroCloud(uint index);
vec4 fetchHeroAtlas(ivec3 texel);  // RGBA8 as [0, 1]
bool heroLifeCompiledIn();         // the kHeroCloudsLiving variant (the CPU: always)
uvec4 heroCloudHeader();           // HeroCloudUniforms::count
vec4 fetchHeroNoise(ivec3 texel);  // the detail noise's chain (kHeroNoiseSize), RGBA8 as [0, 1]
vec4 heroNoiseMean();              // its last level, read once (not in the loops that ask)

const float kHeroFar = 1e30f;
// The distance code: (A x 255 - 128) / 127 of the full scale (kHeroDistanceRangeVoxels).
const float kHeroDistanceZero = 128.0f;
// Steps inside a hero cloud's box, in its voxels: the fields change linearly within a voxel.
const float kHeroStepVoxels = 1.0f;

// Index coordinates (voxel centres at integers) of a camera-relative point.
FX_INLINE vec3 heroIndex(IN(HeroCloudInstance) h, vec3 relative) {
  return vec3(dot(vec3(h.toIndex[0]), relative) + h.toIndex[0].w,
              dot(vec3(h.toIndex[1]), relative) + h.toIndex[1].w,
              dot(vec3(h.toIndex[2]), relative) + h.toIndex[2].w);
}

// The first texel of an instance's asset in the atlas (HeroCloudInstance::extent.w). Shifts, not
// a division: lavapipe divides integers one lane at a time, and every voxel lookup asks.
FX_INLINE ivec3 heroAtlasOrigin(IN(HeroCloudInstance) h) {
  const uint code = uint(h.extent.w);
  return ivec3(int(code >> kHeroAtlasOriginBits), 0,
               int(code & ((1u << kHeroAtlasOriginBits) - 1u)));
}

// The fields at index coordinate `c`: xyz the profile, detail type and density scale (clear air
// beyond the outermost voxels), w the signed distance (world m; the edge voxels' beyond them).
FX_INLINE vec4 heroFields(IN(HeroCloudInstance) h, vec3 c) {
  const ivec3 last = ivec3(vec3(h.extent)) - 1;
  const ivec3 origin = heroAtlasOrigin(h);
  const vec3 base = floor(c);
  const vec3 f = c - base;
  const ivec3 i0 = ivec3(base);
  vec3 fields = vec3(0.0f);
  float code = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
    const vec3 weights = mix(vec3(1.0f) - f, f, vec3(o));
    const float w = weights.x * weights.y * weights.z;
    const ivec3 at = i0 + o;
    const ivec3 clamped = clamp(at, ivec3(0), last);
    const vec4 texel = fetchHeroAtlas(clamped + origin);
    fields += all(equal(at, clamped)) ? vec3(texel) * w : vec3(0.0f);
    code += texel.w * w;
  }
  const float fullScaleMetres = kHeroDistanceRangeVoxels * h.scales.z;
  return vec4(fields, (code * 255.0f - kHeroDistanceZero) / 127.0f * fullScaleMetres);
}

// How much of its voxels' cloud a cloud's life leaves at index coordinate `c`, whose signed
// distance is `distanceMetres`: in [0, 1], and exactly 1 for a grown cloud that does not
// dissipate (its top above the box and no erosion: wherever a voxel's profile reaches, the
// distance of an NVDF made by buildNvdf() reads at least sqrt(3) voxels inside, its margin for
// the filter's reach, so the one-voxel edge ramp is saturated; see docs/nvdf-format.md).
// The top is domed: a point as many voxels deep as the code reaches (kHeroDistanceRangeVoxels)
// may stand that much above it, so a growing cloud's cores rise first, rounded, not cut flat.
FX_INLINE float heroLifeWeight(IN(HeroCloudInstance) h, vec3 c, float distanceMetres) {
  const float topFeather = max(kHeroTopFeather * float(h.extent.y), 1.0f);
  const float depthVoxels = clamp(-distanceMetres / h.scales.z, 0.0f, kHeroDistanceRangeVoxels);
  const float belowTop = saturate((h.scales.w - c.y + depthVoxels) / topFeather);
  const float insideEdge = saturate((-distanceMetres - h.scales.y) / h.scales.z);
  return belowTop * insideEdge;
}

// Where texel `t` of `level` of the detail noise's chain lies in its n x n x 5n/4 image: level 0
// fills the first n slices; level 1 (n/2 a side) the n/4 slices above, its first n/4 slices at
// x < n/2 and the rest beside them; levels 2 and up side by side along x above level 1's first
// half in y (at x = n - 2 (n >> L), as cloud_sampling.h's noiseLevelOrigin()). So the chain
// takes a quarter more than level 0, not a half.
FX_INLINE ivec3 heroNoiseTexelAddress(int level, ivec3 t) {
  const int n = kHeroNoiseSize;
  const int quarter = n / 4;
  if (level == 0) return t;
  if (level == 1) return ivec3(t.x + (n / 2) * (t.z / quarter), t.y, n + t.z % quarter);
  return ivec3(n - 2 * (n >> level) + t.x, n / 2 + t.y, n + t.z);
}

// The detail noise at `uvw` (tiles) from `level` of its chain, trilinear.
FX_INLINE vec4 sampleHeroNoise(vec3 uvw, int level) {
  const int size = kHeroNoiseSize >> level;
  const vec3 p = uvw * float(size) - 0.5f;
  const vec3 pFloor = floor(p);
  const vec3 f = p - pFloor;
  const ivec3 i0 = ivec3(pFloor);
  vec4 sum = vec4(0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    const ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
    const vec3 weights = mix(vec3(1.0f) - f, f, vec3(o));
    const ivec3 address = heroNoiseTexelAddress(level, (i0 + o) & (size - 1));
    sum += fetchHeroNoise(address) * (weights.x * weights.y * weights.z);
  }
  return sum;
}

// Nubis³'s voxel cloud density sampler: the dimensional `profile` eroded by the detail `noise`
// (sampleHeroNoise()). The wisps (the curly alligator, R and G) and the billows (the
// alligator, B and A, at 0.3 of its strength) each go from their low to their high frequency
// as the profile rises into the core, so edges carry the broad shapes and cores the fine ones;
// the voxel's `detailType` blends wisps (0) into billows (1). Returns x the density, in [0, 1]:
// what survives the erosion, scaled by the voxel's `densityScale` and sharpened by a power that
// rises with it, so thin cloud stays wispy and dense cloud ends in a crisp edge; y the eroded
// profile, which the lighting reads where it reads a profile, so the detail is lit as shapes.
FX_INLINE vec2 heroUprezzed(float profile, float detailType, float densityScale, vec4 noise) {
  const float wispy = mix(noise.x, noise.y, profile);
  const float billowy = mix(noise.z, noise.w, sqrt(sqrt(profile))) * 0.3f;  // profile^0.25
  const float composite = mix(wispy, billowy, detailType);
  const float erodedProfile = saturate(remap(profile, composite, 1.0f, 0.0f, 1.0f));
  const float eroded = erodedProfile * densityScale;
  const float scaleSquared = saturate(densityScale) * saturate(densityScale);
  const float sharpness = mix(0.3f, 0.6f, max(1e-6f, scaleSquared * scaleSquared));  // ^4
  return vec2(eroded > 0.0f ? pow(eroded, sharpness) : 0.0f, erodedProfile);
}

FX_INLINE float heroUprezzedDensity(float profile, float detailType, float densityScale,
                                    vec4 noise) {
  return heroUprezzed(profile, detailType, densityScale, noise).x;
}

// The settings' detail (kHeroDetail*), from the block's header.
FX_INLINE bool heroDetailed() {
  return heroCloudHeader().w == kHeroDetailUprezzed;
}

// The density (x, in units of the instance's scales.x x extinctionPerMetre) and the profile the
// lighting reads (y) of voxel fields `fields` (heroFields(), x the profile as the cloud's life
// leaves it), at the cloud's coarse resolution: eroded by the detail noise's mean.
FX_INLINE vec2 heroCoarseDensity(vec4 fields) {
  if (!heroDetailed()) return vec2(fields.x * fields.z, fields.x);
  return heroUprezzed(fields.x, fields.y, fields.z, heroNoiseMean());
}

// What the hero clouds hold at a camera-relative point, at their coarse resolution, and what
// heroAddDetail() needs to read the detail of the one with the largest profile there.
struct HeroSample {
  float sigmaT;            // extinction (1/m), summed over the clouds
  float profile;           // the (eroded) dimensional profile of the one that is densest there
  float heightFraction;    // the height of the point in that one's box, [0, 1]
  float clearMetres;       // no hero cloud lies within this distance (m); 0 in an envelope
  float reach;             // the largest profile here: > 0 where any detail could leave cloud
  vec3 detailUvw;          // where that cloud's detail noise is read (tiles)
  vec4 detailFields;       // its fields (heroFields()), the profile as its life leaves it
  float detailExtinction;  // the extinction (1/m) of its density's 1
  float detailCoarse;      // its coarse density (heroCoarseDensity())
};

// `excluded`: clouds left out (bit i: instance i), those whose own light a light sample has
// (cloud_hero_light.h's heroSunward()).
FX_INLINE HeroSample heroFieldExcept(vec3 relative, IN(CloudUniforms) u, uint excluded) {
  HeroSample s;
  s.sigmaT = 0.0f;
  s.profile = 0.0f;
  s.heightFraction = 0.0f;
  s.clearMetres = kHeroFar;
  s.reach = 0.0f;
  s.detailUvw = vec3(0.0f);
  s.detailFields = vec4(0.0f);
  s.detailExtinction = 0.0f;
  s.detailCoarse = 0.0f;
  float densest = 0.0f;
  const uint count = heroCloudCount();
  for (uint i = 0u; i < count; ++i) {
    if (((excluded >> i) & 1u) != 0u) continue;
    const HeroCloudInstance h = heroCloud(i);
    const vec3 c = heroIndex(h, relative);
    const vec3 size = vec3(h.extent);
    // Beyond [-1, size] every voxel the filter reads is clear: the box's distance bounds it.
    const vec3 beyond = max(max(vec3(-1.0f) - c, c - size), vec3(0.0f));
    const float boxMetres = length(beyond) * h.scales.z;
    s.clearMetres = min(s.clearMetres, boxMetres);
    for (int inBox = 0; inBox < (boxMetres == 0.0f ? 1 : 0); ++inBox) {
      vec4 fields = heroFields(h, c);
      s.clearMetres = min(s.clearMetres, max(fields.w, 0.0f));
      // A cloud without erosion is grown and not dissipating: its life weighs exactly 1 (see
      // heroLifeWeight()), so it skips it; a frame without living clouds compiles it out.
      const float life =
          heroLifeCompiledIn() && h.scales.y > 0.0f ? heroLifeWeight(h, c, fields.w) : 1.0f;
      fields.x *= life;
      const vec2 density = heroCoarseDensity(fields);
      const float extinction = h.scales.x * u.extinctionPerMetre;
      const float sigma = density.x * extinction;
      s.sigmaT += sigma;
      if (sigma > densest) {
        densest = sigma;
        s.profile = density.y;
        s.heightFraction = saturate((c.y + 1.0f) / (size.y + 1.0f));
      }
      if (fields.x > s.reach) {
        s.reach = fields.x;
        s.detailUvw = c * (h.scales.z / kHeroNoiseTileMetres);
        s.detailFields = fields;
        s.detailExtinction = extinction;
        s.detailCoarse = density.x;
      }
    }
  }
  return s;
}

// The hero clouds at their coarse resolution (the light, the shadow map, the distance queries).
FX_INLINE HeroSample heroField(vec3 relative, IN(CloudUniforms) u) {
  return heroFieldExcept(relative, u, 0u);
}

// The detail (Settings::heroDetail) of the cloud with the largest profile at the sample `s`:
// its density up-rezzed by the detail noise read at the level a pixel `footprintMetres` wide
// covers (rounded by `dither`, as cloud_sampling.h's noiseLevel()) in place of its coarse one,
// and its eroded profile lights the sample. Where another cloud's box overlaps with cloud in
// both, that one keeps its coarse density. Called once per view sample, outside the loops over
// clouds: on lavapipe a fetch inside them slows the whole march, taken or not.
FX_INLINE void heroAddDetail(INOUT(HeroSample) s, float footprintMetres, float dither) {
  if (!heroDetailed() || s.reach <= 0.0f) return;
  const int level = noiseLevel(footprintMetres, kHeroNoiseTileMetres / float(kHeroNoiseSize),
                               dither, kHeroNoiseLevels);
  const vec4 f = s.detailFields;
  const vec2 fine = heroUprezzed(f.x, f.y, f.z, sampleHeroNoise(s.detailUvw, level));
  s.sigmaT = max(s.sigmaT + (fine.x - s.detailCoarse) * s.detailExtinction, 0.0f);
  s.profile = fine.y;
}

// Where the ray from the camera-relative point `from` along the unit `direction` crosses hero
// clouds' boxes, at distances of at least `nearest` (m): x the first entry, y the last exit
// (x >= y when it meets none), z the smallest voxel (m) of the clouds it meets.
FX_INLINE vec3 heroRaySpan(vec3 from, vec3 direction, float nearest) {
  vec3 span = vec3(kHeroFar, -kHeroFar, kHeroFar);
  const uint count = heroCloudCount();
  for (uint i = 0u; i < count; ++i) {
    const HeroCloudInstance h = heroCloud(i);
    const vec3 origin = heroIndex(h, from);
    vec3 d = vec3(dot(vec3(h.toIndex[0]), direction), dot(vec3(h.toIndex[1]), direction),
                  dot(vec3(h.toIndex[2]), direction));
    // A ray parallel to a face: a tiny slope keeps the slab test finite (it then spans +-1e30).
    d = mix(d, vec3(1e-30f), lessThan(abs(d), vec3(1e-30f)));
    const vec3 a = (vec3(-1.0f) - origin) / d;
    const vec3 b = (vec3(h.extent) - origin) / d;
    const vec3 near = min(a, b);
    const vec3 far = max(a, b);
    const float enter = max(max(near.x, near.y), max(near.z, nearest));
    const float exit = min(min(far.x, far.y), far.z);
    if (enter < exit) {
      span.x = min(span.x, enter);
      span.y = max(span.y, exit);
      span.z = min(span.z, h.scales.z);
    }
  }
  return span;
}

FX_SHADER_END

#endif
