// COLMAP database.db (ReadColmapDatabase: SQLite file, then every table's rows and blobs).
#include "fuzz_input.hpp"
#include "sfm_pruning/io/colmap_database.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sfm_pruning;
  return fuzz::Parse([&]() { ReadColmapDatabase(fuzz::WriteInput("database.db", fuzz::WholeInput(data, size))); });
}
