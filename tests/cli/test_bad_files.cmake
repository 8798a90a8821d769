# Corrupt input files through the apps: truncated and bit-flipped scans, labels, configs and
# rawlogs. Each case either exits non-zero with a message naming the file, or (a flip that still
# parses) exits 0 with complete output; which one is asserted per case.
# Binary files are cut and patched with file(DOWNLOAD file://... RANGE_START/RANGE_END) and
# `cmake -E cat`, so NUL bytes survive (CMake strings cannot hold them).
# Inputs: TRAVEL_KITTI, TRAVEL_RAWLOG (optional), WORK_DIR, RAWLOG_DATASET (optional).
cmake_minimum_required(VERSION 3.24)  # file(DOWNLOAD ... RANGE_START)

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

include(${CMAKE_CURRENT_LIST_DIR}/CliExpect.cmake)

# Bytes [first, last] of `src` into `dst` (binary-safe).
function(copy_range src first last dst)
  file(DOWNLOAD "file://${src}" "${dst}" RANGE_START ${first} RANGE_END ${last} STATUS st)
  list(GET st 0 code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "cannot copy bytes ${first}-${last} of ${src}: ${st}")
  endif()
endfunction()

# The first `size` bytes of `src` into `dst`.
function(truncate_file src size dst)
  if(size EQUAL 0)
    file(WRITE "${dst}" "")
  else()
    math(EXPR last "${size} - 1")
    copy_range("${src}" 0 ${last} "${dst}")
  endif()
endfunction()

