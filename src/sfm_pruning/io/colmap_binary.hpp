// Little-endian binary reading and writing for COLMAP's .bin model files. The reader checks
// every access against the end of the buffer so a truncated file becomes an Error, not a crash.
#pragma once

#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <type_traits>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::colmap_binary {

static_assert(sizeof(double) == 8, "COLMAP binary files store IEEE-754 float64");

// Host byte order is assumed little endian (x86-64, aarch64), as in COLMAP's own files.
class Reader {
 public:
  Reader(const std::string& bytes, std::string source) : bytes_(bytes), source_(std::move(source)) {}

  template <typename T>
  T Read() {
    static_assert(std::is_trivially_copyable_v<T>);
    Require(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    return value;
  }

  // A NUL-terminated string.
  std::string ReadString() {
    const size_t end = bytes_.find('\0', offset_);
    if (end == std::string::npos) throw FileError(source_, "truncated file (unterminated string)");
    std::string value = bytes_.substr(offset_, end - offset_);
    offset_ = end + 1;
    return value;
  }

  // Throws unless `count` records of `record_size` bytes can still follow; guards the
  // allocations sized by counts read from the file.
  void RequireRecords(uint64_t count, size_t record_size) const {
    if (record_size != 0 && count > (bytes_.size() - offset_) / record_size) {
      throw FileError(source_, "truncated file (count " + std::to_string(count) + " exceeds the file size)");
    }
  }

  bool AtEnd() const { return offset_ == bytes_.size(); }
  const std::string& source() const { return source_; }

 private:
  void Require(size_t n) const {
    if (bytes_.size() - offset_ < n) throw FileError(source_, "truncated file");
  }

  const std::string& bytes_;
  std::string source_;
  size_t offset_ = 0;
};

template <typename T>
void Write(std::ostream& out, T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

inline void WriteString(std::ostream& out, const std::string& value) {
  out.write(value.c_str(), value.size() + 1);
}

}  // namespace sfm_pruning::colmap_binary
