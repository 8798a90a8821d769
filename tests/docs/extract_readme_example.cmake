# Writes the first ```cpp block of README.md (the libtravel example), or of another Markdown
# file given as README, to OUTPUT, so that the test suite compiles and runs exactly what the
# page shows (tests docs.readme_example, docs.input_contract_example).
#   cmake -DREADME=<README.md> -DOUTPUT=<file.cpp> -P extract_readme_example.cmake
file(READ "${README}" text)
string(FIND "${text}" "```cpp\n" start)
if(start EQUAL -1)
  message(FATAL_ERROR "${README}: no ```cpp block")
endif()
math(EXPR start "${start} + 7")
string(SUBSTRING "${text}" ${start} -1 rest)
string(FIND "${rest}" "```" end)
string(SUBSTRING "${rest}" 0 ${end} code)
file(WRITE "${OUTPUT}.tmp" "${code}")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
