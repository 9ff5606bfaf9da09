#pragma once
// Captures the engine log's warnings for the life of the object (a test's scope), and puts
// the previous sink back after.
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/log.h"

namespace test {

class LogCapture {
 public:
  LogCapture() {
    previous_ = engine::log::setSink([this](engine::log::Level level, std::string_view message) {
      if (level == engine::log::Level::Warning) warnings.emplace_back(message);
    });
  }
  ~LogCapture() { engine::log::setSink(std::move(previous_)); }
  LogCapture(const LogCapture&) = delete;
  LogCapture& operator=(const LogCapture&) = delete;
  std::vector<std::string> warnings;

 private:
  engine::log::Sink previous_;
};

}  // namespace test
