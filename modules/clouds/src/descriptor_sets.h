#pragma once
// The descriptor sets the module allocates, by program, as one table: those made once with the
// context (the generators' targets) and those of each frame slot. The descriptor pool is sized
// from it and the programs' bindings (programs.cpp), so a pass that gains a binding or a set
// needs no count kept by hand: a set allocated beyond the table fails its allocation.
#include <cstdint>

#include "kit.h"
#include "programs.h"

namespace clouds::detail {

struct SetsOf {
  Program program;
  std::uint32_t sets;
};

// Made once (writeFixedSets): the noise generators and their mip chains, the two weather maps'
// generators and maxima, and the coarse maxima of the empty-space-skipping grid; the hero
// clouds' detail noise and its chain (written when it is made).
inline constexpr SetsOf kFixedSets[] = {
    {Program::ShapeNoise, 1}, {Program::DetailNoise, 1},  {Program::CurlNoise, 1},
    {Program::NoiseMip, 2},   {Program::Weather, 2},      {Program::WeatherMaxima, 3},
    {Program::HeroNoise, 1},  {Program::HeroNoiseMip, 1},
};

// One of each per frame slot (Context::Impl::Slot), each written when its pass records.
inline constexpr SetsOf kSlotSets[] = {
    {Program::SceneDistance, 1},   {Program::March, 1},     {Program::Reconstruct, 1},
    {Program::Upsample, 1},        {Program::Composite, 1}, {Program::SkyAmbient, 1},
    {Program::WeatherResample, 1}, {Program::ShadowMap, 1}, {Program::TerrainShadow, 1},
    {Program::GodRayOcclusion, 1}, {Program::GodRays, 1},   {Program::LightningBolts, 1},
    {Program::HeroLight, 1},       {Program::SkyLight, 1},
};

// A pool that holds exactly the sets of the tables for `frames` slots (programs the context
// lacks, such as the composite without a composite format, count for nothing).
UniqueDescriptorPool makeDescriptorPool(const DeviceContext& device, const Programs& programs,
                                        std::uint32_t frames);

}  // namespace clouds::detail
