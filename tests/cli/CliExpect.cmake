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
