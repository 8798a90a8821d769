# RawLogViewer opens the labelled rawlog with the plugin (-l) under a virtual X server.
#   cmake -DRAWLOG_VIEWER=<exe or empty> -DXVFB_RUN=<exe or empty> -DPLUGIN=<abs .so>
#         -DRAWLOG=<rawlog> -DWORK_DIR=<dir> -P test_rawlogviewer.cmake
# Prints "SKIPPED: ..." (the test's SKIP_REGULAR_EXPRESSION) when either program is missing.
# What is checked: the GUI starts, loads the plugin without "Error loading" and keeps running
# (killed by `timeout` after 10 s: exit code 124) instead of crashing while it parses the
# rawlog. Whether the labels are drawn is checked by hand (docs/mrpt-viewers.md): selecting
# an observation needs a mouse click on its custom tree widget.
if(NOT RAWLOG_VIEWER OR NOT EXISTS "${RAWLOG_VIEWER}")
  message("SKIPPED: RawLogViewer not installed (Debian package mrpt-apps)")
  return()
endif()
if(NOT XVFB_RUN OR NOT EXISTS "${XVFB_RUN}")
  message("SKIPPED: xvfb-run not installed (Debian package xvfb)")
  return()
endif()

function(run_viewer plugin out_var rc_var)
  execute_process(
    COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24"
            timeout 10 ${RAWLOG_VIEWER} -l ${plugin} ${RAWLOG}
    OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 60)
  set(${out_var} "${out}${err}" PARENT_SCOPE)
  set(${rc_var} "${rc}" PARENT_SCOPE)
endfunction()

run_viewer(${PLUGIN} out rc)
string(FIND "${out}" "Error loading" load_error)
if(NOT load_error EQUAL -1 OR NOT rc EQUAL 124)
  message(FATAL_ERROR "RawLogViewer -l ${PLUGIN} ${RAWLOG}: exit ${rc} "
                      "(expected 124: still running when timeout stopped it):\n${out}")
endif()

# The check above can fail: a missing plugin is reported.
run_viewer(${WORK_DIR}/no_such_plugin.so out rc)
string(FIND "${out}" "Error loading" load_error)
if(load_error EQUAL -1)
  message(FATAL_ERROR "RawLogViewer did not report a missing plugin; output:\n${out}")
endif()
message(STATUS "RawLogViewer loaded the plugin and the rawlog and kept running")

# A screenshot of the loaded rawlog (the tree lists our class; the statistics panel counts it),
# when the X tools are installed: WORK_DIR/rawlogviewer.png.
find_program(XDOTOOL xdotool)
find_program(XWD xwd)
find_program(XWDTOPNM xwdtopnm)
if(XDOTOOL AND XWD AND XWDTOPNM)
  set(shot ${WORK_DIR}/rawlogviewer.png)
  file(REMOVE ${shot})
  execute_process(
    COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1000x24"
            sh ${CMAKE_CURRENT_LIST_DIR}/rawlogviewer_screenshot.sh ${RAWLOG_VIEWER} ${PLUGIN}
               ${shot} ${RAWLOG}
    OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 90)
  file(SIZE ${shot} shot_size)
  if(NOT rc EQUAL 0 OR shot_size LESS 20000)
    message(FATAL_ERROR "RawLogViewer screenshot failed (exit ${rc}, ${shot_size} bytes):\n${out}${err}")
  endif()
  message(STATUS "RawLogViewer screenshot: ${shot} (${shot_size} bytes)")
else()
  message(STATUS "xdotool / xwd / netpbm not installed: no screenshot")
endif()
