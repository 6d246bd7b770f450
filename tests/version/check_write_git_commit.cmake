# Runs cmake/WriteGitCommit.cmake on trees without git metadata and checks the commit it writes:
# the archived commit with the suffix -archive, or "unknown" when the archive file is missing or
# was never substituted. In a git work tree it also archives HEAD's archive_commit.txt, as
# `git archive` does for a release tarball, and expects HEAD's commit from it.
# Usage: cmake -DSOURCE_DIR=<repository> -DWORK=<scratch folder> -P check_write_git_commit.cmake
set(script "${SOURCE_DIR}/cmake/WriteGitCommit.cmake")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
# Git must not find the repository that holds WORK (a build folder inside the clone).
set(ENV{GIT_CEILING_DIRECTORIES} "${WORK}")

function(expect_commit tree expected)
  execute_process(COMMAND "${CMAKE_COMMAND}" -DSOURCE_DIR=${tree} -DOUTPUT=${tree}/git_commit.inc -P "${script}"
    RESULT_VARIABLE rc)
  file(READ "${tree}/git_commit.inc" written)
  if(NOT rc EQUAL 0 OR NOT written STREQUAL "\"${expected}\"\n")
    message(FATAL_ERROR "${tree}: expected \"${expected}\", WriteGitCommit.cmake wrote ${written} (exit ${rc})")
  endif()
  message(STATUS "${tree}: ${written}")
endfunction()

function(tree_with name content)
  file(MAKE_DIRECTORY "${WORK}/${name}/cmake")
  if(NOT content STREQUAL "")
    file(WRITE "${WORK}/${name}/cmake/archive_commit.txt" "${content}\n")
  endif()
endfunction()

tree_with(archived "0123456789abcdef0123456789abcdef01234567")
expect_commit("${WORK}/archived" "0123456789ab-archive")
tree_with(unsubstituted "$Format:%H$")
expect_commit("${WORK}/unsubstituted" "unknown")
tree_with(not_a_hash "0123456789ab; rm -rf /")
expect_commit("${WORK}/not_a_hash" "unknown")
tree_with(without_file "")
expect_commit("${WORK}/without_file" "unknown")

unset(ENV{GIT_CEILING_DIRECTORIES})
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse HEAD WORKING_DIRECTORY "${SOURCE_DIR}"
    OUTPUT_VARIABLE head OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE in_git)
endif()
if(GIT_FOUND AND in_git EQUAL 0)
  file(MAKE_DIRECTORY "${WORK}/from_git_archive")
  execute_process(COMMAND "${GIT_EXECUTABLE}" archive --format=tar -o "${WORK}/head.tar" HEAD cmake/archive_commit.txt
    WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "git archive HEAD cmake/archive_commit.txt failed (exit ${rc})")
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" -E tar xf "${WORK}/head.tar" WORKING_DIRECTORY "${WORK}/from_git_archive")
  set(ENV{GIT_CEILING_DIRECTORIES} "${WORK}")
  string(SUBSTRING "${head}" 0 12 head12)
  expect_commit("${WORK}/from_git_archive" "${head12}-archive")
else()
  message(STATUS "not a git work tree: the git archive round trip is not run")
endif()
