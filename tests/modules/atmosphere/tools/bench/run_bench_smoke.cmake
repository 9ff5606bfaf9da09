# Smoke test of the atmosphere's accuracy-versus-cost benchmark: a tiny run with Vulkan
# validation must finish cleanly (atmosphere_bench exits non-zero on a validation message or a
# measurement that is not a number) and write every output, with a CSV row per configuration
# and view.
# Inputs: BENCH (the executable), OUT_DIR.
file(REMOVE_RECURSE "${OUT_DIR}")
execute_process(
  COMMAND "${BENCH}" "${OUT_DIR}" --validation --width 64 --height 36 --rounds 1
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "atmosphere_bench exited with ${result}")
endif()
foreach(output results.csv results.md plots.json plot.png)
  if(NOT EXISTS "${OUT_DIR}/${output}")
    message(FATAL_ERROR "atmosphere_bench wrote no ${OUT_DIR}/${output}")
  endif()
endforeach()
# 31 configurations on 5 views, plus the header.
file(STRINGS "${OUT_DIR}/results.csv" rows)
list(LENGTH rows row_count)
if(row_count LESS 156)
  message(FATAL_ERROR "results.csv has ${row_count} lines, expected at least 156")
endif()
