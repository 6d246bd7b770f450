# The version and git commit recorded in every run log. The commit is read at build time (not
# only at configure time) so a rebuilt binary never reports a stale commit.
set(MSSPH_GENERATED_DIR "${PROJECT_BINARY_DIR}/generated")
add_custom_target(mssph_git_commit
  COMMAND "${CMAKE_COMMAND}" -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
          -DOUTPUT=${MSSPH_GENERATED_DIR}/git_commit.inc
          -P "${PROJECT_SOURCE_DIR}/cmake/WriteGitCommit.cmake"
  BYPRODUCTS "${MSSPH_GENERATED_DIR}/git_commit.inc"
  COMMENT "Reading the git commit"
  VERBATIM)
