# Compiler flags shared by every target.
#
# Eigen alignment is an ODR rule across the whole process: libopengv.so and libceres.a were built
# for baseline x86-64 (16-byte Eigen alignment, malloc already aligned). Every translation unit of
# ours must see the same Eigen allocator configuration, so we never add -march=native / -mavx and
# we pin the two Eigen macros project-wide (see docs/dependencies.md).
add_compile_definitions(EIGEN_MAX_ALIGN_BYTES=16 EIGEN_MALLOC_ALREADY_ALIGNED=1)

set(PRUNESFM_WARNING_FLAGS -Wall -Wextra -Wpedantic -Wno-unused-parameter)
if(PRUNESFM_WARNINGS_AS_ERRORS)
  list(APPEND PRUNESFM_WARNING_FLAGS -Werror)
endif()

if(PRUNESFM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
