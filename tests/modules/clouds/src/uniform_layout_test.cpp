// The per-frame uniform block is declared once (shaders/cloud_types.h) and compiled twice: as
// std140 GLSL by glslang and as a C++ struct. This compares, field by field, the offsets
// glslang's reflection reports for the GLSL block with the C++ offsetof, and the block's size
// with sizeof: a field the two compilers lay out differently fails here.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdio>
#include <map>
#include <memory>
#include <regex>
#include <string>

#include "cloud_types.h"

namespace {

using clouds::shader::CloudUniforms;

#define FIELD(name) \
  { #name, offsetof(CloudUniforms, name) }
const std::map<std::string, std::size_t> kCppOffsets = {FIELD(inverseProjection),
                                                        FIELD(viewToWorld),
                                                        FIELD(previousClipFromView),
                                                        FIELD(previousClipOrigin),
                                                        FIELD(cameraAltitudeMetres),
                                                        FIELD(planetRadiusMetres),
                                                        FIELD(layerBottomMetres),
                                                        FIELD(layerTopMetres),
                                                        FIELD(sunDirection),
                                                        FIELD(cameraMovedMetres),
                                                        FIELD(sunIlluminance),
                                                        FIELD(sunStrength),
                                                        FIELD(ambientTop),
                                                        FIELD(ambientStrength),
                                                        FIELD(ambientBottom),
                                                        FIELD(ambientOcclusionStrength),
                                                        FIELD(shapeOffsetMetres),
                                                        FIELD(shapeTileMetres),
                                                        FIELD(detailOffsetMetres),
                                                        FIELD(detailTileMetres),
                                                        FIELD(weatherOffsetMetres),
                                                        FIELD(weatherTileMetres),
                                                        FIELD(noiseFootprintPerMetre),
                                                        FIELD(curlOffsetMetres),
                                                        FIELD(curlTileMetres),
                                                        FIELD(curlStrengthMetres),
                                                        FIELD(windDirection),
                                                        FIELD(skewMetres),
                                                        FIELD(windShearRadians),
                                                        FIELD(nearFieldMetres),
                                                        FIELD(fineCellMetres),
                                                        FIELD(coarseCellMetres),
                                                        FIELD(nearFieldExtent),
                                                        FIELD(extinctionPerMetre),
                                                        FIELD(coverage),
                                                        FIELD(cloudType),
                                                        FIELD(typeVariation),
                                                        FIELD(anvilBias),
                                                        FIELD(detailErosion),
                                                        FIELD(detailDistanceMetres),
                                                        FIELD(densityVariation),
                                                        FIELD(phaseForwardG),
                                                        FIELD(phaseBackwardG),
                                                        FIELD(phaseBackwardWeight),
                                                        FIELD(albedo),
                                                        FIELD(msOctaves),
                                                        FIELD(msExtinctionScale),
                                                        FIELD(msContribution),
                                                        FIELD(msEccentricityScale),
                                                        FIELD(inScatterStrength),
                                                        FIELD(inScatterCoreProfile),
                                                        FIELD(silverIntensity),
                                                        FIELD(silverG),
                                                        FIELD(viewStepMetres),
                                                        FIELD(viewStepGrowth),
                                                        FIELD(maxDistanceMetres),
                                                        FIELD(transmittanceCutoff),
                                                        FIELD(lightConeMetres),
                                                        FIELD(lightConeSpread),
                                                        FIELD(coarseStepFactor),
                                                        FIELD(emptySamplesToCoarse),
                                                        FIELD(temporalIndex),
                                                        FIELD(maxViewSteps),
                                                        FIELD(flags),
                                                        FIELD(rayStartOffset),
                                                        FIELD(traceExtent),
                                                        FIELD(outputExtent),
                                                        FIELD(tilePhase),
                                                        FIELD(tileSize),
                                                        FIELD(lastFreshPixel),
                                                        FIELD(temporalFreshWeight),
                                                        FIELD(historyClampMargin),
                                                        FIELD(traceScale),
                                                        FIELD(historyClampSpreadPixels),
                                                        FIELD(subpixelOffset),
                                                        FIELD(upsamplingMaxSamples),
                                                        FIELD(lightRound),
                                                        FIELD(aerialPerspectiveScale),
                                                        FIELD(aerialPerspectiveRange),
                                                        FIELD(aerialPerspectiveSlices),
                                                        FIELD(edgeRaysPerTile),
                                                        FIELD(edgeRayStartOffsets),
                                                        FIELD(phaseNormaliserInverseLow),
                                                        FIELD(phaseNormaliserInverseHigh),
                                                        FIELD(edgeSubpixelOffsets),
                                                        FIELD(weatherRegionCount),
                                                        FIELD(layerDensityScale),
                                                        FIELD(fullestCoverage),
                                                        FIELD(previousClipFromWorld),
                                                        FIELD(vortexClock),
                                                        FIELD(vortexRegion),
                                                        FIELD(vortexHistorySeconds),
                                                        FIELD(skyLightRefresh),
                                                        FIELD(padding0)};
#undef FIELD

std::string reflect() {
  const std::string command =
      std::string(GLSLANG_VALIDATOR) +
      " --target-env vulkan1.2 -q --reflect-all-block-variables -o /dev/null -I" +
      CLOUDS_SHADER_DIR + " -I" + FXCONTRACTS_INCLUDE_DIR + " " + PROBE_SHADER + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buffer{};
  while (pipe && fgets(buffer.data(), int(buffer.size()), pipe.get()) != nullptr) {
    out += buffer.data();
  }
  return out;
}

TEST(UniformLayout, GlslAndCppAgreeOnEveryFieldOfTheBlock) {
  const std::string reflection = reflect();
  // "frameUniforms[0].<field>: offset <n>, ..." for every member of the block.
  const std::regex member(R"(frameUniforms\[0\]\.(\w+): offset (\d+))");
  std::map<std::string, std::size_t> glsl;
  for (auto it = std::sregex_iterator(reflection.begin(), reflection.end(), member);
       it != std::sregex_iterator(); ++it) {
    glsl[(*it)[1]] = std::stoul((*it)[2]);
  }
  ASSERT_FALSE(glsl.empty()) << reflection;
  // The weather regions' array (the block's member after the GLSL struct, the C++ struct's
  // last), member by member of each element.
  using clouds::shader::WeatherRegionUniform;
  const std::map<std::string, std::size_t> regionMembers = {
      {"placement", offsetof(WeatherRegionUniform, placement)},
      {"shape", offsetof(WeatherRegionUniform, shape)},
      {"look", offsetof(WeatherRegionUniform, look)},
      {"vortex", offsetof(WeatherRegionUniform, vortex)}};
  const std::regex regionMember(R"(frameWeatherRegions\[(\d+)\]\.(\w+): offset (\d+))");
  std::size_t regionFields = 0;
  for (auto it = std::sregex_iterator(reflection.begin(), reflection.end(), regionMember);
       it != std::sregex_iterator(); ++it, ++regionFields) {
    const std::size_t index = std::stoul((*it)[1]);
    const auto cpp = regionMembers.find((*it)[2]);
    ASSERT_NE(cpp, regionMembers.end()) << (*it)[2] << " is not in the C++ list";
    EXPECT_EQ(offsetof(CloudUniforms, weatherRegions) + index * sizeof(WeatherRegionUniform) +
                  cpp->second,
              std::stoul((*it)[3]))
        << "weatherRegions[" << index << "]." << (*it)[2];
  }
  EXPECT_EQ(regionFields, regionMembers.size() * clouds::shader::kMaxWeatherRegions);
  EXPECT_EQ(glsl.size(), kCppOffsets.size()) << "a field is missing from one side's list";
  for (const auto& [name, offset] : glsl) {
    const auto cpp = kCppOffsets.find(name);
    ASSERT_NE(cpp, kCppOffsets.end()) << name << " is not in the C++ list";
    EXPECT_EQ(cpp->second, offset) << name;
  }
  std::smatch size;
  ASSERT_TRUE(std::regex_search(reflection, size,
                                std::regex(R"(FrameUniforms: offset -1, type \w+, size (\d+))")))
      << reflection;
  EXPECT_EQ(std::stoul(size[1]), sizeof(CloudUniforms));
}

}  // namespace
