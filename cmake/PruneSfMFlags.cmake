# Compiler flags shared by every target.
#
# Eigen alignment is an ODR rule across the whole process: libopengv.so and libceres.a were built
# for baseline x86-64 (16-byte Eigen alignment, malloc already aligned). Every translation unit of
# ours must see the same Eigen allocator configuration, so we never add -march=native / -mavx and
# we pin the two Eigen macros project-wide (see docs/dependencies.md). The library's targets also
# carry them as usage requirements, so a project built on the installed package cannot disagree.
set(PRUNESFM_EIGEN_DEFINITIONS EIGEN_MAX_ALIGN_BYTES=16 EIGEN_MALLOC_ALREADY_ALIGNED=1)
add_compile_definitions(${PRUNESFM_EIGEN_DEFINITIONS})

set(PRUNESFM_WARNING_FLAGS -Wall -Wextra -Wpedantic -Wno-unused-parameter)
if(PRUNESFM_WARNINGS_AS_ERRORS)
  list(APPEND PRUNESFM_WARNING_FLAGS -Werror)
endif()

if(PRUNESFM_SANITIZE)
  # ASan plus UBSan without the checks that instrument every pointer access: null (a null
  # dereference faults and ASan reports it), object-size (ASan checks the bounds), alignment (the
  # Eigen alignment is pinned above) and vptr. Measured on bundle_adjustment.cpp at -O1: with them
  # 2.4x the Release compile time, without them 1.0-1.3x, which is what lets CI build once.
  set(PRUNESFM_SANITIZERS -fsanitize=address,undefined -fno-sanitize=null,object-size,alignment,vptr)
  add_compile_options(${PRUNESFM_SANITIZERS} -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(${PRUNESFM_SANITIZERS})
  # GCC 12 documents that the sanitizers' instrumentation makes -Wmaybe-uninitialized report
  # false positives in optimised builds; it fires inside libstdc++'s <regex> (std::function in
  # _State) in code that the uninstrumented Release build compiles without a warning.
  list(APPEND PRUNESFM_WARNING_FLAGS -Wno-maybe-uninitialized)
endif()

if(PRUNESFM_FUZZ)
  # libFuzzer ships with clang (Debian: clang, libclang-rt-14-dev). Every library the fuzz targets
  # link is instrumented for coverage (fuzzer-no-link) and checked by ASan+UBSan, so a parser bug
  # deep in a reader is found and reported like one in the target itself.
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PRUNESFM_FUZZ needs clang: -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(PRUNESFM_FUZZ_SANITIZERS -fsanitize=address,undefined -fno-sanitize=null,object-size,alignment,vptr)
  add_compile_options(-fsanitize=fuzzer-no-link ${PRUNESFM_FUZZ_SANITIZERS} -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined
                      -fsanitize-ignorelist=${PROJECT_SOURCE_DIR}/tests/fuzz/sanitizer_ignorelist.txt)
  add_link_options(${PRUNESFM_FUZZ_SANITIZERS})
endif()
