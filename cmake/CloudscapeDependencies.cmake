# Finds the Debian 12 packages the project builds against. tools/install_deps.sh installs them.
find_package(Threads REQUIRED)
find_package(Vulkan 1.3 REQUIRED)
find_package(glm REQUIRED)

if(NOT TARGET glm::glm)
  add_library(glm::glm INTERFACE IMPORTED)
  target_include_directories(glm::glm INTERFACE ${GLM_INCLUDE_DIRS})
endif()
# GLM: radians everywhere, depth range [0, 1] as Vulkan expects.
target_compile_definitions(glm::glm INTERFACE GLM_FORCE_DEPTH_ZERO_TO_ONE GLM_FORCE_RADIANS
                                               GLM_ENABLE_EXPERIMENTAL)

find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)

if(CLOUDSCAPE_BUILD_SAMPLE OR CLOUDSCAPE_BUILD_TESTS)
  find_package(glfw3 3.3 REQUIRED)
  find_package(TinyGLTF REQUIRED)
  # OpenImageIO through pkg-config: Debian's CMake package config references files from other
  # packages (/usr/bin/iconvert, the PyImath module, /usr/include/opencv4) and fails to load.
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(OpenImageIO REQUIRED IMPORTED_TARGET OpenImageIO)
  add_library(OpenImageIO::OpenImageIO ALIAS PkgConfig::OpenImageIO)
endif()

if(CLOUDSCAPE_BUILD_TESTS)
  find_package(GTest REQUIRED)
  find_package(benchmark QUIET)
endif()
