#pragma once
// Strict reading of one JSON object of a cloud recipe. Every accessor checks presence, type,
// finiteness and range, and throws std::runtime_error as "<file>: <field path>: <reason>"
// (e.g. "arch.cloud.json: primitives[2].radiusMetres: must be in (0, 100000], got -3");
// finish() rejects keys nobody read, so a misspelt optional key is an error, not a default.
// The tool links only the clouds module, GLM and nlohmann::json, hence its own small reader
// rather than the engine's.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <glm/glm.hpp>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace hero_clouds {

// A closed interval, or half-open at the bottom ("(0, 100]": strictly positive).
struct NumberRange {
  double min = 0.0;
  double max = 0.0;
  bool minExclusive = false;

  bool contains(double value) const;
  std::string describe() const;  // "[0, 1]" or "(0, 100000]"
};

// "%g" of a number as an error message shows it ("-3", "1e+30", "nan").
std::string formatNumber(double value);

class RecipeFields {
 public:
  // Reads `object`, found at `path` ("" for the root) of the file named `source`. Throws when
  // it is not a JSON object.
  RecipeFields(const nlohmann::json& object, std::string source, std::string path);

  bool has(const std::string& key) const;
  double number(const std::string& key, NumberRange range) const;
  double number(const std::string& key, NumberRange range, double fallback) const;
  glm::dvec3 vec3(const std::string& key, NumberRange range) const;
  // A non-empty array of [x, y, z] with [minCount, maxCount] entries.
  std::vector<glm::dvec3> vec3List(const std::string& key, NumberRange range, std::size_t minCount,
                                   std::size_t maxCount) const;
  // An array of exactly `count` numbers.
  std::vector<double> numberList(const std::string& key, NumberRange range,
                                 std::size_t count) const;
  // A string of 1 to maxLength characters.
  std::string string(const std::string& key, std::size_t maxLength) const;
  std::string string(const std::string& key, std::size_t maxLength,
                     const std::string& fallback) const;
  // An array of [minCount, maxCount] objects.
  std::vector<RecipeFields> objects(const std::string& key, std::size_t minCount,
                                    std::size_t maxCount) const;

  // Throws for the first key none of the accessors above asked for; `expected` lists the keys
  // this object takes, for the message.
  void finish(const std::string& expected) const;

  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;
  std::string pathOf(const std::string& key) const;
  const std::string& source() const { return source_; }

 private:
  const nlohmann::json& required(const std::string& key) const;

  const nlohmann::json* object_;
  std::string source_;
  std::string path_;
  mutable std::set<std::string> read_;
};

// Parses JSON text. A syntax error or an unrepresentable number (1e400) throws
// "<source>: <path of the value being read>: not valid JSON: <line, column and reason>".
nlohmann::json parseRecipeJson(std::string_view text, const std::string& source);

// Throws "<source>: <path>: <reason>" (or "<source>: <reason>" for an empty path).
[[noreturn]] void failAt(const std::string& source, const std::string& path,
                         const std::string& reason);

}  // namespace hero_clouds
