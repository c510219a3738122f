// Little helpers for the fixed-layout binary files of OpenMVG (.desc, cereal PortableBinary
// matches): bounds-checked reads that turn truncation into an Error naming the file, and raw
// writes of fixed-size integers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::openmvg_binary {

class ByteReader {
 public:
  // `bytes` must outlive the reader; `source` is the file name used in errors.
  ByteReader(const std::string& bytes, std::string source) : bytes_(bytes), source_(std::move(source)) {}

  // Byte-swaps every later integer read (a PortableBinary archive written on a big-endian host).
  void set_swap_bytes(bool swap) { swap_bytes_ = swap; }

  size_t position() const { return pos_; }
  size_t remaining() const { return bytes_.size() - pos_; }

  // Reads one integer; `what` names the field in the truncation error.
  template <typename T>
  T Read(const std::string& what) {
    static_assert(std::is_integral_v<T>, "ByteReader reads integers only");
    Require(sizeof(T), what);
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return swap_bytes_ ? SwapBytes(value) : value;
  }

  // Copies `size` raw bytes.
  void ReadBytes(void* out, size_t size, const std::string& what) {
    Require(size, what);
    std::memcpy(out, bytes_.data() + pos_, size);
    pos_ += size;
  }

  // Throws unless `size` more bytes are available.
  void Require(size_t size, const std::string& what) const {
    if (size > remaining()) {
      throw FileError(source_, "truncated file: " + what + " needs " + std::to_string(size) + " bytes at offset " +
                                   std::to_string(pos_) + ", only " + std::to_string(remaining()) + " left");
    }
  }

 private:
  template <typename T>
  static T SwapBytes(T value) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  const std::string& bytes_;
  std::string source_;
  size_t pos_ = 0;
  bool swap_bytes_ = false;
};

// Writes one integer in the host's byte order (little-endian on every platform we build for).
template <typename T>
void WriteRaw(std::ostream& out, T value) {
  static_assert(std::is_integral_v<T>, "WriteRaw writes integers only");
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

}  // namespace sfm_pruning::openmvg_binary
