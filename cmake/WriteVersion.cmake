# cmake -DSOURCE_DIR=... -DBINARY_DIR=... -DPROJECT_VERSION=... -P WriteVersion.cmake: writes generated/core/version.hpp
# with the commit the tree is at ("-dirty" when tracked files differ from it); configure_file leaves the file
# untouched when nothing changed, so a build at the same commit recompiles nothing.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE SUSPEND_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _git)
if(NOT _git EQUAL 0 OR SUSPEND_GIT_COMMIT STREQUAL "")
  set(SUSPEND_GIT_COMMIT "unknown")
else()
  execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE _changes ERROR_QUIET)
  if(NOT _changes STREQUAL "")
    string(APPEND SUSPEND_GIT_COMMIT "-dirty")
  endif()
endif()
configure_file(${SOURCE_DIR}/core/version.hpp.in ${BINARY_DIR}/generated/core/version.hpp @ONLY)
