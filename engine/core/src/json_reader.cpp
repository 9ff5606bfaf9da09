#include "engine/core/json_reader.h"

#include <cmath>
#include <sstream>

#include "engine/core/error.h"
#include "engine/core/file_io.h"

namespace engine {
namespace {

std::string describe(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::boolean:
      return "a boolean";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::object:
      return "an object";
    default:
      return "a number";
  }
}

std::string format(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

nlohmann::json JsonReader::parseFile(const std::filesystem::path& path) {
  const std::string text = readTextFile(path, std::size_t{16} << 20);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw Error(path.string() + ": not valid JSON (at byte " + std::to_string(e.byte) + ")");
  } catch (const nlohmann::json::out_of_range&) {
    // nlohmann throws this, not a parse_error, for a number no double holds (1e444). Found by
    // fuzz_scene and fuzz_input_script.
    throw Error(path.string() + ": not valid JSON: a number is too large for a double");
  }
}

JsonReader::JsonReader(const nlohmann::json& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {
  if (!value.is_object()) {
    throw Error(file_ + ": " + (path_.empty() ? std::string("(root)") : path_) +
                ": must be an object, got " + describe(value));
  }
}

std::string JsonReader::pathOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void JsonReader::fail(const std::string& key, const std::string& reason) const {
  throw Error(file_ + ": " + (key.empty() ? path_ : pathOf(key)) + ": " + reason);
}

std::vector<std::string> JsonReader::keys() const {
  std::vector<std::string> names;
  for (const auto& item : value_->items()) names.push_back(item.key());
  return names;
}

bool JsonReader::has(const std::string& key) const {
  return value_->contains(key);
}

const nlohmann::json& JsonReader::child(const std::string& key) const {
  read_.insert(key);
  const auto it = value_->find(key);
  if (it == value_->end()) fail(key, "is required");
  return *it;
}

JsonReader JsonReader::object(const std::string& key) const {
  const nlohmann::json& value = child(key);
  if (!value.is_object()) fail(key, "must be an object, got " + describe(value));
  return JsonReader(value, file_, pathOf(key));
}

std::vector<JsonReader> JsonReader::objects(const std::string& key) const {
  const nlohmann::json& value = child(key);
  if (!value.is_array()) fail(key, "must be an array, got " + describe(value));
  std::vector<JsonReader> readers;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string path = pathOf(key) + "[" + std::to_string(i) + "]";
    if (!value[i].is_object()) {
      throw Error(file_ + ": " + path + ": must be an object, got " + describe(value[i]));
    }
    readers.emplace_back(value[i], file_, path);
  }
  return readers;
}

double JsonReader::number(const std::string& key, double min, double max) const {
  const nlohmann::json& value = child(key);
  if (!value.is_number()) fail(key, "must be a number, got " + describe(value));
  const double v = value.get<double>();
  if (!std::isfinite(v) || v < min || v > max) {
    fail(key, "must be in [" + format(min) + ", " + format(max) + "], got " + format(v));
  }
  return v;
}

double JsonReader::number(const std::string& key, double min, double max, double fallback) const {
  return has(key) ? number(key, min, max) : fallback;
}

std::int64_t JsonReader::integer(const std::string& key, std::int64_t min, std::int64_t max) const {
  const nlohmann::json& value = child(key);
  if (!value.is_number_integer()) fail(key, "must be an integer, got " + describe(value));
  // Unsigned values past INT64_MAX would wrap to negative numbers in get<int64_t>().
  if (value.is_number_unsigned() &&
      value.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX)) {
    fail(key, "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                  std::to_string(value.get<std::uint64_t>()));
  }
  const std::int64_t v = value.get<std::int64_t>();
  if (v < min || v > max) {
    fail(key, "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                  std::to_string(v));
  }
  return v;
}

std::int64_t JsonReader::integer(const std::string& key, std::int64_t min, std::int64_t max,
                                 std::int64_t fallback) const {
  return has(key) ? integer(key, min, max) : fallback;
}

bool JsonReader::boolean(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& value = child(key);
  if (!value.is_boolean()) fail(key, "must be true or false, got " + describe(value));
  return value.get<bool>();
}

std::string JsonReader::string(const std::string& key) const {
  const nlohmann::json& value = child(key);
  if (!value.is_string()) fail(key, "must be a string, got " + describe(value));
  return value.get<std::string>();
}

std::string JsonReader::string(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

std::filesystem::path JsonReader::existingFile(const std::string& key,
                                               const std::filesystem::path& directory) const {
  const std::filesystem::path path = directory / string(key);
  if (!std::filesystem::is_regular_file(path)) fail(key, "file not found: " + path.string());
  return path;
}

std::string JsonReader::choice(const std::string& key, const std::vector<std::string>& allowed,
                               const std::string& fallback) const {
  if (!has(key)) return fallback;
  const std::string value = string(key);
  for (const auto& a : allowed) {
    if (a == value) return value;
  }
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  fail(key, "must be one of " + list + ", got \"" + value + "\"");
}

std::vector<double> JsonReader::numbers(const std::string& key, std::size_t count, double min,
                                        double max) const {
  const nlohmann::json& value = child(key);
  if (!value.is_array() || value.size() != count) {
    fail(key, "must be an array of " + std::to_string(count) + " numbers, got " + describe(value));
  }
  std::vector<double> v(count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto& e = value[i];
    if (!e.is_number()) fail(key, "element " + std::to_string(i) + " must be a number");
    v[i] = e.get<double>();
    if (!std::isfinite(v[i]) || v[i] < min || v[i] > max) {
      fail(key, "element " + std::to_string(i) + " must be in [" + format(min) + ", " +
                    format(max) + "], got " + format(v[i]));
    }
  }
  return v;
}

glm::dvec2 JsonReader::vec2(const std::string& key, double min, double max) const {
  const std::vector<double> v = numbers(key, 2, min, max);
  return {v[0], v[1]};
}

glm::dvec3 JsonReader::vec3(const std::string& key, double min, double max) const {
  const std::vector<double> v = numbers(key, 3, min, max);
  return {v[0], v[1], v[2]};
}

glm::dvec3 JsonReader::vec3(const std::string& key, double min, double max,
                            const glm::dvec3& fallback) const {
  return has(key) ? vec3(key, min, max) : fallback;
}

std::vector<std::string> JsonReader::strings(const std::string& key) const {
  const nlohmann::json& value = child(key);
  if (!value.is_array()) fail(key, "must be an array of strings, got " + describe(value));
  std::vector<std::string> out;
  for (const auto& e : value) {
    if (!e.is_string()) fail(key, "must contain only strings");
    out.push_back(e.get<std::string>());
  }
  return out;
}

void JsonReader::finish() const {
  for (const auto& [key, value] : value_->items()) {
    (void)value;
    if (read_.count(key) == 0) fail(key, "unknown key");
  }
}

}  // namespace engine
