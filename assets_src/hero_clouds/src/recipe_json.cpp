#include "recipe_json.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace hero_clouds {
namespace {

std::string indexPath(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

// The JSON type as an author would name it, for "must be a number, got string".
std::string typeName(const nlohmann::json& value) {
  return value.type_name();
}

double checkedNumber(const nlohmann::json& value, NumberRange range, const std::string& source,
                     const std::string& path) {
  if (!value.is_number()) failAt(source, path, "must be a number, got " + typeName(value));
  const double number = value.get<double>();
  // nlohmann::json never yields a non-finite number from text, but say so plainly if it does.
  if (!std::isfinite(number)) failAt(source, path, "must be finite, got " + formatNumber(number));
  if (!range.contains(number)) {
    failAt(source, path, "must be in " + range.describe() + ", got " + formatNumber(number));
  }
  return number;
}

const nlohmann::json& checkedArray(const nlohmann::json& value, std::size_t minCount,
                                   std::size_t maxCount, const std::string& source,
                                   const std::string& path) {
  if (!value.is_array()) failAt(source, path, "must be an array, got " + typeName(value));
  if (value.size() < minCount || value.size() > maxCount) {
    const std::string count = minCount == maxCount
                                  ? std::to_string(minCount)
                                  : std::to_string(minCount) + " to " + std::to_string(maxCount);
    failAt(source, path, "must have " + count + " entries, got " + std::to_string(value.size()));
  }
  return value;
}

glm::dvec3 checkedVec3(const nlohmann::json& value, NumberRange range, const std::string& source,
                       const std::string& path) {
  if (!value.is_array() || value.size() != 3) {
    failAt(source, path, "must be an array of 3 numbers [x, y, z]");
  }
  glm::dvec3 v{0.0};
  for (std::size_t i = 0; i < 3; ++i) {
    v[static_cast<glm::length_t>(i)] = checkedNumber(value[i], range, source, indexPath(path, i));
  }
  return v;
}

// Follows the parse through nlohmann::json's callback events, so that an error can say which
// value it was in: "primitives[2].radiusMetres" rather than only a line and column.
class JsonPathTracker {
 public:
  bool onEvent(nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
        frames_.push_back({false, {}, 0});
        break;
      case Event::array_start:
        frames_.push_back({true, {}, 0});
        break;
      case Event::key:
        if (!frames_.empty()) frames_.back().key = parsed.get<std::string>();
        break;
      case Event::object_end:
      case Event::array_end:
        if (!frames_.empty()) frames_.pop_back();
        elementDone();
        break;
      case Event::value:
        elementDone();
        break;
    }
    return true;  // keep every value
  }

  std::string path() const {
    std::string p;
    for (const Frame& frame : frames_) {
      if (frame.isArray) {
        p = indexPath(p, frame.index);
      } else if (!frame.key.empty()) {
        p += (p.empty() ? "" : ".") + frame.key;
      }
    }
    return p;
  }

 private:
  struct Frame {
    bool isArray = false;
    std::string key;        // of an object: the key last read
    std::size_t index = 0;  // of an array: the element being read
  };

  void elementDone() {
    if (!frames_.empty() && frames_.back().isArray) ++frames_.back().index;
  }

  std::vector<Frame> frames_;
};

// "[json.exception.parse_error.101] parse error at line 3, ..." without the library's tag.
std::string withoutExceptionTag(const std::string& what) {
  const std::size_t tagEnd = what.find("] ");
  return what.starts_with("[json.exception.") && tagEnd != std::string::npos
             ? what.substr(tagEnd + 2)
             : what;
}

}  // namespace

nlohmann::json parseRecipeJson(std::string_view text, const std::string& source) {
  JsonPathTracker tracker;
  const nlohmann::json::parser_callback_t follow =
      [&tracker](int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        return tracker.onEvent(event, parsed);
      };
  try {
    return nlohmann::json::parse(text, follow);
  } catch (const nlohmann::json::exception& e) {
    failAt(source, tracker.path(), "not valid JSON: " + withoutExceptionTag(e.what()));
  }
}

