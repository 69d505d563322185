# `cmake --install`: the shared library with its versioned SONAME symlinks, the static library,
# the header, a relocatable pkg-config file and a CMake package giving profsubd::profsubd.
include(CMakePackageConfigHelpers)

install(FILES "${PROFSUBD_LIB_DIR}/${PROFSUBD_SHARED_REAL}"
        DESTINATION ${CMAKE_INSTALL_LIBDIR}
        PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
# Symlinks are installed as symlinks.
install(FILES "${PROFSUBD_LIB_DIR}/${PROFSUBD_SONAME}" "${PROFSUBD_LIB_DIR}/libprofsubd.so"
              "${PROFSUBD_LIB_DIR}/libprofsubd.a"
        DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES "${PROFSUBD_INCLUDE_DIR}/profsubd.h" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

# pkg-config: the prefix is found relative to the .pc file, so installing with
# `cmake --install build --prefix DIR` gives a correct file whatever prefix was configured.
file(RELATIVE_PATH PROFSUBD_PC_TO_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
string(REGEX REPLACE "/$" "" PROFSUBD_PC_TO_PREFIX "${PROFSUBD_PC_TO_PREFIX}")
configure_file(cmake/profsubd.pc.in "${CMAKE_BINARY_DIR}/profsubd.pc" @ONLY)
install(FILES "${CMAKE_BINARY_DIR}/profsubd.pc" DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

set(PROFSUBD_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/profsubd)
configure_package_config_file(cmake/profsubdConfig.cmake.in
  "${CMAKE_BINARY_DIR}/profsubdConfig.cmake"
  INSTALL_DESTINATION ${PROFSUBD_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_LIBDIR)
# 0.x releases may break the ABI at every minor version (as the SONAME major says for 1.x on).
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(_profsubd_compat SameMinorVersion)
else()
  set(_profsubd_compat SameMajorVersion)
endif()
write_basic_package_version_file("${CMAKE_BINARY_DIR}/profsubdConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY ${_profsubd_compat})
install(FILES "${CMAKE_BINARY_DIR}/profsubdConfig.cmake" "${CMAKE_BINARY_DIR}/profsubdConfigVersion.cmake"
        DESTINATION ${PROFSUBD_CMAKE_DIR})
