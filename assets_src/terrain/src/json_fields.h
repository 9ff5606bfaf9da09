#pragma once
// Typed, range-checked reads from a JSON object whose errors name the file and the field path.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace terrain {

/// Reads the fields of one JSON object. The keys it may hold are given up front so that a typo is
/// reported as an unknown key (with the list of known ones) before it shows up as a missing one.
class JsonFields {
 public:
  /// `file` prefixes every message; `path` is the dotted path of this object ("" at top level).
  JsonFields(const nlohmann::json& object, std::string file, std::string path,
             std::vector<std::string> keys);

  double number(const std::string& key, double min, double max);
  std::int64_t integer(const std::string& key, std::int64_t min, std::int64_t max);
  /// A linear RGB colour: an array of three numbers in [0, 1].
  glm::vec3 linearRgb(const std::string& key);
  JsonFields object(const std::string& key, std::vector<std::string> keys);

  /// "<file>: <path.key>" for messages about a field this object holds.
  std::string where(const std::string& key) const;

 private:
  const nlohmann::json& field(const std::string& key);

  const nlohmann::json& object_;
  std::string file_;
  std::string path_;
};

}  // namespace terrain
