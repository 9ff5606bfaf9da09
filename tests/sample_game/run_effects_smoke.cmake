# Smoke test of the effects benchmark (tools/effects_bench.py): a tiny run must finish and
# write a table with a row per effect, each saying what the scene without it lacks; the god
# rays' row names their pipelines and memory, and the terrain shadows' adds no memory; and
# lightning's cost is summed over the passes it changes; weather regions and a change of weather
# have their rows; the water's row names its pipeline; the HUD has its table too.
# Inputs: PYTHON, SCRIPT, SAMPLE (the executable), OUT_DIR.
file(REMOVE_RECURSE "${OUT_DIR}")
execute_process(
  COMMAND "${PYTHON}" "${SCRIPT}" "${OUT_DIR}" --sample "${SAMPLE}" --rounds 1 --frames 5
          --width 96 --height 54
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "effects_bench.py exited with ${result}")
endif()
file(READ "${OUT_DIR}/results.md" report)
# Fails naming `what` (and showing the report) unless the report matches `pattern`.
function(expect_in_report pattern what)
  if(NOT report MATCHES "${pattern}")
    message(FATAL_ERROR "${what}:\n${report}")
  endif()
endfunction()
foreach(row "| terrain |" "| clouds |" "| atmosphere |" "| cloud shadows |"
            "| terrain shadows |" "| god rays |" "| god rays, sun in view |" "| cloud sky light |"
            "| lightning |"
            "| lightning, a flash always active |" "| weather regions (the storm front) |"
            "| a change of weather (its middle, against that weather held) |"
            "| water (the lake scene) |")
  string(FIND "${report}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "results.md has no row ${row}")
  endif()
endforeach()
expect_in_report("\\| god rays \\|[^\n]*\\| clouds module: god rays \\| 0\\.[0-9]+ \\|"
                 "the god rays' row does not name their pipelines and memory")
expect_in_report("\\| cloud sky light \\|[^\n]*clouds module: sky light[^\n]*\\| 0\\.[0-9]+ \\|"
                 "the sky light's row does not name its pipeline and memory")
expect_in_report("\\| lightning, a flash always active \\|[^\n]*clouds module: lightning"
                 "the lightning's row does not name its pipelines")
# The regions' code is in their own pipeline variant; a change of weather adds no pass or
# pipeline to the weather held.
expect_in_report("\\| weather regions \\(the storm front\\) \\|[^\n]*clouds module: weather regions"
                 "the weather regions' row does not name their pipelines")
expect_in_report("\\| a change of weather [^|]*\\|[^|]*\\|[^|]*\\|[^|]*\\| - \\| - \\|"
                 "a change of weather adds passes or pipelines")
# The water is drawn in the scene pass: its pipeline, no pass of its own.
expect_in_report("\\| water \\(the lake scene\\) \\|[^|]*\\|[^|]*\\|[^|]*\\| - \\| water \\(cloud shadows\\) \\|"
                 "the water's row does not name its pipeline alone")
expect_in_report("\\| terrain shadows \\|[^\n]*\\| 0\\.00 \\|"
                 "the terrain shadows' row adds memory")
# Lightning's cost in the passes it changes: a row per lightning comparison, with the bolts' pass.
expect_in_report("\\| effect \\| frame: scene \\|[^\n]*clouds: lightning bolts \\| all of them \\|"
                 "no table of lightning's cost in the passes it changes")
expect_in_report("\\| lightning, a ground strike and its bolt always active \\| [+-][0-9.]+ \\("
                 "the passes table has no row for the bolt")
# The HUD's table: its line and the panel, each against no HUD, paired.
file(READ "${OUT_DIR}/hud.md" hud)
foreach(row "| the HUD's line |" "| the settings panel open |"
            "| the settings panel open, backgrounds as triangles |")
  string(FIND "${hud}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "hud.md has no row ${row}:\n${hud}")
  endif()
endforeach()
