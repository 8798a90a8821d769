# No app writes over its inputs: an output path that names an input (a scan, the rawlog, the
# ground-truth labels folder, the sequence's poses) or another output is refused before anything
# is written, whatever its spelling (./, .., a trailing '/', a symlink), and the input is left
# byte for byte as it was. Also: a missing --labels folder, a --labels folder without any label
# of the scans, an -o, --csv or --track-png that is a folder where a file is written, a picture name without a picture
# extension; output folders of side outputs (--csv) are created.
# Variables: TRAVEL_KITTI, TRAVEL_RAWLOG and TRAVEL_VIEW (optional), MAKE_SCANS, SAMPLE, WORK_DIR.
include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(seq ${WORK_DIR}/seq)

# `file`'s MD5 must still be `expected` (the refused run left it alone).
function(expect_unchanged file expected)
  if(NOT EXISTS ${file})
    message(FATAL_ERROR "${file} was removed")
  endif()
  file(MD5 ${file} now)
  if(NOT now STREQUAL expected)
    message(FATAL_ERROR "${file} was changed")
  endif()
endfunction()

# A KITTI-like sequence: two synthetic scans and, as its ground truth, labels of a first run.
expect_success(${MAKE_SCANS} ${seq}/velodyne 2)
expect_success(${TRAVEL_KITTI} -q -i ${seq} -o ${seq}/labels)
file(MD5 ${seq}/labels/000000.label label_md5)
file(MD5 ${seq}/velodyne/000000.bin scan_md5)
file(MD5 ${seq}/velodyne/000001.bin scan1_md5)

# travel-kitti: -o the labels folder, however spelt; a side output on a scan; two outputs on one
# file; the sequence's poses.txt under --track.
foreach(spelling ${seq}/labels ${seq}/labels/ ${seq}/./velodyne/../labels)
  expect_failure_mentioning("the same path as the labels folder"
                            ${TRAVEL_KITTI} -q -i ${seq} -o ${spelling})
endforeach()
expect_unchanged(${seq}/labels/000000.label ${label_md5})
expect_failure_mentioning("the same path as the scan"
                          ${TRAVEL_KITTI} -q -i ${seq}/velodyne/000000.bin -o ${WORK_DIR}/out
                          --csv ${seq}/velodyne/000000.bin)
expect_unchanged(${seq}/velodyne/000000.bin ${scan_md5})
expect_failure_mentioning("the same path as the scan"
                          ${TRAVEL_KITTI} -q -i ${seq} -o ${WORK_DIR}/out --track
                          --track-png ${seq}/velodyne/000001.bin)
expect_unchanged(${seq}/velodyne/000001.bin ${scan1_md5})
expect_failure_mentioning("give each output its own path"
                          ${TRAVEL_KITTI} -q -i ${seq} -o ${WORK_DIR}/out --csv ${WORK_DIR}/x.csv
                          --track --track-png ${WORK_DIR}/x.csv)
file(WRITE ${seq}/poses.txt "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0.8 0 1 0 0 0 0 1 0\n")
file(MD5 ${seq}/poses.txt poses_md5)
expect_failure_mentioning("the same path as the sequence's"
                          ${TRAVEL_KITTI} -q -i ${seq} -o ${seq} --track)
expect_unchanged(${seq}/poses.txt ${poses_md5})
file(REMOVE ${seq}/poses.txt)
if(EXISTS ${WORK_DIR}/out OR EXISTS ${WORK_DIR}/x.csv)
  message(FATAL_ERROR "a refused run created its outputs")
endif()

# A path through a symlink and then "..": beside the link's target, not beside the link, so
# link/../000000.bin is no input here (it names elsewhere/000000.bin) and the run goes on.
file(MAKE_DIRECTORY ${WORK_DIR}/elsewhere/dir)
file(CREATE_LINK ${WORK_DIR}/elsewhere/dir ${seq}/velodyne/link SYMBOLIC)
expect_success(${TRAVEL_KITTI} -q -i ${seq}/velodyne/000000.bin -o ${WORK_DIR}/linked
               --csv ${seq}/velodyne/link/../000000.bin)
expect_unchanged(${seq}/velodyne/000000.bin ${scan_md5})
if(NOT EXISTS ${WORK_DIR}/elsewhere/000000.bin)
  message(FATAL_ERROR "--csv link/../000000.bin was not written beside the link's target")
endif()
file(REMOVE ${seq}/velodyne/link)

