# The soak: 10,000 frames of the changing weather scene at 160x90 (time of day, wind, a weather
# schedule through every built-in state and lightning all running, 0.06 s a frame: ten simulated
# minutes, the schedule's 320 s cycle twice) with --soak-report, then the
# series checked: GPU memory and pipelines the same in every row, host memory grown by less than
# 4 MiB after the first 1,000 frames. The series is printed (frame time is reported, not held:
# a timed assertion would flake).
# Inputs: SAMPLE (the executable), SCENE, OUT_DIR.
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
set(report "${OUT_DIR}/soak.csv")
execute_process(
  COMMAND "${SAMPLE}" --headless --frames 10000 --fixed-dt 0.06 --width 160 --height 90
          --scene "${SCENE}" --soak-report "${report}"
  RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "sample_game exited with ${result}")
endif()
file(STRINGS "${report}" rows)
list(POP_FRONT rows header)
list(LENGTH rows count)
if(NOT count EQUAL 40)
  message(FATAL_ERROR "${report}: ${count} rows, expected 40 (one per 250 frames)")
endif()
message(STATUS "soak series (${header}):")
set(first_gpu "")
set(first_pipelines "")
set(settled_rss "")
set(max_rss 0)
set(index 0)
foreach(row IN LISTS rows)
  message(STATUS "  ${row}")
  string(REPLACE "," ";" fields "${row}")
  list(GET fields 0 frame)
  list(GET fields 2 rss)
  list(GET fields 3 gpu)
  list(GET fields 4 pipelines)
  if(index EQUAL 0)
    set(first_gpu ${gpu})
    set(first_pipelines ${pipelines})
  endif()
  if(NOT gpu EQUAL first_gpu)
    message(FATAL_ERROR "frame ${frame}: GPU memory ${gpu} bytes, ${first_gpu} at the start")
  endif()
  if(NOT pipelines EQUAL first_pipelines)
    message(FATAL_ERROR "frame ${frame}: ${pipelines} pipelines, ${first_pipelines} at the start")
  endif()
  if(index EQUAL 3)
    set(settled_rss ${rss})  # after 1,000 frames
  endif()
  if(index GREATER 3 AND rss GREATER max_rss)
    set(max_rss ${rss})
  endif()
  math(EXPR index "${index} + 1")
endforeach()
math(EXPR growth "${max_rss} - ${settled_rss}")
message(STATUS "host memory grew ${growth} KiB after the first 1,000 frames")
if(growth GREATER 4096)
  message(FATAL_ERROR "host memory grew ${growth} KiB after the first 1,000 frames (bar 4096)")
endif()
