// The atmosphere model's preamble. Its headers compile as GLSL, in float, for the module's
// shaders, and as C++ in double precision, in namespace atmosphere::model, for the CPU
// reference and the host's sun transmittance (the same integrals, one definition). Scalars are
// `real`, vectors the GLSL names: in C++ they are GLM's double-precision types. Literals are
// written without a suffix (GLSL reads them as float, C++ as double).
#ifndef ATMOSPHERE_INTEROP_H
#define ATMOSPHERE_INTEROP_H

#include "fxcontracts/shader_interop.h"

#ifdef __cplusplus
#define ATMOSPHERE_MODEL_BEGIN  \
  namespace atmosphere::model { \
  using namespace glm;          \
  using real = double;          \
  using vec2 = glm::dvec2;      \
  using vec3 = glm::dvec3;      \
  using vec4 = glm::dvec4;      \
  using uint = std::uint32_t;
#define ATMOSPHERE_MODEL_END }
#else
#define real float
#define ATMOSPHERE_MODEL_BEGIN
#define ATMOSPHERE_MODEL_END
#endif

#endif