# --labels: a missing folder, and one that holds no label of these scans.
expect_failure_mentioning("--labels directory '${WORK_DIR}/nope' does not exist"
                          ${TRAVEL_KITTI} -q -i ${seq} -o ${WORK_DIR}/out --labels ${WORK_DIR}/nope)
file(MAKE_DIRECTORY ${WORK_DIR}/empty)
expect_failure_mentioning("no <stem>.label for any of the 2 scans"
                          ${TRAVEL_KITTI} -q -i ${seq} -o ${WORK_DIR}/out --labels ${WORK_DIR}/empty)
# A file output given as a folder: refused before the run (no labels written).
file(MAKE_DIRECTORY ${WORK_DIR}/folder.png)
foreach(flag --csv --track-png)
  expect_failure_mentioning("${flag} ${WORK_DIR}/folder.png: a folder; give the name of the file"
                            ${TRAVEL_KITTI} -q -i ${seq} -o ${WORK_DIR}/out --track
                            ${flag} ${WORK_DIR}/folder.png)
  if(EXISTS ${WORK_DIR}/out)
    message(FATAL_ERROR "${flag} a folder: the refused run wrote ${WORK_DIR}/out")
  endif()
endforeach()
# A side output's folder is created.
expect_success(${TRAVEL_KITTI} -q -i ${seq} -o ${WORK_DIR}/out --csv ${WORK_DIR}/new/sub/x.csv)
if(NOT EXISTS ${WORK_DIR}/new/sub/x.csv)
  message(FATAL_ERROR "--csv new/sub/x.csv was not written")
endif()

if(TRAVEL_VIEW)
  file(CREATE_LINK ${seq}/velodyne/000000.bin ${WORK_DIR}/link.png SYMBOLIC)
  expect_failure_mentioning("an input" ${TRAVEL_VIEW} -q -i ${seq}/velodyne/000000.bin
                            -o ${WORK_DIR}/link.png)
  expect_unchanged(${seq}/velodyne/000000.bin ${scan_md5})
  expect_failure_mentioning("a folder; give the name of the file" ${TRAVEL_VIEW} -q
                            -i ${seq}/velodyne/000000.bin -o ${WORK_DIR}/folder.png)
  expect_failure_mentioning("not a picture name" ${TRAVEL_VIEW} -q -i ${seq}/velodyne/000000.bin
                            -o ${WORK_DIR}/picture)
endif()

if(TRAVEL_RAWLOG AND EXISTS ${SAMPLE})
  set(in ${WORK_DIR}/in.rawlog)
  file(COPY_FILE ${SAMPLE} ${in})
  file(MD5 ${in} rawlog_md5)
  foreach(flag --csv --label-reference)
    expect_failure_mentioning("${flag} ${WORK_DIR}/./in.rawlog: the same path as -i"
                              ${TRAVEL_RAWLOG} -q -i ${in} -o ${WORK_DIR}/o.rawlog
                              ${flag} ${WORK_DIR}/./in.rawlog)
    expect_unchanged(${in} ${rawlog_md5})
  endforeach()
  expect_failure_mentioning("give each output its own path"
                            ${TRAVEL_RAWLOG} -q -i ${in} -o ${WORK_DIR}/o.rawlog
                            --csv ${WORK_DIR}/o.rawlog)
  # The rawlog is written as OUT.part first: an input of that name would be emptied, then removed.
  set(part_in ${WORK_DIR}/p.rawlog.part)
  file(COPY_FILE ${SAMPLE} ${part_in})
  expect_failure_mentioning("-o (its part file) ${WORK_DIR}/p.rawlog.part: the same path as -i"
                            ${TRAVEL_RAWLOG} -q -i ${part_in} -o ${WORK_DIR}/p.rawlog)
  expect_unchanged(${part_in} ${rawlog_md5})
  file(REMOVE ${part_in})
  file(MAKE_DIRECTORY ${WORK_DIR}/folder)
  expect_failure_mentioning("a folder; give the name of the file to write"
                            ${TRAVEL_RAWLOG} -q -i ${in} -o ${WORK_DIR}/folder)
  file(GLOB left ${WORK_DIR}/*.part ${WORK_DIR}/folder/*)
  if(left OR EXISTS ${WORK_DIR}/o.rawlog)
    message(FATAL_ERROR "refused runs left files behind: ${left}")
  endif()
else()
  message(STATUS "travel-rawlog or ${SAMPLE} missing: rawlog part skipped")
endif()
