# Smoke test of the accuracy-versus-cost benchmark: a tiny run with Vulkan validation must
# finish cleanly (clouds_bench exits non-zero on a validation message or an implausible
# measurement) and write every output, with a CSV row per configuration and view.
# Inputs: BENCH (the executable), OUT_DIR.
file(REMOVE_RECURSE "${OUT_DIR}")
execute_process(
  COMMAND "${BENCH}" "${OUT_DIR}" --validation --width 64 --height 36 --converge-frames 2
          --timed-frames 1 --reference-frames 1 --fly-frames 12
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "clouds_bench exited with ${result}")
endif()
foreach(output results.csv results.md plots.json plot_static.png plot_fly_through.png
       plot_shadow.png)
  if(NOT EXISTS "${OUT_DIR}/${output}")
    message(FATAL_ERROR "clouds_bench wrote no ${OUT_DIR}/${output}")
  endif()
endforeach()
# 20 configurations (the presets, the knobs, High timed again) on 6 static views and the
# fly-through, plus the header; 16 shadow-map configurations on its 2 views.
file(STRINGS "${OUT_DIR}/results.csv" rows)
list(LENGTH rows row_count)
if(row_count LESS 173)
  message(FATAL_ERROR "results.csv has ${row_count} lines, expected at least 173")
endif()
file(READ "${OUT_DIR}/results.md" report)
if(NOT report MATCHES "Timing noise: High timed twice")
  message(FATAL_ERROR "results.md does not state the run's timing noise")
endif()
if(NOT report MATCHES "## The cloud shadow map")
  message(FATAL_ERROR "results.md has no cloud shadow map section")
endif()
if(NOT report MATCHES "## Hero clouds: seed 002's optimisation ladder")
  message(FATAL_ERROR "results.md has no hero clouds' ladder section")
endif()
