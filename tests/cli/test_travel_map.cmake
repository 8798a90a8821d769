# travel-map command-line test (cmake -P): good inputs write every export; bad inputs fail with
# a message naming the file (and line) or key at fault.
# -DTRAVEL_MAP -DTRAVEL_RAWLOG -DMAKE_SYNTHETIC -DSAMPLE -DCONFIG -DDATA_DIR -DWORK_DIR
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(expect_exports dir name)
  foreach(suffix .bt _grid.gridmap.gz _height.gridmap.gz _traversability.png _occupancy.png
                 _height.png .3Dscene .travelmap)
    if(NOT EXISTS ${dir}/${name}${suffix})
      message(FATAL_ERROR "missing output ${dir}/${name}${suffix}")
    endif()
  endforeach()
endfunction()

# --help explains inputs and outputs.
expect_success(${TRAVEL_MAP} --help)
foreach(word "gridmap.gz" "poses" "identity pose" "KITTI")
  string(FIND "${last_output}" "${word}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "--help does not mention '${word}'")
  endif()
endforeach()

# The synthetic moving-robot rawlog (VLP-16 rotating scans + odometry + IMU): poses from the
# odometry records.
expect_success(${MAKE_SYNTHETIC} ${WORK_DIR}/street.rawlog)
expect_success(${TRAVEL_MAP} -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/street
  -p vlp16 --set sensor_height=1.8 --set min_range=2 --extent " -30,30,-20,20")
expect_exports(${WORK_DIR}/street street)
foreach(word "LiDAR frames mapped: 10" "poses: odometry in the rawlog" "occupied voxels")
  string(FIND "${last_output}" "${word}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "summary lacks '${word}':\n${last_output}")
  endif()
endforeach()

# An export that cannot be written whole (a file size limit of one block, as a full disk): an
# error naming it and exit 1; the files of the run before stay as they were, and no part file
# is left. The .bt is the first export.
set(exports .bt _grid.gridmap.gz _height.gridmap.gz _traversability.png _occupancy.png
            _height.png .3Dscene .travelmap)
foreach(suffix ${exports})
  file(SHA256 ${WORK_DIR}/street/street${suffix} before${suffix})
endforeach()
execute_process(COMMAND sh -c "ulimit -f 1; trap '' XFSZ; exec \"$0\" \"$@\"" ${TRAVEL_MAP}
                        -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/street -p vlp16 -q
                        --set sensor_height=1.8 --set min_range=2 --extent " -30,30,-20,20"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "street/street\\.bt: cannot write \\(File too large\\)")
  message(FATAL_ERROR "exports over the file size limit (${rc}):\n${out}${err}")
endif()
foreach(suffix ${exports})
  file(SHA256 ${WORK_DIR}/street/street${suffix} after)
  if(NOT after STREQUAL "${before${suffix}}")
    message(FATAL_ERROR "street${suffix} changed by the run that failed")
  endif()
endforeach()
file(GLOB parts ${WORK_DIR}/street/*.part ${WORK_DIR}/street/*.part.*)
if(parts)
  message(FATAL_ERROR "part files left by the run that failed: ${parts}")
endif()

# The same drive in the SensoryFrame format with CActionRobotMovement2D odometry actions (true
# planar increments) and no pose file: poses from the actions; the road is traversable and the
# south wall (y = -11) an obstacle where the scene has them.
expect_success(${MAKE_SYNTHETIC} ${WORK_DIR}/street_sf.rawlog --odometry-actions)
expect_success(${TRAVEL_MAP} -i ${WORK_DIR}/street_sf.rawlog -o ${WORK_DIR}/street_sf
  -p vlp16 --set sensor_height=1.8 --set min_range=2 --extent " -30,30,-20,20"
  --probe " 2,0" --probe " -25,3" --probe " -20,-11")
expect_exports(${WORK_DIR}/street_sf street_sf)
foreach(word "LiDAR frames mapped: 10" "poses: odometry actions of the SensoryFrames (10 increments)"
        "probe 2,0: traversable" "probe -25,3: traversable" "probe -20,-11: obstacle")
  string(FIND "${last_output}" "${word}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "SensoryFrame/actions summary lacks '${word}':\n${last_output}")
  endif()
endforeach()

# travel-rawlog's output of that drive (labels and per-class clouds beside each scan): the same
# 10 LiDAR frames, also for a KITTI pose file, which is indexed by LiDAR frame.
expect_success(${TRAVEL_RAWLOG} -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/street_labelled.rawlog
  -p vlp16 --set sensor_height=1.8 --set min_range=2)
set(kitti_poses "")
foreach(i RANGE 9)
  string(APPEND kitti_poses "1 0 0 ${i} 0 1 0 0 0 0 1 0\n")
endforeach()
file(WRITE ${WORK_DIR}/street_kitti.txt "${kitti_poses}")
expect_success(${TRAVEL_MAP} -i ${WORK_DIR}/street_labelled.rawlog -o ${WORK_DIR}/street_labelled
  -p vlp16 --set sensor_height=1.8 --set min_range=2 --extent " -30,30,-20,20"
  --poses ${WORK_DIR}/street_kitti.txt)
string(FIND "${last_output}" "LiDAR frames mapped: 10, rejected: 0\n" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "travel-rawlog output: TRAVEL's clouds mapped as LiDAR frames:\n${last_output}")
endif()

# A LiDAR frame that is not mapped says why, naming the record, once per reason (10 frames here,
# all of another sensor).
execute_process(COMMAND ${TRAVEL_MAP} -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/street_nope
  -p vlp16 --set sensor_label=NOPE RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCHALL "street.rawlog: record [0-9]+: not mapped: sensor label 'VLP16' does not match"
  notes "${out}${err}")
list(LENGTH notes count)
if(rc EQUAL 0 OR NOT count EQUAL 1)
  message(FATAL_ERROR "rejected frames: ${count} notes (want 1), exit ${rc}:\n${out}${err}")
endif()

# The same rawlog with a TUM pose file (robot standing still at x = 1): used instead.
file(WRITE ${WORK_DIR}/tum.txt
  "# t x y z qx qy qz qw\n999999999.5 1 0 0 0 0 0 1\n1000000000.5 1 0 0 0 0 0 1\n1000000001.5 1 0 0 0 0 0 1\n")
expect_success(${TRAVEL_MAP} -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/street_tum
  --poses ${WORK_DIR}/tum.txt -p vlp16 --set sensor_height=1.8 --max-frames 2)
string(FIND "${last_output}" "poses: pose file" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "pose file not used:\n${last_output}")
endif()

# MRPT's VLP-16 sample has no poses: identity pose with a warning. The filter's note (no
# velocity to deskew with) is a "travel-map: note:" on stderr, as travel-rawlog prints it, not
# MRPT's time-stamped log line on stdout, which carries only the summary.
if(EXISTS ${SAMPLE})
  execute_process(COMMAND ${TRAVEL_MAP} -i ${SAMPLE} -o ${WORK_DIR}/vlp16 -c ${CONFIG}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "travel-map on the VLP-16 sample failed:\n${out}${err}")
  endif()
  expect_exports(${WORK_DIR}/vlp16 test_velodyne_VLP16)
  string(FIND "${err}" "identity pose" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "no identity-pose warning:\n${out}${err}")
  endif()
  string(FIND "${err}" "travel-map: note: no recent robot velocity" pos)
  if(pos EQUAL -1 OR out MATCHES "TravelFilter|INFO|velocity")
    message(FATAL_ERROR
      "the filter's note is not a note on stderr:\nstdout:\n${out}\nstderr:\n${err}")
  endif()
endif()

# A KITTI sequence directory (first frame only) when the shared data is there.
if(EXISTS ${DATA_DIR}/semantickitti/sequences/00/velodyne/000000.bin)
  expect_success(${TRAVEL_MAP} -i ${DATA_DIR}/semantickitti/sequences/00 -o ${WORK_DIR}/kitti
    --max-frames 1)
  expect_exports(${WORK_DIR}/kitti 00)
  # A KITTI-layout sequence with poses.txt (cam0 poses) and calib.txt (Tr: velodyne -> cam0):
  # the same scan twice, the second 10 m further along cam0's z (= the LiDAR's x). The poses
  # come from the files and the two frames are fused.
  set(seq ${WORK_DIR}/kitti_posed)
  file(MAKE_DIRECTORY ${seq}/velodyne)
  file(COPY_FILE ${DATA_DIR}/semantickitti/sequences/00/velodyne/000000.bin
       ${seq}/velodyne/000000.bin)
  file(COPY_FILE ${DATA_DIR}/semantickitti/sequences/00/velodyne/000000.bin
       ${seq}/velodyne/000001.bin)
  file(WRITE ${seq}/poses.txt "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 10\n")
  file(WRITE ${seq}/calib.txt
       "Tr: 0 -1 0 0 0 0 -1 -0.08 1 0 0 -0.27\n")
  expect_success(${TRAVEL_MAP} -i ${seq} -o ${WORK_DIR}/kitti_posed_out
                 --extent " -40,50,-40,40" --resolution 0.5)
  foreach(needle "poses: pose file" "poses.txt" "LiDAR frames mapped: 2, rejected: 0")
    string(FIND "${last_output}" "${needle}" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "KITTI with poses: '${needle}' not in the summary:\n${last_output}")
    endif()
  endforeach()
  # Every frame had a pose: no "without pose: 0" line.
  string(FIND "${last_output}" "without pose" pos)
  if(NOT pos EQUAL -1)
    message(FATAL_ERROR "KITTI with poses: summary mentions 'without pose':\n${last_output}")
  endif()
  expect_exports(${WORK_DIR}/kitti_posed_out kitti_posed)
  # -i naming the sequence's velodyne/ folder finds the same poses.txt and calib.txt.
  expect_success(${TRAVEL_MAP} -i ${seq}/velodyne -o ${WORK_DIR}/kitti_posed_velodyne
                 --extent " -40,50,-40,40" --resolution 0.5)
  foreach(needle "poses: pose file ${seq}/poses.txt" "LiDAR frames mapped: 2, rejected: 0")
    string(FIND "${last_output}" "${needle}" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "KITTI velodyne/ folder: '${needle}' not in the summary:\n${last_output}")
    endif()
  endforeach()
  # --calib without a KITTI pose file to apply it to is an error, not ignored.
  expect_failure_mentioning("--calib needs a KITTI pose file" ${TRAVEL_MAP}
    -i ${DATA_DIR}/semantickitti/sequences/00 -o ${WORK_DIR}/kitti_calib_alone --max-frames 1
    --calib ${seq}/calib.txt)
  # poses.txt with a wrong column count is an error naming the file and line.
  file(WRITE ${seq}/poses.txt "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1\n")
  expect_failure_mentioning("poses.txt:2" ${TRAVEL_MAP} -i ${seq} -o ${WORK_DIR}/kitti_posed_bad)
else()
  message(STATUS "SKIPPED part: ${DATA_DIR}/semantickitti not found")
endif()

# Bad inputs.
# --calib with a rawlog (robot poses, never cam0 ones) is an error, not ignored.
file(WRITE ${WORK_DIR}/calib.txt "Tr: 0 -1 0 0 0 0 -1 -0.08 1 0 0 -0.27\n")
expect_failure_mentioning("--calib is for scan inputs" ${TRAVEL_MAP}
  -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/calib_rawlog --calib ${WORK_DIR}/calib.txt)
expect_failure_mentioning("${WORK_DIR}/missing.rawlog" ${TRAVEL_MAP}
  -i ${WORK_DIR}/missing.rawlog -o ${WORK_DIR}/bad)
file(WRITE ${WORK_DIR}/not_a_rawlog.rawlog "hello, I am text\n")
# A run that fails before writing anything leaves none of the folders it created; a folder that
# existed before stays.
file(REMOVE_RECURSE ${WORK_DIR}/new_parent)
file(MAKE_DIRECTORY ${WORK_DIR}/kept)
expect_failure_mentioning("not_a_rawlog.rawlog: record 0" ${TRAVEL_MAP}
  -i ${WORK_DIR}/not_a_rawlog.rawlog -o ${WORK_DIR}/new_parent/maps)
expect_failure_mentioning("not_a_rawlog.rawlog: record 0" ${TRAVEL_MAP}
  -i ${WORK_DIR}/not_a_rawlog.rawlog -o ${WORK_DIR}/kept)
if(EXISTS ${WORK_DIR}/new_parent OR NOT IS_DIRECTORY ${WORK_DIR}/kept)
  message(FATAL_ERROR "a failed travel-map run left the folders it created, or removed one it did not")
endif()
expect_failure_mentioning("not_a_rawlog.rawlog: record 0" ${TRAVEL_MAP}
  -i ${WORK_DIR}/not_a_rawlog.rawlog -o ${WORK_DIR}/bad)
# The output folder is checked first and created when the map is written: a run that fails on
# its input leaves none; one that cannot create it says so before mapping.
file(REMOVE_RECURSE ${WORK_DIR}/new_parent)
expect_failure_mentioning("not_a_rawlog.rawlog: record 0" ${TRAVEL_MAP}
  -i ${WORK_DIR}/not_a_rawlog.rawlog -o ${WORK_DIR}/new_parent/maps)
if(EXISTS ${WORK_DIR}/new_parent)
  message(FATAL_ERROR "a travel-map run that failed on its input left its output folder")
endif()
file(WRITE ${WORK_DIR}/a_file "x")
expect_failure_mentioning("cannot create folder ${WORK_DIR}/a_file/maps" ${TRAVEL_MAP}
  -i ${WORK_DIR}/not_a_rawlog.rawlog -o ${WORK_DIR}/a_file/maps)
file(WRITE ${WORK_DIR}/columns.txt "0 0 0 0 0 0 0 1\n1 0 0 0 0 0 1\n")
expect_failure_mentioning("columns.txt:2: expected 8 numbers" ${TRAVEL_MAP}
  -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/bad --poses ${WORK_DIR}/columns.txt)
file(WRITE ${WORK_DIR}/words.txt "0 0 0 0 0 0 0 1\n1 0 zero 0 0 0 0 1\n")
expect_failure_mentioning("words.txt:2: column 3: 'zero'" ${TRAVEL_MAP}
  -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/bad --poses ${WORK_DIR}/words.txt)
file(WRITE ${WORK_DIR}/backwards.txt "2 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n")
expect_failure_mentioning("backwards.txt:2: timestamp" ${TRAVEL_MAP}
  -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/bad --poses ${WORK_DIR}/backwards.txt)
expect_failure_mentioning("unknown key 'colour'" ${TRAVEL_MAP}
  -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/bad --set colour=red)
expect_failure_mentioning("--extent" ${TRAVEL_MAP}
  -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/bad --extent 1,2,3)
# --probe and --extent read numbers as every numeric flag does: finite decimals, nothing after.
foreach(bad 1 "nan,0" "1e999,0" "0x10,0" "1,2x" "1,,2" "inf,0")
  expect_failure_mentioning("--probe" ${TRAVEL_MAP}
    -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/bad --probe ${bad})
endforeach()
foreach(bad "nan,1,0,1" "0x10,20,0,1" "0,1,0,1m")
  expect_failure_mentioning("--extent" ${TRAVEL_MAP}
    -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/bad --extent ${bad})
endforeach()
# --resolution must be > 0; like the other configuration flags it comes before each --set.
foreach(bad 0 -1 " -0.5")
  expect_failure_mentioning("--resolution" ${TRAVEL_MAP}
    -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/bad --resolution ${bad})
endforeach()
foreach(args "--resolution;0.3" "--resolution;0.1;--set;map.resolution=0.5"
             "--set;map.resolution=0.5;--resolution;0.1")
  expect_success(${TRAVEL_MAP} ${args} --print-config)
  string(REGEX MATCH "\nmap:\n(\n|  [^\n]*\n)*  resolution: ([0-9.]+)\n" found "${last_output}")
  set(want 0.5)
  if(args STREQUAL "--resolution;0.3")
    set(want 0.3)
  endif()
  if(NOT CMAKE_MATCH_2 STREQUAL want)
    message(FATAL_ERROR "${args}: map.resolution '${CMAKE_MATCH_2}', want ${want}")
  endif()
endforeach()
expect_failure_mentioning("min_x" ${TRAVEL_MAP}
  -i ${WORK_DIR}/street.rawlog -o ${WORK_DIR}/bad --extent 5,1,0,1)
message(STATUS "travel-map CLI: all checks passed")
