#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/error.h"
#include "engine/core/json_reader.h"

namespace {

using engine::JsonReader;

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const engine::Error& e) {
    return e.what();
  }
  return "";
}

TEST(JsonReader, ReadsTypedValuesWithDefaults) {
  const auto json = nlohmann::json::parse(
      R"({"a": 1.5, "n": 3, "flag": true, "name": "x", "v": [1, 2, 3], "child": {"k": 2}})");
  const JsonReader r(json, "f.json");
  EXPECT_DOUBLE_EQ(r.number("a", 0, 2), 1.5);
  EXPECT_EQ(r.integer("n", 0, 10), 3);
  EXPECT_TRUE(r.boolean("flag", false));
  EXPECT_EQ(r.string("name"), "x");
  EXPECT_EQ(r.vec3("v", 0, 5), glm::dvec3(1, 2, 3));
  EXPECT_DOUBLE_EQ(r.number("missing", 0, 1, 0.25), 0.25);
  const JsonReader child = r.object("child");
  EXPECT_EQ(child.integer("k", 0, 5), 2);
  child.finish();
  r.finish();
}

TEST(JsonReader, ErrorsNameFilePathAndReason) {
  const auto json = nlohmann::json::parse(
      R"({"clouds": {"coverage": 1.5, "type": "x", "typo": 1}, "list": [{"a": 1}, 5]})");
  const JsonReader r(json, "scene.json");
  EXPECT_EQ(errorOf([&] { r.object("clouds").number("coverage", 0, 1); }),
            "scene.json: clouds.coverage: must be in [0, 1], got 1.5");
  EXPECT_EQ(errorOf([&] { r.object("clouds").number("type", 0, 1); }),
            "scene.json: clouds.type: must be a number, got a string");
  EXPECT_EQ(errorOf([&] { r.object("camera"); }), "scene.json: camera: is required");
  EXPECT_EQ(errorOf([&] { r.objects("list"); }),
            "scene.json: list[1]: must be an object, got a number");
  EXPECT_EQ(errorOf([&] {
              const JsonReader c = r.object("clouds");
              c.number("coverage", 0, 2);
              c.string("type");
              c.finish();
            }),
            "scene.json: clouds.typo: unknown key");
  EXPECT_EQ(errorOf([&] { r.choice("missing", {"a"}, "a"); }), "");
}

// A file a scene names, relative to the scene's folder: found, or refused naming the key.
TEST(JsonReader, ExistingFilesAreFoundRelativeToAFolder) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "cloudscape_json_reader_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "map.png") << "";
  const auto json = nlohmann::json::parse(R"({"here": "map.png", "gone": "none.png"})");
  const JsonReader r(json, "scene.json");
  EXPECT_EQ(r.existingFile("here", dir), dir / "map.png");
  EXPECT_EQ(errorOf([&] { r.existingFile("gone", dir); }),
            "scene.json: gone: file not found: " + (dir / "none.png").string());
}

TEST(JsonReader, HugeUnsignedIntegersAreOutOfRangeNotWrapped) {
  const auto json = nlohmann::json::parse(R"({"seed": 18446744073709551615})");
  const JsonReader r(json, "t.json");
  EXPECT_EQ(errorOf([&] { r.integer("seed", 0, 4294967295); }),
            "t.json: seed: must be in [0, 4294967295], got 18446744073709551615");
}

// Writes `text` to a file in the temporary folder and returns parseFile()'s error for it.
std::string parseErrorOf(const char* name, const char* text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(text, f);
    std::fclose(f);
  }
  return errorOf([&] { JsonReader::parseFile(path); });
}

TEST(JsonReader, SyntaxErrorsNameTheFile) {
  const std::string error = parseErrorOf("cloudscape_json_reader_bad.json", "{\"a\": 1,,}");
  EXPECT_NE(error.find("cloudscape_json_reader_bad.json: not valid JSON"), std::string::npos)
      << error;
}

// A number beyond a double's range is refused like a syntax error (nlohmann throws another
// exception type for it, which once escaped as an uncaught std::exception: found by fuzzing).
TEST(JsonReader, NumbersBeyondADoubleNameTheFile) {
  const std::string error = parseErrorOf("cloudscape_json_reader_huge.json", "{\"a\": 1e444}");
  EXPECT_NE(error.find("cloudscape_json_reader_huge.json: not valid JSON: a number is too large"),
            std::string::npos)
      << error;
}

}  // namespace
