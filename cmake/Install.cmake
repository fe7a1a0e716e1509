# `cmake --install build --prefix PREFIX`: PREFIX/bin/suspend, and beside each other in PREFIX/share/suspend the
# Python reader and exporters (python/suspend), the user tools (tools/*.py, which find python/ as ../python) and the
# shipped cases. `cpack -G DEB` (run in the build folder) packs the same tree as a Debian package for /usr.
include(GNUInstallDirs)
set(SUSPEND_DATA_DIR ${CMAKE_INSTALL_DATADIR}/suspend)

install(TARGETS suspend RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/suspend DESTINATION ${SUSPEND_DATA_DIR}/python
        FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
file(GLOB SUSPEND_TOOLS ${PROJECT_SOURCE_DIR}/tools/*.py)
install(PROGRAMS ${SUSPEND_TOOLS} DESTINATION ${SUSPEND_DATA_DIR}/tools)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cases/ DESTINATION ${SUSPEND_DATA_DIR}/cases)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

set(CPACK_PACKAGE_NAME suspend)
set(CPACK_PACKAGE_VENDOR "the suspend developers")
set(CPACK_PACKAGE_CONTACT "the suspend developers <suspend@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "rheology of dense non-Brownian suspensions: lubrication-DEM and FCM Stokes solvers with one contact module")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The shared libraries the binary links (FFTW, HDF5, yaml-cpp, OpenMP, MPI) are found by dpkg-shlibdeps; the
# Python side needs Debian's numpy, h5py and matplotlib (and gsd for `suspend export --format gsd`).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-numpy, python3-h5py, python3-matplotlib")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-gsd, python3-yaml, python3-scipy, ffmpeg")
include(CPack)
