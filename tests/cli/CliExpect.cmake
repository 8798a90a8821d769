# Shared by the command-line tests (cmake -P scripts): run a command that must fail, and check
# that its message mentions `needle` (usually the file or key at fault).
function(expect_failure_mentioning needle)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "expected failure: ${ARGN}\n${out}${err}")
  endif()
  string(FIND "${out}${err}" "${needle}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "message does not mention '${needle}': ${ARGN}\n${out}${err}")
  endif()
endfunction()

# Run a command that must succeed; its stdout + stderr are left in `last_output`.
function(expect_success)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "expected success: ${ARGN}\n${out}${err}")
  endif()
  set(last_output "${out}${err}" PARENT_SCOPE)
endfunction()
