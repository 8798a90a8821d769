# Documentation consistency check (test docs.paths):
#   cmake -DROOT=<repository root> -P check_doc_paths.cmake
# Fails, naming every offence, when
#   - a repository path named in README.md, docs/**.md or a source file (C++, CMake, shell,
#     presets and configs) does not exist (paths that start with one of the top-level
#     directories below; globs and <placeholders> must match at least one file);
#   - a relative Markdown link or image in README.md or docs/ points at nothing, or out of the
#     repository;
#   - anything outside tests/ mentions the parent directory "../shared" (the repository must
#     stand alone; only tests and benchmarks may read real data beside it);
#   - README.md is longer than 10,000 bytes (a newcomer reads it in five minutes).
cmake_minimum_required(VERSION 3.16)
if(NOT ROOT OR NOT IS_DIRECTORY "${ROOT}")
  message(FATAL_ERROR "usage: cmake -DROOT=<repository root> -P check_doc_paths.cmake")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)

set(top_dirs "docs|share|scripts|apps|libtravel|mrpt_plugin|tests|cmake|python|examples")
# Installed locations that share a top-level name with the repository (<prefix>/share/travel,
# MRPT's own <prefix>/share/mrpt): named in comments, not repository paths.
set(installed_paths "^share/(travel|mrpt)(/|$)")
set(readme_limit 10000)
set(errors "")

# ---- Files to scan: what git knows (tracked and new), else the known top-level directories ----
set(files "")
find_package(Git QUIET)
if(GIT_FOUND AND EXISTS "${ROOT}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" ls-files --cached --others --exclude-standard
    WORKING_DIRECTORY "${ROOT}" OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
  if(rc EQUAL 0)
    string(REPLACE "\n" ";" files "${listing}")
  endif()
endif()
if(NOT files)
  file(GLOB_RECURSE files RELATIVE "${ROOT}" LIST_DIRECTORIES false
    "${ROOT}/*.md" "${ROOT}/*.cpp" "${ROOT}/*.hpp" "${ROOT}/*.h" "${ROOT}/*.cmake"
    "${ROOT}/*CMakeLists.txt" "${ROOT}/*.sh" "${ROOT}/*.yaml" "${ROOT}/*.ini" "${ROOT}/*.in")
  list(FILTER files EXCLUDE REGEX "^(build[^/]*|out|travel-out)/")
endif()
list(FILTER files INCLUDE REGEX
  "(\\.md|\\.cpp|\\.hpp|\\.h|\\.cmake|CMakeLists\\.txt|\\.sh|\\.yaml|\\.ini|\\.in|^\\.ci/run)$")
list(FILTER files EXCLUDE REGEX "^tests/fuzz/corpus/")
list(FILTER files EXCLUDE REGEX "^tests/check_doc_paths\\.cmake$")

# True when `pattern` (repository-relative; *, <placeholder> and an all-capitals file or
# directory name such as NAME.yaml are wildcards) names something.
function(path_exists pattern out)
  string(REGEX REPLACE "<[^>]*>" "*" glob "${pattern}")
  string(REGEX REPLACE "/[A-Z][A-Z0-9_]*(\\.|/|$)" "/*\\1" glob "${glob}")
  if(glob MATCHES "[*]")
    file(GLOB hits "${ROOT}/${glob}")
    if(hits)
      set(${out} TRUE PARENT_SCOPE)
    else()
      set(${out} FALSE PARENT_SCOPE)
    endif()
  elseif(EXISTS "${ROOT}/${glob}")
    set(${out} TRUE PARENT_SCOPE)
  else()
    set(${out} FALSE PARENT_SCOPE)
  endif()
endfunction()

foreach(file IN LISTS files)
  if(NOT EXISTS "${ROOT}/${file}" OR IS_DIRECTORY "${ROOT}/${file}")
    continue()  # deleted in the work tree, or a submodule
  endif()
  file(READ "${ROOT}/${file}" text)
  # CMake list syntax would split on these; they never occur inside a path.
  string(REPLACE ";" " " text "${text}")
  string(REPLACE "[" " " text "${text}")
  string(REPLACE "](" " LINK:" text "${text}")
  string(REPLACE "]" " " text "${text}")

  # 1. Repository paths: a top-level directory name not preceded by a path character (so
  #    build/apps/..., ${ROOT}/share/... and URLs are not read as repository paths).
  string(REGEX MATCHALL "[^A-Za-z0-9_./$}:-](${top_dirs})/[A-Za-z0-9_./*{},<>-]*" hits
    " ${text}")
  foreach(hit IN LISTS hits)
    string(SUBSTRING "${hit}" 1 -1 path)
    string(REGEX REPLACE "[.,:]+$" "" path "${path}")
    if(path MATCHES "${installed_paths}")
      continue()
    endif()
    # {a,b} alternatives: check each.
    set(variants "${path}")
    if(path MATCHES "^([^{]*){([^}]*)}(.*)$")
      set(prefix "${CMAKE_MATCH_1}")
      set(suffix "${CMAKE_MATCH_3}")
      string(REPLACE "," ";" alternatives "${CMAKE_MATCH_2}")
      set(variants "")
      foreach(alternative IN LISTS alternatives)
        list(APPEND variants "${prefix}${alternative}${suffix}")
      endforeach()
    endif()
    foreach(variant IN LISTS variants)
      string(REGEX REPLACE ",.*$" "" variant "${variant}")
      path_exists("${variant}" ok)
      if(NOT ok)
        list(APPEND errors "${file}: names '${variant}', which does not exist")
      endif()
    endforeach()
  endforeach()

  # 2. Relative Markdown links and images.
  if(file MATCHES "\\.md$")
    get_filename_component(dir "${ROOT}/${file}" DIRECTORY)
    string(REGEX MATCHALL "LINK:[^) \n]+" links "${text}")
    foreach(link IN LISTS links)
      string(SUBSTRING "${link}" 5 -1 target)
      if(target MATCHES "^(https?:|mailto:|#)")
        continue()
      endif()
      string(REGEX REPLACE "#.*$" "" target "${target}")
      get_filename_component(resolved "${dir}/${target}" ABSOLUTE)
      string(FIND "${resolved}/" "${ROOT}/" at)
      if(NOT at EQUAL 0)
        list(APPEND errors "${file}: link '${target}' points out of the repository")
      elseif(NOT EXISTS "${resolved}")
        list(APPEND errors "${file}: link '${target}' points at nothing")
      endif()
    endforeach()
  endif()

  # 3. Nothing but tests points at the directory beside the repository.
  if(NOT file MATCHES "^tests/")
    string(FIND "${text}" "../shared" at)
    if(NOT at EQUAL -1)
      list(APPEND errors "${file}: mentions '../shared' (outside the repository)")
    endif()
  endif()
endforeach()

file(SIZE "${ROOT}/README.md" readme_size)
if(readme_size GREATER readme_limit)
  list(APPEND errors "README.md: ${readme_size} bytes, more than ${readme_limit}")
endif()

list(LENGTH files scanned)
if(errors)
  list(REMOVE_DUPLICATES errors)
  list(LENGTH errors count)
  string(REPLACE ";" "\n  " report "${errors}")
  message(FATAL_ERROR "docs.paths: ${count} problem(s) in ${scanned} files:\n  ${report}")
endif()
message(STATUS "docs.paths: ${scanned} files, every named path exists; README.md ${readme_size} bytes")
