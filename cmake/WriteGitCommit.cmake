# Writes the current commit (with -dirty for local changes) into OUTPUT, touching it only when
# it changed, so an unchanged tree rebuilds nothing. A tree without git metadata, unpacked from a
# `git archive` tarball, has the archived commit in archive_commit.txt (export-subst in
# .gitattributes): it is written with the suffix -archive, since local changes cannot be told.
# Otherwise the commit is "unknown".
set(commit "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND "${GIT_EXECUTABLE}" describe --always --dirty --abbrev=12
    WORKING_DIRECTORY "${SOURCE_DIR}" OUTPUT_VARIABLE described
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
  if(rc EQUAL 0 AND described)
    set(commit "${described}")
  endif()
endif()
set(archive_file "${SOURCE_DIR}/cmake/archive_commit.txt")
if(commit STREQUAL "unknown" AND EXISTS "${archive_file}")
  file(STRINGS "${archive_file}" archived LIMIT_COUNT 1)
  if(archived MATCHES "^[0-9a-f]+$")
    string(LENGTH "${archived}" length)
    if(length GREATER_EQUAL 12)
      string(SUBSTRING "${archived}" 0 12 archived)
      set(commit "${archived}-archive")
    endif()
  endif()
endif()
set(content "\"${commit}\"\n")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT "${old}" STREQUAL "${content}")
  file(WRITE "${OUTPUT}" "${content}")
endif()
