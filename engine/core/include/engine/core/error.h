#pragma once
// Load-time errors. Setup code (files, scenes, assets, device creation) throws engine::Error
// with a message that names the file and field at fault; per-frame code never throws.
#include <stdexcept>
#include <string>

namespace engine {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// Throws engine::Error("<context>: <message>") when `condition` is false.
void require(bool condition, const std::string& context, const std::string& message);

}  // namespace engine
