#pragma once
// Minimal leveled logging to stderr with a replaceable sink (tests capture messages).
#include <functional>
#include <string_view>

namespace engine::log {

enum class Level { Debug, Info, Warning, Error };

using Sink = std::function<void(Level, std::string_view)>;

// Replaces the sink; returns the previous one. An empty sink restores stderr output.
Sink setSink(Sink sink);
void setMinimumLevel(Level level);

void write(Level level, std::string_view message);
inline void debug(std::string_view m) {
  write(Level::Debug, m);
}
inline void info(std::string_view m) {
  write(Level::Info, m);
}
inline void warning(std::string_view m) {
  write(Level::Warning, m);
}
inline void error(std::string_view m) {
  write(Level::Error, m);
}

}  // namespace engine::log
