# The git commit is baked into the program so run.h5 records exactly which code produced it. It is read at every
# build, not only when CMake configures (a tree configured once and built at many commits still says which one).
set(_version_args -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DBINARY_DIR=${PROJECT_BINARY_DIR}
                  -DPROJECT_VERSION=${PROJECT_VERSION} -P ${PROJECT_SOURCE_DIR}/cmake/WriteVersion.cmake)
execute_process(COMMAND ${CMAKE_COMMAND} ${_version_args})
add_custom_target(suspend_version COMMAND ${CMAKE_COMMAND} ${_version_args}
                  BYPRODUCTS ${PROJECT_BINARY_DIR}/generated/core/version.hpp VERBATIM)
