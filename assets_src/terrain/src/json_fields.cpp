#include "json_fields.h"

#include <algorithm>
#include <sstream>

#include "engine/core/error.h"

namespace terrain {
namespace {

// Shows the offending value in the message, shortened so a huge array does not flood it.
std::string shown(const nlohmann::json& value) {
  std::string text = value.dump();
  constexpr std::size_t kMaxChars = 40;
  if (text.size() > kMaxChars) text = text.substr(0, kMaxChars) + "...";
  return std::string(value.type_name()) + " " + text;
}

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

JsonFields::JsonFields(const nlohmann::json& object, std::string file, std::string path,
                       std::vector<std::string> keys)
    : object_(object), file_(std::move(file)), path_(std::move(path)) {
  const std::string what = path_.empty() ? std::string("top level") : path_;
  if (!object_.is_object()) {
    throw engine::Error(file_ + ": " + what + ": must be a JSON object, got " + shown(object_));
  }
  for (const auto& item : object_.items()) {
    if (std::find(keys.begin(), keys.end(), item.key()) != keys.end()) continue;
    std::string known;
    for (const std::string& k : keys) known += (known.empty() ? "" : ", ") + k;
    throw engine::Error(where(item.key()) + ": unknown key (expected one of: " + known + ")");
  }
}

std::string JsonFields::where(const std::string& key) const {
  return file_ + ": " + (path_.empty() ? key : path_ + "." + key);
}

const nlohmann::json& JsonFields::field(const std::string& key) {
  const auto it = object_.find(key);
  if (it == object_.end()) throw engine::Error(where(key) + ": missing (every field is required)");
  return *it;
}

double JsonFields::number(const std::string& key, double min, double max) {
  const nlohmann::json& value = field(key);
  const std::string range = "[" + formatNumber(min) + ", " + formatNumber(max) + "]";
  if (!value.is_number()) {
    throw engine::Error(where(key) + ": must be a number in " + range + ", got " + shown(value));
  }
  const double v = value.get<double>();
  if (!(v >= min && v <= max)) {
    throw engine::Error(where(key) + ": must be a number in " + range + ", got " + value.dump());
  }
  return v;
}

std::int64_t JsonFields::integer(const std::string& key, std::int64_t min, std::int64_t max) {
  const nlohmann::json& value = field(key);
  const std::string expected =
      "must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "], got ";
  if (!value.is_number_integer()) throw engine::Error(where(key) + ": " + expected + shown(value));
  // Unsigned JSON integers above INT64_MAX are out of every range this tool accepts.
  if (value.is_number_unsigned() &&
      value.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX)) {
    throw engine::Error(where(key) + ": " + expected + value.dump());
  }
  const std::int64_t v = value.get<std::int64_t>();
  if (v < min || v > max) throw engine::Error(where(key) + ": " + expected + value.dump());
  return v;
}

glm::vec3 JsonFields::linearRgb(const std::string& key) {
  const nlohmann::json& value = field(key);
  const std::string expected = "must be a linear RGB array of three numbers in [0, 1], got ";
  if (!value.is_array() || value.size() != 3) {
    throw engine::Error(where(key) + ": " + expected + shown(value));
  }
  glm::vec3 colour(0.0f);
  for (glm::vec3::length_type i = 0; i < 3; ++i) {
    const nlohmann::json& c = value[static_cast<std::size_t>(i)];
    if (!c.is_number() || !(c.get<double>() >= 0.0 && c.get<double>() <= 1.0)) {
      throw engine::Error(where(key) + "[" + std::to_string(i) + "]: " + expected + shown(c));
    }
    colour[i] = c.get<float>();
  }
  return colour;
}

JsonFields JsonFields::object(const std::string& key, std::vector<std::string> keys) {
  const nlohmann::json& value = field(key);
  return JsonFields(value, file_, path_.empty() ? key : path_ + "." + key, std::move(keys));
}

}  // namespace terrain
