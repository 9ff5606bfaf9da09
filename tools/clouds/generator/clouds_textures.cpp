// clouds_textures: writes the clouds module's procedural textures as PNG (8 bits, the bytes the
// module's images hold) and EXR (the unrounded values), computed on the CPU by the module's own
// texel functions (clouds/procedural_textures.h), so artists can inspect them and paint over
// the weather map (a painted map goes back through FrameInputs::weatherView, or a scene's
// "weatherMap").
//
// Usage: clouds_textures --out DIR [--seed N] [--time SECONDS] [--state NAME]...
//                        [--around NAME] [--region NAME,X,Z,RADIUS,BLEND]...
//   --seed   the module's CreateInfo::noiseSeed (default 1)
//   --time   the clock of the weather map (FrameInputs::timeSeconds, default 0)
//   --state  a built-in weather state to write the marched weather of (sparse, cloudy,
//            overcast, stormy; repeatable; default all four)
//   --region a weather region (clouds::WeatherRegion, a disc) of a built-in state centred at
//            world (X, Z) m, its look held within RADIUS m and blended out over BLEND m more
//            (repeatable, applied in order, at most clouds::kMaxWeatherRegions)
//   --around the built-in state around the regions (default: the module's default look)
// Writes into DIR: shape_noise, detail_noise, hero_noise (volumes as atlases of z slices, left
// to right then top to bottom), curl_noise, weather_map (what to paint over),
// weather_<state> (the map as the march reads it under the state) and, with regions,
// weather_regions (the tile at the world's origin as the march reads it under them), each .png
// and .exr, and textures.json describing them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "clouds/procedural_textures.h"
#include "clouds/weather.h"
#include "engine/assets/image_io.h"
#include "engine/core/error.h"

namespace {

namespace fs = std::filesystem;
using engine::assets::ImageRgba32f;
using engine::assets::ImageRgba8;

struct Options {
  fs::path out;
  std::uint32_t seed = 1;
  double timeSeconds = 0.0;
  std::vector<clouds::WeatherPreset> states;
  std::optional<clouds::WeatherPreset> around;
  std::vector<clouds::WeatherRegion> regions;
};

[[noreturn]] void usageError(const std::string& message) {
  throw engine::Error("clouds_textures: " + message +
                      "\nusage: clouds_textures --out DIR [--seed N] [--time SECONDS] "
                      "[--state sparse|cloudy|overcast|stormy]... [--around STATE] "
                      "[--region STATE,X,Z,RADIUS,BLEND]...");
}

clouds::WeatherPreset statePreset(const std::string& flag, const std::string& name) {
  clouds::WeatherPreset preset{};
  if (!clouds::parseWeatherPreset(name, &preset)) {
    usageError(flag + " " + name + ": not sparse, cloudy, overcast or stormy");
  }
  return preset;
}

// "STATE,X,Z,RADIUS,BLEND": a disc of a built-in state's look.
clouds::WeatherRegion parseRegion(const std::string& value) {
  const std::size_t comma = value.find(',');
  const std::string name = value.substr(0, comma);
  double numbers[4] = {};
  std::size_t at = comma;
  for (double& number : numbers) {
    if (at == std::string::npos) usageError("--region " + value + ": not STATE,X,Z,RADIUS,BLEND");
    const char* start = value.c_str() + at + 1;
    char* end = nullptr;
    number = std::strtod(start, &end);
    if (end == start || !std::isfinite(number) || (*end != ',' && *end != '\0')) {
      usageError("--region " + value + ": not STATE,X,Z,RADIUS,BLEND");
    }
    at = *end == ',' ? std::size_t(end - value.c_str()) : std::string::npos;
  }
  if (at != std::string::npos) usageError("--region " + value + ": not STATE,X,Z,RADIUS,BLEND");
  clouds::WeatherRegion region;
  region.centreMetres = {numbers[0], numbers[1]};
  region.radiusMetres = float(numbers[2]);
  region.blendMetres = float(numbers[3]);
  if (!(numbers[2] >= 0.0 && numbers[2] <= 1e7) || !(numbers[3] >= 100.0 && numbers[3] <= 1e7) ||
      std::abs(numbers[0]) > 1e7 || std::abs(numbers[1]) > 1e7) {
    usageError("--region " + value +
               ": X and Z within 1e7 m, RADIUS in [0, 1e7] m, BLEND in [100, 1e7] m");
  }
  return clouds::withWeather(region, clouds::weatherPreset(statePreset("--region", name)));
}

Options parseOptions(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) usageError(flag + " needs a value");
    const std::string value = argv[++i];
    char* end = nullptr;
    if (flag == "--out") {
      options.out = value;
    } else if (flag == "--seed") {
      const unsigned long long seed = std::strtoull(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || value[0] == '-' || seed > 0xffffffffull) {
        usageError("--seed " + value + ": not a whole number in [0, 4294967295]");
      }
      options.seed = static_cast<std::uint32_t>(seed);
    } else if (flag == "--time") {
      options.timeSeconds = std::strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0' || !(options.timeSeconds >= 0.0) ||
          options.timeSeconds > 1e9) {
        usageError("--time " + value + ": not a number of seconds in [0, 1e9]");
      }
    } else if (flag == "--state") {
      options.states.push_back(statePreset(flag, value));
    } else if (flag == "--around") {
      options.around = statePreset(flag, value);
    } else if (flag == "--region") {
      if (options.regions.size() == clouds::kMaxWeatherRegions) {
        usageError("--region: at most " + std::to_string(clouds::kMaxWeatherRegions) + " regions");
      }
      options.regions.push_back(parseRegion(value));
    } else {
      usageError("unknown option " + flag);
    }
  }
  if (options.out.empty()) usageError("--out DIR is required");
  if (options.around && options.regions.empty()) usageError("--around: around no --region");
  if (options.states.empty()) {
    options.states.assign(std::begin(clouds::kWeatherPresets), std::end(clouds::kWeatherPresets));
  }
  return options;
}