# `src` with the byte at each offset in `offsets` (ascending) XORed with `mask`, into `dst`.
# A byte that would become NUL is XORed with 0x01 instead (CMake cannot write NUL).
function(flip_bytes src dst mask)
  file(SIZE "${src}" size)
  set(parts)
  set(pos 0)
  set(k 0)
  foreach(offset IN LISTS ARGN)
    if(offset GREATER pos)
      math(EXPR last "${offset} - 1")
      copy_range("${src}" ${pos} ${last} "${dst}.part${k}")
      list(APPEND parts "${dst}.part${k}")
    endif()
    file(READ "${src}" hex OFFSET ${offset} LIMIT 1 HEX)
    math(EXPR value "0x${hex} ^ ${mask}")
    if(value EQUAL 0)
      math(EXPR value "0x${hex} ^ 1")
    endif()
    string(ASCII ${value} byte)
    file(WRITE "${dst}.byte${k}" "${byte}")
    list(APPEND parts "${dst}.byte${k}")
    math(EXPR pos "${offset} + 1")
    math(EXPR k "${k} + 1")
  endforeach()
  if(pos LESS size)
    math(EXPR last "${size} - 1")
    copy_range("${src}" ${pos} ${last} "${dst}.part${k}")
    list(APPEND parts "${dst}.part${k}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E cat ${parts} OUTPUT_FILE "${dst}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cannot write ${dst}")
  endif()
  file(REMOVE ${parts})
  file(SIZE "${dst}" new_size)
  if(NOT new_size EQUAL size)
    message(FATAL_ERROR "flip_bytes: ${dst} has ${new_size} bytes, expected ${size}")
  endif()
endfunction()

# ---------------------------------------------------------------------------------------------
# travel-kitti: a generated scan (1000 points; every byte printable so file(WRITE) can make it),
# its SemanticKITTI-style labels, and a config.
set(n_points 1000)
set(bin_text "")
set(label_text "")
foreach(i RANGE 1 ${n_points})
  # x in [8, 16) (exponent byte 0x41), y ~ 10, z ~ 0.5, intensity tiny: all bytes in 0x01-0x7f.
  math(EXPR lo "1 + (${i} % 120)")
  math(EXPR mid "1 + ((${i} / 120) % 120)")
  string(ASCII ${lo} ${mid} 32 65  1 1 32 65  1 1 1 63  1 1 1 1 record)
  string(APPEND bin_text "${record}")
  string(APPEND label_text "AAAA")
endforeach()
file(MAKE_DIRECTORY ${WORK_DIR}/good/scans ${WORK_DIR}/good/labels)
file(WRITE ${WORK_DIR}/good/scans/000000.bin "${bin_text}")
file(WRITE ${WORK_DIR}/good/labels/000000.label "${label_text}")
math(EXPR bin_size "${n_points} * 16")
math(EXPR label_size "${n_points} * 4")

# The generated scan runs (with labels), one uint32 per point written.
expect_success(${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans -o ${WORK_DIR}/good/out
               --labels ${WORK_DIR}/good/labels -q)
file(SIZE ${WORK_DIR}/good/out/000000.label size)
if(NOT size EQUAL label_size)
  message(FATAL_ERROR "good scan: ${size} bytes of labels, expected ${label_size}")
endif()

# .bin truncated to sizes that are not a multiple of 16: error naming the file.
foreach(cut 1 15 17 8007 15999)
  set(dir ${WORK_DIR}/bin_cut_${cut})
  file(MAKE_DIRECTORY ${dir}/scans)
  truncate_file(${WORK_DIR}/good/scans/000000.bin ${cut} ${dir}/scans/000000.bin)
  expect_failure_mentioning("000000.bin" ${TRAVEL_KITTI} -i ${dir}/scans -o ${dir}/out -q)
endforeach()
# Truncated to a multiple of 16 (a shorter scan): a valid scan, complete output for it.
set(dir ${WORK_DIR}/bin_cut_800)
file(MAKE_DIRECTORY ${dir}/scans)
truncate_file(${WORK_DIR}/good/scans/000000.bin 800 ${dir}/scans/000000.bin)
expect_success(${TRAVEL_KITTI} -i ${dir}/scans -o ${dir}/out -q)
file(SIZE ${dir}/out/000000.label size)
if(NOT size EQUAL 200)
  message(FATAL_ERROR "50-point scan: ${size} bytes of labels, expected 200")
endif()
# Bit flips in a .bin always parse (the size is unchanged; NaN/inf/huge values are invalid
# points): exit 0 and one label per point.
set(dir ${WORK_DIR}/bin_flip)
file(MAKE_DIRECTORY ${dir}/scans)
flip_bytes(${WORK_DIR}/good/scans/000000.bin ${dir}/scans/000000.bin 0xC0 3 7 11 1003 5555 15999)
flip_bytes(${dir}/scans/000000.bin ${dir}/scans/000001.bin 0x7F 19 23 27 8003)
expect_success(${TRAVEL_KITTI} -i ${dir}/scans -o ${dir}/out -q)
foreach(frame 000000 000001)
  file(SIZE ${dir}/out/${frame}.label size)
  if(NOT size EQUAL label_size)
    message(FATAL_ERROR "bit-flipped ${frame}.bin: ${size} bytes of labels, expected ${label_size}")
  endif()
endforeach()

# Scans that are no scans (issue 13): empty, garbage (text padded to a multiple of 16 bytes, which
# used to become junk points) and non-finite only (quiet NaN 0x7FC01010 in every float; its bytes
# are all printable-safe, so file(WRITE) can make it). Each: non-zero exit naming the file, and no
# .label written for it.
string(ASCII 16 16 192 127 nan_float)
string(REPEAT "${nan_float}" 80 nan_text)  # 20 KITTI or 16 nuScenes records
set(text "This is a text file, padded to a multiple of 16 bytes.")
string(APPEND text "          ")  # 64 bytes
foreach(kind empty garbage nan)
  set(dir ${WORK_DIR}/bin_${kind})
  file(MAKE_DIRECTORY ${dir}/scans)
  if(kind STREQUAL "empty")
    file(WRITE ${dir}/scans/000000.bin "")
  elseif(kind STREQUAL "garbage")
    file(WRITE ${dir}/scans/000000.bin "${text}")
  else()
    file(WRITE ${dir}/scans/000000.bin "${nan_text}")
  endif()
  expect_failure_mentioning("000000.bin" ${TRAVEL_KITTI} -i ${dir}/scans -o ${dir}/out -q)
  if(EXISTS ${dir}/out/000000.label)
    message(FATAL_ERROR "${kind} .bin: a .label was written for a file that is no scan")
  endif()
endforeach()

# .label truncated (not a multiple of 4, or a multiple of 4 but too few): error naming it.
foreach(cut 0 3 2001 3996)
  set(dir ${WORK_DIR}/label_cut_${cut})
  file(MAKE_DIRECTORY ${dir}/labels)
  truncate_file(${WORK_DIR}/good/labels/000000.label ${cut} ${dir}/labels/000000.label)
  expect_failure_mentioning("000000.label" ${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans
                            -o ${dir}/out --labels ${dir}/labels -q)
endforeach()

# ---------------------------------------------------------------------------------------------
# Configs. A YAML and an ini file with several keys; truncated mid-line and with a flipped bit in
# a key: error naming file:line and the key. A flip inside a comment still parses: exit 0.
set(yaml "# test config\ntravel:\n  sensor_height: 1.73\n  tgf_resolution: 4.0\n  max_range: 80\n  ring_source: auto\n")
set(ini "; test config\n[travel]\nsensor_height = 1.73\ntgf_resolution = 4.0\nmax_range = 80\nring_source = auto\n")
foreach(kind yaml ini)
  set(dir ${WORK_DIR}/config_${kind})
  file(MAKE_DIRECTORY ${dir})
  file(WRITE ${dir}/good.${kind} "${${kind}}")
  expect_success(${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans -o ${dir}/out
                 --config ${dir}/good.${kind} -q)

  # Truncated in the middle of line 4's key ("tgf_reso"): unknown key named with file:4.
  string(FIND "${${kind}}" "tgf_reso" cut)
  math(EXPR cut "${cut} + 8")
  string(SUBSTRING "${${kind}}" 0 ${cut} text)
  file(WRITE ${dir}/cut_key.${kind} "${text}")
  expect_failure_mentioning("cut_key.${kind}:4" ${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans
                            -o ${dir}/out --config ${dir}/cut_key.${kind} -q)
  expect_failure_mentioning("tgf_reso" ${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans
                            -o ${dir}/out --config ${dir}/cut_key.${kind} -q)
  # Truncated in the middle of line 5's value ("max_range: 8" / "max_range = 8"): still a valid
  # assignment of 8 m, so it parses; the run succeeds.
  string(FIND "${${kind}}" "80\n" cut)
  math(EXPR cut "${cut} + 1")
  string(SUBSTRING "${${kind}}" 0 ${cut} text)
  file(WRITE ${dir}/cut_value.${kind} "${text}")
  expect_success(${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans -o ${dir}/out
                 --config ${dir}/cut_value.${kind} -q)
  # Truncated right after the key's separator: an empty value, error naming line and key.
  string(FIND "${${kind}}" "ring_source" cut)
  math(EXPR cut "${cut} + 13")
  string(SUBSTRING "${${kind}}" 0 ${cut} text)
  file(WRITE ${dir}/cut_sep.${kind} "${text}")
  expect_failure_mentioning("cut_sep.${kind}:6" ${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans
                            -o ${dir}/out --config ${dir}/cut_sep.${kind} -q)
  expect_failure_mentioning("ring_source" ${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans
                            -o ${dir}/out --config ${dir}/cut_sep.${kind} -q)

  # One bit flipped in a key: 'sensor_height' -> 'sensor_heighu' (t ^ 0x01).
  string(REPLACE "sensor_height" "sensor_heighu" text "${${kind}}")
  file(WRITE ${dir}/flip_key.${kind} "${text}")
  expect_failure_mentioning("flip_key.${kind}:3" ${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans
                            -o ${dir}/out --config ${dir}/flip_key.${kind} -q)
  expect_failure_mentioning("sensor_heighu" ${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans
                            -o ${dir}/out --config ${dir}/flip_key.${kind} -q)
  # One bit flipped in the separator (':' ^ 0x01 = ';', '=' ^ 0x01 = '<'): line 4 is no
  # assignment any more.
  if(kind STREQUAL "yaml")
    string(REPLACE "tgf_resolution:" "tgf_resolution;" text "${${kind}}")
  else()
    string(REPLACE "tgf_resolution =" "tgf_resolution <" text "${${kind}}")
  endif()
  file(WRITE ${dir}/flip_sep.${kind} "${text}")
  expect_failure_mentioning("flip_sep.${kind}:4" ${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans
                            -o ${dir}/out --config ${dir}/flip_sep.${kind} -q)
  # One bit flipped in a value digit ('4' ^ 0x40 = 't'): not a number, names the key.
  string(REPLACE "tgf_resolution: 4.0" "tgf_resolution: t.0" text "${${kind}}")
  string(REPLACE "tgf_resolution = 4.0" "tgf_resolution = t.0" text "${text}")
  file(WRITE ${dir}/flip_value.${kind} "${text}")
  expect_failure_mentioning("tgf_resolution" ${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans
                            -o ${dir}/out --config ${dir}/flip_value.${kind} -q)
  # One bit flipped inside the comment ('t' ^ 0x20 = 'T'): still parses, exit 0.
  string(REPLACE "test config" "Test config" text "${${kind}}")
  file(WRITE ${dir}/flip_comment.${kind} "${text}")
  expect_success(${TRAVEL_KITTI} -i ${WORK_DIR}/good/scans -o ${dir}/out
                 --config ${dir}/flip_comment.${kind} -q)
endforeach()

# ---------------------------------------------------------------------------------------------
# travel-rawlog on the mrpt-common VLP-16 sample (gzip-compressed).
if(NOT RAWLOG_DATASET)
  set(RAWLOG_DATASET /usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog)
endif()
if(NOT TRAVEL_RAWLOG)
  message(STATUS "travel-rawlog not built: rawlog cases skipped")
  return()
endif()
if(NOT EXISTS ${RAWLOG_DATASET})
  message(STATUS "${RAWLOG_DATASET} not found (package mrpt-common?): rawlog cases skipped")
  return()
endif()
set(dir ${WORK_DIR}/rawlog)
file(MAKE_DIRECTORY ${dir})
file(COPY_FILE ${RAWLOG_DATASET} ${dir}/good.rawlog)
file(SIZE ${dir}/good.rawlog rawlog_size)
expect_success(${TRAVEL_RAWLOG} -i ${dir}/good.rawlog -o ${dir}/good_out.rawlog)
string(REGEX MATCH "records: [0-9]+, LiDAR frames processed: [0-9]+" good_summary "${last_output}")
if(NOT good_summary)
  message(FATAL_ERROR "no summary from travel-rawlog:\n${last_output}")
endif()

# Truncated at several sizes (inside the gzip header, inside the deflate stream): error naming
# the file. Zero bytes is an empty file.
math(EXPR cut_half "${rawlog_size} / 2")
math(EXPR cut_deflate "${rawlog_size} - 12")
foreach(cut 1 10 100 1000 ${cut_half} ${cut_deflate})
  truncate_file(${dir}/good.rawlog ${cut} ${dir}/cut_${cut}.rawlog)
  expect_failure_mentioning("cut_${cut}.rawlog" ${TRAVEL_RAWLOG} -i ${dir}/cut_${cut}.rawlog
                            -o ${dir}/out_cut_${cut}.rawlog -q)
  if(EXISTS ${dir}/out_cut_${cut}.rawlog)
    message(FATAL_ERROR "a failed run left ${dir}/out_cut_${cut}.rawlog (should stay .part)")
  endif()
endforeach()
# Cut inside the 8-byte gzip trailer (CRC32, ISIZE): every record has been decompressed, and the
# reader (mrpt::io::CFileGZInputStream over zlib's gzread) does not check the trailer, so the run
# succeeds with the complete output (same records and frames).
math(EXPR cut_crc "${rawlog_size} - 8")
math(EXPR cut_isize "${rawlog_size} - 4")
math(EXPR cut_last "${rawlog_size} - 1")
foreach(cut ${cut_crc} ${cut_isize} ${cut_last})
  truncate_file(${dir}/good.rawlog ${cut} ${dir}/cut_${cut}.rawlog)
  expect_success(${TRAVEL_RAWLOG} -i ${dir}/cut_${cut}.rawlog -o ${dir}/out_cut_${cut}.rawlog)
  string(REGEX MATCH "records: [0-9]+, LiDAR frames processed: [0-9]+" summary "${last_output}")
  if(NOT summary STREQUAL good_summary)
    message(FATAL_ERROR "cut to ${cut} bytes: '${summary}', expected '${good_summary}'")
  endif()
endforeach()

# Random bytes (seeded offsets) flipped inside the compressed data: error naming the file.
string(RANDOM LENGTH 8 ALPHABET 0123456789 RANDOM_SEED 2026 unused)
foreach(trial RANGE 1 4)
  set(offsets)
  foreach(k RANGE 1 3)
    string(RANDOM LENGTH 9 ALPHABET 0123456789 r)
    math(EXPR offset "100 + (${r} % (${rawlog_size} - 200))")
    list(APPEND offsets ${offset})
  endforeach()
  list(SORT offsets COMPARE NATURAL)
  list(REMOVE_DUPLICATES offsets)
  flip_bytes(${dir}/good.rawlog ${dir}/flip_${trial}.rawlog 0x5A ${offsets})
  expect_failure_mentioning("flip_${trial}.rawlog" ${TRAVEL_RAWLOG} -i ${dir}/flip_${trial}.rawlog
                            -o ${dir}/out_flip_${trial}.rawlog -q)
endforeach()

# A bit flipped in the gzip header's original-file-name field (bytes 10.. after FLG.FNAME): the
# data still decompresses and checks, so the run succeeds with the same records and frames.
flip_bytes(${dir}/good.rawlog ${dir}/flip_name.rawlog 0x01 12)
expect_success(${TRAVEL_RAWLOG} -i ${dir}/flip_name.rawlog -o ${dir}/flip_name_out.rawlog)
string(REGEX MATCH "records: [0-9]+, LiDAR frames processed: [0-9]+" summary "${last_output}")
if(NOT summary STREQUAL good_summary)
  message(FATAL_ERROR "header flip: '${summary}', expected '${good_summary}'")
endif()

# Corrupt records announcing gigabytes (found by fuzz_rawlog: MRPT's reader allocates the
# announced size; without the ceiling travel-rawlog grew to 23.6 GB and was killed): with
# --max-memory the allocation fails and the record is reported as corrupt, no crash.
if(FUZZ_CORPUS AND SANITIZE)
  # The ceiling is not applied in sanitizer builds (their shadow memory needs the address
  # space): the plain build runs these cases.
  message(STATUS "sanitizer build: corrupt-size rawlog cases skipped")
elseif(FUZZ_CORPUS)
  foreach(name huge_alloc_1 huge_alloc_2)
    execute_process(COMMAND ${TRAVEL_RAWLOG} -i ${FUZZ_CORPUS}/${name}.rawlog
                            -o ${dir}/out_${name}.rawlog -q --max-memory 1024
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
    if(NOT rc EQUAL 1)
      message(FATAL_ERROR "${name}: expected exit 1 and a clean error, got '${rc}':\n${out}${err}")
    endif()
    foreach(needle "${name}.rawlog: record 0" "corrupt record")
      string(FIND "${err}" "${needle}" pos)
      if(pos EQUAL -1)
        message(FATAL_ERROR "${name}: message does not mention '${needle}':\n${err}")
      endif()
    endforeach()
  endforeach()
  # The ceiling's own argument is checked (2^44 MiB would wrap to 0 bytes); a ceiling that a
  # good rawlog's run does not fit in (256 MiB: shared libraries, stacks and arenas alone take
  # more) is named in the error, with -j 1 (an allocation) and -j 2 (a thread start); where the
  # reader meets it first, its record is reported as larger than --max-memory allows.
  foreach(mib 10 17592186044416)
    expect_failure_mentioning("--max-memory must be 0 (no limit) or 256 to" ${TRAVEL_RAWLOG}
                              -i ${dir}/good.rawlog -o ${dir}/x.rawlog --max-memory ${mib})
  endforeach()
  foreach(jobs 1 2)
    expect_failure_mentioning("--max-memory" ${TRAVEL_RAWLOG}
                              -i ${dir}/good.rawlog -o ${dir}/x.rawlog --max-memory 256 -j ${jobs})
  endforeach()
endif()
