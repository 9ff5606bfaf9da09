#include "engine/core/log.h"

#include <cstdio>
#include <mutex>

namespace engine::log {
namespace {

std::mutex& sinkMutex() {
  static std::mutex mutex;
  return mutex;
}
Sink& currentSink() {
  static Sink sink;
  return sink;
}
Level& minimumLevel() {
  static Level level = Level::Info;
  return level;
}

const char* levelName(Level level) {
  switch (level) {
    case Level::Debug:
      return "debug";
    case Level::Info:
      return "info";
    case Level::Warning:
      return "warning";
    case Level::Error:
      return "error";
  }
  return "?";
}

}  // namespace

Sink setSink(Sink sink) {
  std::lock_guard lock(sinkMutex());
  Sink previous = std::move(currentSink());
  currentSink() = std::move(sink);
  return previous;
}

void setMinimumLevel(Level level) {
  std::lock_guard lock(sinkMutex());
  minimumLevel() = level;
}

void write(Level level, std::string_view message) {
  std::lock_guard lock(sinkMutex());
  if (level < minimumLevel()) return;
  if (currentSink()) {
    currentSink()(level, message);
    return;
  }
  std::fprintf(stderr, "[%s] %.*s\n", levelName(level), static_cast<int>(message.size()),
               message.data());
}

}  // namespace engine::log
