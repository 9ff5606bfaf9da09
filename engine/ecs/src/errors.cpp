#include "engine/ecs/errors.h"

#include <string>

#include "engine/core/error.h"

namespace engine::ecs::detail {

void fail(std::string_view where, std::string_view type, std::string_view what) {
  std::string message(where);
  if (!type.empty()) {
    message += '<';
    message += type;
    message += '>';
  }
  message += ": ";
  message += what;
  throw engine::Error(message);
}

void failEntity(std::string_view where, std::string_view type, Entity entity,
                std::string_view what) {
  std::string detail = entity.isNull()
                           ? std::string("entity {null}")
                           : "entity {index " + std::to_string(entity.index) + ", generation " +
                                 std::to_string(entity.generation) + "}";
  detail += ' ';
  detail += what;
  fail(where, type, detail);
}

}  // namespace engine::ecs::detail
