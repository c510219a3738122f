# prunesfm_add_module(NAME SOURCES ... DEPENDS ...)
# One static library per folder of src/sfm_pruning, named sfm_pruning_<NAME>. Modules depend on
# each other only along the data flow (sfm <- io, geometry <- view_graph <- global <- pruning), so
# a change in one module rebuilds only the modules downstream of it.
function(prunesfm_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  set(target sfm_pruning_${name})
  add_library(${target} STATIC ${ARG_SOURCES})
  add_library(sfm_pruning::${name} ALIAS ${target})
  # Headers: the source tree when building, <prefix>/include (sfm_pruning/<module>/...) installed.
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
                                              $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # The Eigen configuration every user of our headers must share (PruneSfMFlags.cmake says why).
  target_compile_definitions(${target} PUBLIC ${PRUNESFM_EIGEN_DEFINITIONS})
  target_compile_options(${target} PRIVATE ${PRUNESFM_WARNING_FLAGS})
  target_link_libraries(${target} PUBLIC ${ARG_DEPENDS})
  # A sanitized library needs the sanitizers' runtime in whatever links it, installed users too.
  if(PRUNESFM_SANITIZE)
    target_link_options(${target} INTERFACE ${PRUNESFM_SANITIZERS})
  endif()
  # Installed and exported as PruneSfM::<NAME> (cmake/PruneSfMInstall.cmake).
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON EXPORT_NAME ${name})
  install(TARGETS ${target} EXPORT PruneSfMTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()

# prunesfm_add_test(NAME SOURCES ... DEPENDS ... [LABELS ...])
# One GoogleTest executable per module folder of tests/; every TEST becomes a ctest entry.
# LABELS: `slow` for end-to-end engine runs (the sanitizer job skips them), `interop` for tests
# that drive the real colmap executable.
function(prunesfm_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${PRUNESFM_WARNING_FLAGS})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} prunesfm_test_support GTest::gtest GTest::gtest_main)
  # Paths reach the tests as compile definitions of prunesfm_test_support (tests/CMakeLists.txt),
  # not as ctest ENVIRONMENT: a list-valued ENVIRONMENT does not survive gtest_discover_tests.
  if(ARG_LABELS)
    gtest_discover_tests(${name} PROPERTIES LABELS "${ARG_LABELS}" DISCOVERY_TIMEOUT 60)
  else()
    gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60)
  endif()
endfunction()