bool NumberRange::contains(double value) const {
  const bool aboveMin = minExclusive ? value > min : value >= min;
  return aboveMin && value <= max;
}

std::string NumberRange::describe() const {
  return (minExclusive ? "(" : "[") + formatNumber(min) + ", " + formatNumber(max) + "]";
}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void failAt(const std::string& source, const std::string& path, const std::string& reason) {
  throw std::runtime_error(path.empty() ? source + ": " + reason
                                        : source + ": " + path + ": " + reason);
}

RecipeFields::RecipeFields(const nlohmann::json& object, std::string source, std::string path)
    : object_(&object), source_(std::move(source)), path_(std::move(path)) {
  if (!object.is_object()) {
    failAt(source_, path_, "must be a JSON object, got " + typeName(object));
  }
}

std::string RecipeFields::pathOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void RecipeFields::fail(const std::string& key, const std::string& reason) const {
  failAt(source_, pathOf(key), reason);
}

bool RecipeFields::has(const std::string& key) const {
  return object_->contains(key);
}

const nlohmann::json& RecipeFields::required(const std::string& key) const {
  read_.insert(key);
  const auto found = object_->find(key);
  if (found == object_->end()) fail(key, "missing (required)");
  return *found;
}

double RecipeFields::number(const std::string& key, NumberRange range) const {
  return checkedNumber(required(key), range, source_, pathOf(key));
}

double RecipeFields::number(const std::string& key, NumberRange range, double fallback) const {
  return has(key) ? number(key, range) : fallback;
}

glm::dvec3 RecipeFields::vec3(const std::string& key, NumberRange range) const {
  return checkedVec3(required(key), range, source_, pathOf(key));
}

std::vector<glm::dvec3> RecipeFields::vec3List(const std::string& key, NumberRange range,
                                               std::size_t minCount, std::size_t maxCount) const {
  const nlohmann::json& list =
      checkedArray(required(key), minCount, maxCount, source_, pathOf(key));
  std::vector<glm::dvec3> values;
  for (std::size_t i = 0; i < list.size(); ++i) {
    values.push_back(checkedVec3(list[i], range, source_, indexPath(pathOf(key), i)));
  }
  return values;
}

std::vector<double> RecipeFields::numberList(const std::string& key, NumberRange range,
                                             std::size_t count) const {
  const nlohmann::json& list = checkedArray(required(key), count, count, source_, pathOf(key));
  std::vector<double> values;
  for (std::size_t i = 0; i < list.size(); ++i) {
    values.push_back(checkedNumber(list[i], range, source_, indexPath(pathOf(key), i)));
  }
  return values;
}

std::string RecipeFields::string(const std::string& key, std::size_t maxLength) const {
  const nlohmann::json& value = required(key);
  if (!value.is_string()) fail(key, "must be a string, got " + typeName(value));
  const std::string text = value.get<std::string>();
  if (text.empty() || text.size() > maxLength) {
    fail(key, "must have 1 to " + std::to_string(maxLength) + " characters, got " +
                  std::to_string(text.size()));
  }
  return text;
}

std::string RecipeFields::string(const std::string& key, std::size_t maxLength,
                                 const std::string& fallback) const {
  return has(key) ? string(key, maxLength) : fallback;
}

std::vector<RecipeFields> RecipeFields::objects(const std::string& key, std::size_t minCount,
                                                std::size_t maxCount) const {
  const nlohmann::json& list =
      checkedArray(required(key), minCount, maxCount, source_, pathOf(key));
  std::vector<RecipeFields> entries;
  for (std::size_t i = 0; i < list.size(); ++i) {
    entries.emplace_back(list[i], source_, indexPath(pathOf(key), i));
  }
  return entries;
}

void RecipeFields::finish(const std::string& expected) const {
  for (const auto& [key, value] : object_->items()) {
    if (!read_.contains(key)) fail(key, "unknown key (expected " + expected + ")");
  }
}

}  // namespace hero_clouds