// An image of width x height RGBA texels, as float (for EXR) from which the PNG's bytes are the
// module's stored bytes.
struct Picture {
  ImageRgba32f values;

  Picture(std::uint32_t width, std::uint32_t height) {
    values.width = width;
    values.height = height;
    values.pixels.assign(4 * std::size_t(width) * height, 0.0f);
  }
  void set(std::uint32_t x, std::uint32_t y, glm::vec4 v) {
    float* p = values.at(x, y);
    p[0] = v.x;
    p[1] = v.y;
    p[2] = v.z;
    p[3] = v.w;
  }
  void write(const fs::path& stem) const {
    ImageRgba8 bytes{values.width, values.height, {}};
    bytes.pixels.reserve(values.pixels.size());
    for (const float v : values.pixels) bytes.pixels.push_back(clouds::storedUnorm8(v));
    engine::assets::writePng(fs::path(stem).concat(".png"), bytes);
    engine::assets::writeExr(fs::path(stem).concat(".exr"), values);
  }
};

// A volume `size` texels wide as an atlas of its z slices, `columns` slices across; each slice
// computed by `slice(z)` on the machine's threads.
template <typename Value>
Picture volumeAtlas(int size, int columns, const std::function<std::vector<Value>(int)>& slice,
                    const std::function<glm::vec4(Value)>& texel) {
  const int rows = (size + columns - 1) / columns;
  Picture atlas{std::uint32_t(size * columns), std::uint32_t(size * rows)};
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t) {
    workers.emplace_back([&, t] {
      for (int z = int(t); z < size; z += int(threads)) {
        const std::vector<Value> values = slice(z);
        const int originX = (z % columns) * size;
        const int originY = (z / columns) * size;
        for (int y = 0; y < size; ++y) {
          for (int x = 0; x < size; ++x) {
            atlas.set(std::uint32_t(originX + x), std::uint32_t(originY + y),
                      texel(values[std::size_t(y) * std::size_t(size) + std::size_t(x)]));
          }
        }
      }
    });
  }
  for (std::thread& worker : workers) worker.join();
  return atlas;
}

Picture squareMap(int size, const std::function<glm::vec4(std::size_t)>& texel) {
  Picture map{std::uint32_t(size), std::uint32_t(size)};
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      map.set(std::uint32_t(x), std::uint32_t(y),
              texel(std::size_t(y) * std::size_t(size) + std::size_t(x)));
    }
  }
  return map;
}

glm::vec4 grey(float v) {
  return {v, v, v, 1.0f};
}

