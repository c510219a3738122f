# The installed package: `cmake --install BUILD --prefix P` puts the libraries (one static library
# per module), the headers under P/include/sfm_pruning/, the prunesfm executable, the image codecs
# module and P/lib/cmake/PruneSfM/, so another project can
#   find_package(PruneSfM REQUIRED)
#   target_link_libraries(app PRIVATE PruneSfM::sfm_pruning)   # or one module, e.g. PruneSfM::io
# and gets the include path, the Eigen definitions and every dependency with it
# (examples/consumer is such a project; scripts/test.sh builds and runs it against an install).
include(CMakePackageConfigHelpers)
set(PRUNESFM_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/PruneSfM)
install(EXPORT PruneSfMTargets NAMESPACE PruneSfM:: DESTINATION ${PRUNESFM_CMAKE_INSTALL_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/PruneSfMConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/PruneSfMConfig.cmake
                              INSTALL_DESTINATION ${PRUNESFM_CMAKE_INSTALL_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/PruneSfMConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/PruneSfMConfig.cmake ${PROJECT_BINARY_DIR}/PruneSfMConfigVersion.cmake
        DESTINATION ${PRUNESFM_CMAKE_INSTALL_DIR})
