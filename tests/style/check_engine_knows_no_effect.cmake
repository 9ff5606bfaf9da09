# The engine knows no effect (the design brief: "adding an effect never edits engine/"): no file
# under engine/ names the effect modules or what they hand each other. Effects exchange their
# per-frame values through the frame graph's blackboard in types the engine does not define.
# Fails naming each file and line. Run with -DSOURCE_DIR=<repository root>.
file(GLOB_RECURSE files LIST_DIRECTORIES false
     ${SOURCE_DIR}/engine/*.h ${SOURCE_DIR}/engine/*.cpp ${SOURCE_DIR}/engine/*.glsl
     ${SOURCE_DIR}/engine/*.vert ${SOURCE_DIR}/engine/*.frag ${SOURCE_DIR}/engine/*.comp
     ${SOURCE_DIR}/engine/*.txt ${SOURCE_DIR}/engine/*.md)
# Case-insensitive by lowering each line; "cloudscape" (the project's name) is allowed.
set(words "cloud" "haze" "aerial" "vkfx" "god ray" "godray" "lightning" "atmosphere module")
set(found "")
foreach(file IN LISTS files)
  file(STRINGS ${file} lines)
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    string(TOLOWER "${line}" lower)
    string(REPLACE "cloudscape" "" lower "${lower}")
    foreach(word IN LISTS words)
      string(FIND "${lower}" "${word}" at)
      if(NOT at EQUAL -1)
        file(RELATIVE_PATH relative ${SOURCE_DIR} ${file})
        string(APPEND found "  ${relative}:${number}: names '${word}': ${line}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "engine/ names an effect of the modules:\n${found}")
endif()
list(LENGTH files count)
message(STATUS "engine/: ${count} files, none names an effect")
