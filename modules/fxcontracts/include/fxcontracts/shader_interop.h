// The shared GLSL/C++ preamble of an effect module's shader headers. A header that includes it
// compiles both as GLSL (the module's compute shaders) and as C++ (its host code, its CPU
// reference and its tests), so each model has exactly one definition. Shaders find it with the
// kit's include folder on their include path (vkfx_embed_shaders adds it).
//
// Writing shared code: GLSL built-ins that GLM also has (mix, clamp, exp, dot, ...);
// IN(T) / OUT(T) / INOUT(T) for parameters; no arrays, no struct constructors, no bool in GPU
// structs (use uint), and no texture access: shaders and CPU code each implement the fetch
// prototypes a module declares. In C++ the code lives in the namespace given to
// FX_SHADER_BEGIN, with GLM's types and functions.
#ifndef FX_SHADER_INTEROP_H
#define FX_SHADER_INTEROP_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define FX_SHADER_BEGIN(ns) \
  namespace ns {            \
  using namespace glm;      \
  using uint = std::uint32_t;
#define FX_SHADER_END }
#define FX_STATIC_ASSERT(condition) static_assert(condition, #condition)
#define FX_INLINE inline
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
#else
#define FX_SHADER_BEGIN(ns)
#define FX_SHADER_END
#define FX_STATIC_ASSERT(condition)
#define FX_INLINE
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#endif

#endif
