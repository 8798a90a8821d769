# travel-nav-sim from the command line: a short run writes its three outputs into the working
# directory; bad inputs fail with messages naming the culprit.
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# A few simulated seconds on the small flat world, outputs in the current directory.
# Its scratch folder goes under TMPDIR (checked below).
file(MAKE_DIRECTORY ${WORK_DIR}/tmp)
execute_process(COMMAND ${CMAKE_COMMAND} -E env TMPDIR=${WORK_DIR}/tmp
  ${TRAVEL_NAV_SIM} -i flat_obstacles.world --timeout 4
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "travel-nav-sim failed:\n${out}${err}")
endif()
foreach(f flat_obstacles_travel.csv flat_obstacles_travel.png flat_obstacles_travel.reactivenavlog)
  if(NOT EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "missing output ${f}:\n${out}${err}")
  endif()
endforeach()
file(STRINGS ${WORK_DIR}/flat_obstacles_travel.csv rows)
list(LENGTH rows n)
list(GET rows 0 header)
if(NOT header STREQUAL "t,x,y,z,yaw_deg,roll_deg,pitch_deg,v,w,clearance,obstacles" OR n LESS 30)
  message(FATAL_ERROR "unexpected trajectory CSV (${n} rows, header '${header}')")
endif()
string(FIND "${out}" "travel    timeout" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "no per-run summary line:\n${out}")
endif()
file(GLOB leftovers ${WORK_DIR}/.travel-nav-sim-* ${WORK_DIR}/tmp/.travel-nav-sim-*
     ${WORK_DIR}/*.part ${WORK_DIR}/*.part.png)
if(leftovers)
  message(FATAL_ERROR "scratch files left behind: ${leftovers}")
endif()

# The map source: a short run saves the map beside the usual outputs and reports its cost.
execute_process(COMMAND ${CMAKE_COMMAND} -E env TMPDIR=${WORK_DIR}/tmp
  ${TRAVEL_NAV_SIM} -i flat_obstacles.world -s map --timeout 3 --no-navlog
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "travel-nav-sim -s map failed:\n${out}${err}")
endif()
foreach(f flat_obstacles_map.csv flat_obstacles_map.png flat_obstacles_map.bt
          flat_obstacles_map_grid.gridmap.gz flat_obstacles_map_height.gridmap.gz)
  if(NOT EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "missing output ${f}:\n${out}${err}")
  endif()
endforeach()
string(FIND "${out}" "map update + sensing" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "no map timing line:\n${out}")
endif()

# A world with a mover, tracking on: the summary reports the clearance to the movers and the CSV
# has its column.
execute_process(COMMAND ${CMAKE_COMMAND} -E env TMPDIR=${WORK_DIR}/tmp
  ${TRAVEL_NAV_SIM} -i crossing.world --track --timeout 3 --no-navlog
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "travel-nav-sim --track failed:\n${out}${err}")
endif()
string(FIND "${out}" "min clearance to the movers" pos)
file(STRINGS ${WORK_DIR}/crossing_travel.csv rows LIMIT_COUNT 1)
if(pos EQUAL -1 OR NOT rows MATCHES ",mover_clearance$")
  message(FATAL_ERROR "no clearance to the movers:\n${out}\nCSV header: ${rows}")
endif()

# Errors name what is wrong.
expect_failure_mentioning("nowhere.world" ${TRAVEL_NAV_SIM} -i ${WORK_DIR}/nowhere.world)
expect_failure_mentioning("unknown obstacle source 'lidar'" ${TRAVEL_NAV_SIM} --source lidar
  -i flat_obstacles.world)
expect_failure_mentioning("-s/--source: unknown obstacle source 'bogus' (expected travel, raw, threshold, map or all)"
  ${TRAVEL_NAV_SIM} -s bogus -i flat_obstacles.world)
expect_failure_mentioning("-t/--timeout must be > 0" ${TRAVEL_NAV_SIM} -t -1
  -i flat_obstacles.world)
expect_failure_mentioning("-t/--timeout must be > 0" ${TRAVEL_NAV_SIM} --timeout 0
  -i flat_obstacles.world)
foreach(bad -3 4294967296)
  expect_failure_mentioning("--seed must be 0 to 4294967295" ${TRAVEL_NAV_SIM} --seed ${bad}
    -i flat_obstacles.world -o ${WORK_DIR}/seed --timeout 1 --no-navlog)
endforeach()
# A flag for a source the run does not drive is named, not ignored.
expect_failure_mentioning("--no-plan and --no-map-save are for -s map" ${TRAVEL_NAV_SIM}
  -i flat_obstacles.world -s travel --no-plan)
expect_failure_mentioning("--no-plan and --no-map-save are for -s map" ${TRAVEL_NAV_SIM}
  -i flat_obstacles.world -s all --no-map-save)
expect_failure_mentioning("--threshold is for -s threshold or -s all" ${TRAVEL_NAV_SIM}
  -i flat_obstacles.world -s map --threshold 0.3)
expect_failure_mentioning("--track is for the sources travel and map" ${TRAVEL_NAV_SIM}
  -i flat_obstacles.world -s raw --track)
file(WRITE ${WORK_DIR}/bad.world "start 0 0 0\ngoal 5 0\npole 1 1 0.1\n")
expect_failure_mentioning("bad.world:3" ${TRAVEL_NAV_SIM} -i ${WORK_DIR}/bad.world)
expect_failure_mentioning("tgf_resolution" ${TRAVEL_NAV_SIM} -i flat_obstacles.world
  --set tgf_resolution=-1)