void generate(const Options& options) {
  const fs::path& out = options.out;
  const std::uint32_t seed = options.seed;
  volumeAtlas<float>(
      clouds::kShapeNoiseTexels, 16, [&](int z) { return clouds::shapeNoiseSlice(seed, z); }, grey)
      .write(out / "shape_noise");
  volumeAtlas<float>(
      clouds::kDetailNoiseTexels, 8, [&](int z) { return clouds::detailNoiseSlice(seed, z); }, grey)
      .write(out / "detail_noise");
  volumeAtlas<glm::vec4>(
      clouds::kHeroNoiseTexels, 16, [&](int z) { return clouds::heroNoiseSlice(seed, z); },
      [](glm::vec4 v) { return v; })
      .write(out / "hero_noise");
  const std::vector<glm::vec2> curl = clouds::curlNoise(seed);
  squareMap(clouds::kCurlNoiseTexels, [&](std::size_t i) {
    return glm::vec4(curl[i], 0.0f, 1.0f);
  }).write(out / "curl_noise");

  const clouds::Settings defaults;
  const float phase = clouds::proceduralWeatherPhase(defaults, options.timeSeconds);
  const std::vector<glm::vec4> weather = clouds::proceduralWeatherMap(seed, phase);
  squareMap(clouds::kWeatherMapTexels, [&](std::size_t i) {
    return weather[i];
  }).write(out / "weather_map");
  std::string stateList;
  for (const clouds::WeatherPreset preset : options.states) {
    const clouds::Settings settings = clouds::withWeather(defaults, clouds::weatherPreset(preset));
    const std::string name = clouds::weatherPresetName(preset);
    squareMap(clouds::kWeatherMapTexels, [&](std::size_t i) {
      return clouds::weatherAsMarched(weather[i], settings);
    }).write(out / ("weather_" + name));
    stateList += (stateList.empty() ? "\"" : ", \"") + name + "\"";
  }
  if (!options.regions.empty()) {
    const clouds::Settings around =
        options.around ? clouds::withWeather(defaults, clouds::weatherPreset(*options.around))
                       : defaults;
    // Texel centres of the tile whose corner is the world's origin, x along u, z along v.
    const double texelMetres = double(defaults.weatherTileMetres) / clouds::kWeatherMapTexels;
    squareMap(clouds::kWeatherMapTexels, [&](std::size_t i) {
      const glm::dvec2 xz(double(i % clouds::kWeatherMapTexels) + 0.5,
                          double(i / clouds::kWeatherMapTexels) + 0.5);
      return clouds::weatherAsMarched(weather[i], around, options.regions, xz * texelMetres);
    }).write(out / "weather_regions");
  }

  std::ofstream manifest(out / "textures.json");
  manifest
      << "{\n  \"seed\": " << seed << ",\n  \"timeSeconds\": " << options.timeSeconds
      << ",\n  \"weatherPhase\": " << phase << ",\n"
      << "  \"shape_noise\": {\"size\": 128, \"atlasColumns\": 16, \"channels\": "
         "\"RGB the shape value\"},\n"
      << "  \"detail_noise\": {\"size\": 32, \"atlasColumns\": 8, \"channels\": "
         "\"RGB the detail value\"},\n"
      << "  \"hero_noise\": {\"size\": 128, \"atlasColumns\": 16, \"channels\": "
         "\"RG curly alligator low/high, BA alligator low/high\"},\n"
      << "  \"curl_noise\": {\"size\": 128, \"channels\": \"RG 0.5 + 0.5 curl\"},\n"
      << "  \"weather_map\": {\"size\": 512, \"channels\": \"R coverage, G type, B density "
         "(raw: what the module generates and a painted map holds)\"},\n"
      << "  \"weather_states\": [" << stateList
      << "],\n  \"weather_state_channels\": \"R coverage, G type, B density as marched\",\n"
      << "  \"weather_regions\": " << options.regions.size()
      << ",\n  \"weather_regions_tile\": \"x along u, z along v, from the world's origin\"\n}\n";
  if (!manifest) throw engine::Error(out.string() + "/textures.json: cannot write");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parseOptions(argc, argv);
    generate(options);
    std::printf("clouds_textures: wrote %s\n", options.out.string().c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
