# Runs clouds_textures: a good run (files, sizes, manifest), a rerun (same bytes), bad options.
file(REMOVE_RECURSE ${OUT_DIR})

function(generate dir)
  execute_process(COMMAND ${GENERATOR} --out ${dir} --seed 7 --time 1000 --state stormy
                          --state sparse --around sparse --region stormy,25000,20000,4000,3000
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "clouds_textures failed (${rc}): ${out}${err}")
  endif()
endfunction()

# The width and height a PNG's header holds.
function(png_size file out_width out_height)
  file(READ ${file} header LIMIT 24 HEX)
  string(SUBSTRING ${header} 32 8 width_hex)
  string(SUBSTRING ${header} 40 8 height_hex)
  math(EXPR width "0x${width_hex}")
  math(EXPR height "0x${height_hex}")
  set(${out_width} ${width} PARENT_SCOPE)
  set(${out_height} ${height} PARENT_SCOPE)
endfunction()

generate(${OUT_DIR}/first)
# name, width, height: volumes as atlases of their slices.
set(expected shape_noise 2048 1024 detail_noise 256 128 hero_noise 2048 1024 curl_noise 128 128
             weather_map 512 512 weather_stormy 512 512 weather_sparse 512 512
             weather_regions 512 512)
list(LENGTH expected count)
math(EXPR last "${count} - 1")
foreach(i RANGE 0 ${last} 3)
  math(EXPR w "${i} + 1")
  math(EXPR h "${i} + 2")
  list(GET expected ${i} name)
  list(GET expected ${w} width)
  list(GET expected ${h} height)
  foreach(ext png exr)
    if(NOT EXISTS ${OUT_DIR}/first/${name}.${ext})
      message(FATAL_ERROR "clouds_textures wrote no ${name}.${ext}")
    endif()
  endforeach()
  png_size(${OUT_DIR}/first/${name}.png actual_width actual_height)
  if(NOT actual_width EQUAL width OR NOT actual_height EQUAL height)
    message(FATAL_ERROR "${name}.png is ${actual_width}x${actual_height}, not ${width}x${height}")
  endif()
endforeach()
if(EXISTS ${OUT_DIR}/first/weather_cloudy.png)
  message(FATAL_ERROR "clouds_textures wrote a state it was not asked for")
endif()
file(READ ${OUT_DIR}/first/textures.json manifest)
string(JSON seed GET ${manifest} seed)
string(JSON phase GET ${manifest} weatherPhase)
string(JSON states GET ${manifest} weather_states)
string(JSON regions GET ${manifest} weather_regions)
if(NOT seed EQUAL 7 OR NOT phase EQUAL 0.5 OR NOT states STREQUAL "[ \"stormy\", \"sparse\" ]"
   OR NOT regions EQUAL 1)
  message(FATAL_ERROR "textures.json: seed ${seed}, phase ${phase}, states ${states}, "
                      "regions ${regions}")
endif()

# The same options, the same bytes (the volumes are computed slice by slice on any threads).
generate(${OUT_DIR}/second)
foreach(name shape_noise hero_noise weather_map weather_stormy weather_regions)
  file(SHA256 ${OUT_DIR}/first/${name}.png a)
  file(SHA256 ${OUT_DIR}/second/${name}.png b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "${name}.png differs between two runs with the same options")
  endif()
endforeach()

# Bad options: refused, naming the option.
foreach(case "--seed;-3;--seed" "--seed;x;--seed" "--time;-1;--time" "--time;nan;--time"
             "--state;sunny;--state sunny" "--colour;red;unknown option --colour"
             "--seed;5;--out DIR is required" "--out;needs a value"
             "--region;stormy,1,2,3;--region stormy,1,2,3: not STATE,X,Z,RADIUS,BLEND"
             "--region;hail,1,2,3,400;--region hail"
             "--region;stormy,1,2,3,50;BLEND in [100, 1e7]"
             "--out;x;--around;sparse;--around: around no --region")
  list(GET case -1 expected_message)
  list(REMOVE_AT case -1)
  execute_process(COMMAND ${GENERATOR} ${case} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "clouds_textures accepted ${case}")
  endif()
  string(FIND "${err}" "${expected_message}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "clouds_textures ${case}: the error does not say '${expected_message}': ${err}")
  endif()
endforeach()
