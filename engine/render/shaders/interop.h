// Shared GLSL/C++ preamble for engine shader headers. A header that includes it compiles both
// as GLSL (included by shaders) and as C++ (included by the code that fills its structs), so
// GPU structs and shader math have one definition. In C++ the types come from GLM.
// Rules for shared structs: std430-compatible, explicit padding, no bool (use uint), and a
// SHADER_STATIC_ASSERT on the size.
#ifndef ENGINE_SHADERS_INTEROP_H
#define ENGINE_SHADERS_INTEROP_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#define SHADER_NAMESPACE_BEGIN \
  namespace engine::shaders {  \
  using namespace glm;         \
  using uint = std::uint32_t;
#define SHADER_NAMESPACE_END }
#define SHADER_STATIC_ASSERT(condition) static_assert(condition, #condition)
#define SHADER_INLINE inline
#else
#define SHADER_NAMESPACE_BEGIN
#define SHADER_NAMESPACE_END
#define SHADER_STATIC_ASSERT(condition)
#define SHADER_INLINE
#endif

#endif
