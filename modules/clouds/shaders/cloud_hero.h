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
#ifndef CLOUDS_CLOUD_HERO_H
#define CLOUDS_CLOUD_HERO_H

#include "cloud_math.h"
#include "cloud_types.h"

FX_SHADER_BEGIN(clouds::shader)

// The includer's: this frame's hero clouds (0 where they are not compiled in), the atlas and
// the up-rez noise (cloud_noise.h's heroNoiseTexel(), kHeroNoiseSize^3, wrapped).
uint heroCloudCount();
HeroCloudInstance heroCloud(uint index);
vec4 fetchHeroAtlas(ivec3 texel);  // RGBA8 as [0, 1]
vec4 fetchHeroNoise(ivec3 texel);  // RGBA8 as [0, 1]

const float kHeroFar = 1e30f;
// The distance code: (A x 255 - 128) / 127 of the full scale (HeroCloudInstance::scales.y).
const float kHeroDistanceZero = 128.0f;
// Steps inside a hero cloud's box, in its voxels: the fields change linearly within a voxel.
const float kHeroStepVoxels = 1.0f;
// The up-rez noise's tile in a cloud's own metres: 128 texels of 0.75 m, its low frequencies'
// features 24 m across, its high ones' 6 m.
const float kHeroNoiseTileMetres = 96.0f;
// The pixel footprint (m) beyond which the noise's features are too small to see: its erosion
// fades out from half of it (a level of detail without mips: nothing is sampled that would only
// alias).
const float kHeroNoiseFootprintMetres = 12.0f;

// Index coordinates (voxel centres at integers) of a camera-relative point.
FX_INLINE vec3 heroIndex(IN(HeroCloudInstance) h, vec3 relative) {
  return vec3(dot(vec3(h.toIndex[0]), relative) + h.toIndex[0].w,
              dot(vec3(h.toIndex[1]), relative) + h.toIndex[1].w,
              dot(vec3(h.toIndex[2]), relative) + h.toIndex[2].w);
}

// The fields at index coordinate `c`: xyz the profile, detail type and density scale (clear air
// beyond the outermost voxels), w the signed distance (world m; the edge voxels' beyond them).
FX_INLINE vec4 heroFields(IN(HeroCloudInstance) h, vec3 c) {
  const ivec3 last = ivec3(vec3(h.extent)) - 1;
  const int slice = int(h.extent.w);
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
    const vec4 texel = fetchHeroAtlas(ivec3(clamped.x, clamped.y, clamped.z + slice));
    fields += all(equal(at, clamped)) ? vec3(texel) * w : vec3(0.0f);
    code += texel.w * w;
  }
  return vec4(fields, (code * 255.0f - kHeroDistanceZero) / 127.0f * h.scales.y);
}

// The up-rez noise at `uvw` (tile units, wrapping), filtered trilinearly by hand as the other
// noises are (cloud_sampling.h): the same on the GPU and the CPU.
FX_INLINE vec4 sampleHeroNoise(vec3 uvw) {
  const int n = kHeroNoiseSize;
  const vec3 p = uvw * float(n) - 0.5f;
  const vec3 pFloor = floor(p);
  const vec3 f = p - pFloor;
  const ivec3 i0 = ivec3(pFloor) & (n - 1);
  const ivec3 i1 = (i0 + 1) & (n - 1);
  const vec4 x00 =
      mix(fetchHeroNoise(ivec3(i0.x, i0.y, i0.z)), fetchHeroNoise(ivec3(i1.x, i0.y, i0.z)), f.x);
  const vec4 x10 =
      mix(fetchHeroNoise(ivec3(i0.x, i1.y, i0.z)), fetchHeroNoise(ivec3(i1.x, i1.y, i0.z)), f.x);
  const vec4 x01 =
      mix(fetchHeroNoise(ivec3(i0.x, i0.y, i1.z)), fetchHeroNoise(ivec3(i1.x, i0.y, i1.z)), f.x);
  const vec4 x11 =
      mix(fetchHeroNoise(ivec3(i0.x, i1.y, i1.z)), fetchHeroNoise(ivec3(i1.x, i1.y, i1.z)), f.x);
  return mix(mix(x00, x10, f.y), mix(x01, x11, f.y), f.z);
}

