#include "engine/core/error.h"

namespace engine {

void require(bool condition, const std::string& context, const std::string& message) {
  if (!condition) throw Error(context + ": " + message);
}

}  // namespace engine
