# Every dependency comes from a Debian 12 package (scripts/install_deps.sh installs them by name).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)                 # Eigen3::Eigen
find_package(Ceres 2.1 REQUIRED)                            # Ceres::ceres (static)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs features2d flann calib3d)
find_package(opengv REQUIRED)                               # opengv
find_package(flann REQUIRED CONFIG)                         # flann::flann_cpp (header-only C++ API)
find_package(cereal REQUIRED)                               # cereal::cereal
find_package(igraph 0.10 REQUIRED)                          # igraph::igraph
find_package(SQLite3 REQUIRED)                              # SQLite::SQLite3
find_package(CLI11 REQUIRED)                                # CLI11::CLI11
find_package(nlohmann_json 3 REQUIRED)                      # nlohmann_json::nlohmann_json
# BLAS by its generic name (-lblas = libblas.so.3), not a vendor's library: Debian's alternatives
# then decide at run time, and install_deps.sh installs OpenBLAS, which takes precedence.
set(BLA_VENDOR Generic)
find_package(BLAS REQUIRED)                                 # BLAS::BLAS
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBEXIF REQUIRED IMPORTED_TARGET libexif) # PkgConfig::LIBEXIF
if(PRUNESFM_BUILD_TESTS)
  find_package(GTest REQUIRED)                              # GTest::gtest GTest::gtest_main
  include(GoogleTest)
endif()
