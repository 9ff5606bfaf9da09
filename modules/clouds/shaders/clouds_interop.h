// Shared GLSL/C++ preamble of the clouds module. Every header in this folder that includes it
// compiles both as GLSL (the module's compute shaders) and as C++ (the module's host code and
// its CPU reference renderer), so the cloud model has exactly one definition.
//
// Writing shared code: use float literals with an f suffix; GLSL built-ins that GLM also has
// (mix, clamp, exp, dot, ...); IN(T) / OUT(T) / INOUT(T) for parameters; no arrays, no struct
// constructors, no bool in GPU structs (use uint), and no texture access: shaders and the CPU
// reference each implement the texel-fetch prototypes declared in cloud_sampling.h.
#ifndef CLOUDS_INTEROP_H
#define CLOUDS_INTEROP_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define CLOUDS_SHADER_BEGIN  \
  namespace clouds::shader { \
  using namespace glm;       \
  using uint = std::uint32_t;
#define CLOUDS_SHADER_END }
#define CLOUDS_STATIC_ASSERT(condition) static_assert(condition, #condition)
#define CLOUDS_INLINE inline
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
#else
#define CLOUDS_SHADER_BEGIN
#define CLOUDS_SHADER_END
#define CLOUDS_STATIC_ASSERT(condition)
#define CLOUDS_INLINE
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#endif

#endif
