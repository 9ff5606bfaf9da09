#include <gtest/gtest.h>

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

TEST(JsonReader, HugeUnsignedIntegersAreOutOfRangeNotWrapped) {
  const auto json = nlohmann::json::parse(R"({"seed": 18446744073709551615})");
  const JsonReader r(json, "t.json");
  EXPECT_EQ(errorOf([&] { r.integer("seed", 0, 4294967295); }),
            "t.json: seed: must be in [0, 4294967295], got 18446744073709551615");
}

TEST(JsonReader, SyntaxErrorsNameTheFile) {
  const auto path = std::filesystem::temp_directory_path() / "cloudscape_json_reader_bad.json";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs("{\"a\": 1,,}", f);
    std::fclose(f);
  }
  const std::string error = errorOf([&] { JsonReader::parseFile(path); });
  EXPECT_NE(error.find("cloudscape_json_reader_bad.json: not valid JSON"), std::string::npos)
      << error;
}

}  // namespace
