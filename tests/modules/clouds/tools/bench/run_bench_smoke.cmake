# Smoke test of the accuracy-versus-cost benchmark: a tiny run with Vulkan validation must
# finish cleanly (clouds_bench exits non-zero on a validation message or an implausible
# measurement) and write every output, with a CSV row per configuration and view.
# Inputs: BENCH (the executable), OUT_DIR.
#
# Compiling a configuration's pipelines under validation takes most of the time (about 9 s each
# with GPU-assisted validation on lavapipe, again for each shadow-map view), so the smoke runs the
# configurations whose passes differ, not every value of a knob: the presets (each has its own
# pipelines: the march, the upsampling and the shadow map's at their own resolutions), High timed
# again (the timing-noise statement) and the switches that take a pass or a history away.
file(REMOVE_RECURSE "${OUT_DIR}")
set(configs Low Medium High Ultra "High, timed again" "temporal reuse off"
            "temporal upsampling off" "trace scale 1" "edge rays off" "shadow resolution 64")
set(config_arguments)
foreach(config IN LISTS configs)
  list(APPEND config_arguments --config "${config}")
endforeach()
execute_process(
  COMMAND "${BENCH}" "${OUT_DIR}" --validation --width 64 --height 36 --converge-frames 2
          --upsampled-converge-frames 2 --timed-frames 1 --reference-frames 1 --fly-frames 12
          ${config_arguments}
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
# 9 configurations on 9 static views and the fly-through, the Reference on each, 5 shadow-map
# configurations (the presets and a resolution) on its 2 views, the hero clouds' ladder, and
# the header.
file(STRINGS "${OUT_DIR}/results.csv" rows)
list(LENGTH rows row_count)
if(row_count LESS 111)
  message(FATAL_ERROR "results.csv has ${row_count} lines, expected at least 111")
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