// Nubis³'s up-rez of a voxel cloud (Schneider 2023, the voxel cloud density sampler): the
// dimensional profile eroded by a composite of the noise. Wisps (curly alligator) blend from
// low to high frequency as the profile deepens; billows (alligator, a third as strong) blend
// likewise, sooner (profile^0.25); the detail type picks between them. `erosion` in [0, 1]
// (Settings::detailErosion, faded with the pixel's footprint): 0 leaves the profile as it is.
FX_INLINE float upRezzedProfile(float profile, float detailType, vec4 noise, float erosion) {
  const float wispy = mix(noise.x, noise.y, profile);
  const float billowy = mix(noise.z * 0.3f, noise.w * 0.3f, pow(profile, 0.25f));
  const float composite = mix(wispy, billowy, saturate(detailType));
  return saturate(remap(profile, composite * erosion, 1.0f, 0.0f, 1.0f));
}

// What the hero clouds hold at a camera-relative point.
struct HeroSample {
  float sigmaT;          // extinction (1/m), summed over the clouds
  float profile;         // the dimensional profile of the one that is densest there
  float heightFraction;  // the height of the point in that one's box, [0, 1]
  float clearMetres;     // no hero cloud lies within this distance (m); 0 in an envelope
};

// `distance` (m) from the camera and `wantDetail` (0: the coarse field, as light samples and the
// shadow map take it) decide the up-rez.
FX_INLINE HeroSample heroField(vec3 relative, float distance, uint wantDetail,
                               IN(CloudUniforms) u) {
  HeroSample s;
  s.sigmaT = 0.0f;
  s.profile = 0.0f;
  s.heightFraction = 0.0f;
  s.clearMetres = kHeroFar;
  float densest = 0.0f;
  const uint count = heroCloudCount();
  for (uint i = 0u; i < count; ++i) {
    const HeroCloudInstance h = heroCloud(i);
    const vec3 c = heroIndex(h, relative);
    const vec3 size = vec3(h.extent);
    // Beyond [-1, size] every voxel the filter reads is clear: the box's distance bounds it.
    const vec3 beyond = max(max(vec3(-1.0f) - c, c - size), vec3(0.0f));
    const float boxMetres = length(beyond) * h.scales.z;
    s.clearMetres = min(s.clearMetres, boxMetres);
    for (int inBox = 0; inBox < (boxMetres == 0.0f ? 1 : 0); ++inBox) {
      const vec4 fields = heroFields(h, c);
      s.clearMetres = min(s.clearMetres, max(fields.w, 0.0f));
      float density = fields.x;
      const float footprint = distance * u.noiseFootprintPerMetre;
      const float erosion =
          u.detailErosion * saturate(2.0f - 2.0f * footprint / kHeroNoiseFootprintMetres);
      CLOUDS_WHEN(wantDetail != 0u && fields.x > 0.0f && erosion > 0.0f &&
                  distance < u.detailDistanceMetres) {
        // The noise is fixed to the cloud: its own metres (index coordinates times its voxel).
        const vec3 uvw = c * (h.scales.z / kHeroNoiseTileMetres);
        density = upRezzedProfile(fields.x, fields.y, sampleHeroNoise(uvw), erosion);
      }
      const float sigma = density * fields.z * h.scales.x * u.extinctionPerMetre;
      s.sigmaT += sigma;
      if (sigma > densest) {
        densest = sigma;
        s.profile = fields.x;
        s.heightFraction = saturate((c.y + 1.0f) / (size.y + 1.0f));
      }
    }
  }
  return s;
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
