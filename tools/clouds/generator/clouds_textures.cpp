// clouds_textures: writes the clouds module's procedural textures as PNG (8 bits, the bytes the
// module's images hold) and EXR (the unrounded values), computed on the CPU by the module's own
// texel functions (clouds/procedural_textures.h), so artists can inspect them and paint over
// the weather map (a painted map goes back through FrameInputs::weatherView, or a scene's
// "weatherMap").
//
// Usage: clouds_textures --out DIR [--seed N] [--time SECONDS] [--state NAME]...
//   --seed   the module's CreateInfo::noiseSeed (default 1)
//   --time   the clock of the weather map (FrameInputs::timeSeconds, default 0)
//   --state  a built-in weather state to write the marched weather of (sparse, cloudy,
//            overcast, stormy; repeatable; default all four)
// Writes into DIR: shape_noise, detail_noise, hero_noise (volumes as atlases of z slices, left
// to right then top to bottom), curl_noise, weather_map (what to paint over) and
// weather_<state> (the map as the march reads it under the state), each .png and .exr, and
// textures.json describing them.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
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
};

[[noreturn]] void usageError(const std::string& message) {
  throw engine::Error("clouds_textures: " + message +
                      "\nusage: clouds_textures --out DIR [--seed N] [--time SECONDS] "
                      "[--state sparse|cloudy|overcast|stormy]...");
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
      clouds::WeatherPreset preset{};
      if (!clouds::parseWeatherPreset(value, &preset)) {
        usageError("--state " + value + ": not sparse, cloudy, overcast or stormy");
      }
      options.states.push_back(preset);
    } else {
      usageError("unknown option " + flag);
    }
  }
  if (options.out.empty()) usageError("--out DIR is required");
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

  std::ofstream manifest(out / "textures.json");
  manifest << "{\n  \"seed\": " << seed << ",\n  \"timeSeconds\": " << options.timeSeconds
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
           << "],\n  \"weather_state_channels\": \"R coverage, G type, B density as marched\"\n}\n";
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
