#pragma once
// Strict reading of JSON data files (scenes, scripts, asset parameters). Every accessor
// checks presence, type and range and throws engine::Error as
//   "<file>: <json path>: <reason>"     e.g. "scenes/noon.json: camera.fov: must be in [1, 179],
//   got 200"
// and finish() rejects keys nobody read (typos do not pass silently). Nothing is applied
// half-way: callers read everything into plain structs first.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace engine {

class JsonReader {
 public:
  // Parses a file; syntax errors name the file and the byte offset.
  static nlohmann::json parseFile(const std::filesystem::path& path);

  // Reads the object `value` found at `path` ("" for the root) of `file`.
  JsonReader(const nlohmann::json& value, std::string file, std::string path = {});

  bool has(const std::string& key) const;
  // The object's keys, sorted (for objects whose keys are names, not fields).
  std::vector<std::string> keys() const;
  // Child object reader; required unless has() was checked.
  JsonReader object(const std::string& key) const;
  // Array of objects.
  std::vector<JsonReader> objects(const std::string& key) const;

  double number(const std::string& key, double min, double max) const;
  double number(const std::string& key, double min, double max, double fallback) const;
  std::int64_t integer(const std::string& key, std::int64_t min, std::int64_t max) const;
  std::int64_t integer(const std::string& key, std::int64_t min, std::int64_t max,
                       std::int64_t fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  // One of `allowed`.
  std::string choice(const std::string& key, const std::vector<std::string>& allowed,
                     const std::string& fallback) const;
  glm::dvec2 vec2(const std::string& key, double min, double max) const;
  glm::dvec3 vec3(const std::string& key, double min, double max) const;
  glm::dvec3 vec3(const std::string& key, double min, double max, const glm::dvec3& fallback) const;
  std::vector<std::string> strings(const std::string& key) const;
  // A path relative to `directory` (a scene's folder) naming a file that exists.
  std::filesystem::path existingFile(const std::string& key,
                                     const std::filesystem::path& directory) const;

  // Throws when the object has a key none of the accessors above asked for.
  void finish() const;

  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;
  const std::string& file() const { return file_; }
  std::string pathOf(const std::string& key) const;

 private:
  const nlohmann::json& child(const std::string& key) const;
  // An array of `count` finite numbers in [min, max].
  std::vector<double> numbers(const std::string& key, std::size_t count, double min,
                              double max) const;

  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
  mutable std::set<std::string> read_;
};

}  // namespace engine
