#include "sfm_pruning/report/palette.hpp"

#include <cstdio>

namespace sfm_pruning {

std::string Rgb::Hex() const {
  char buffer[8];
  std::snprintf(buffer, sizeof(buffer), "#%02x%02x%02x", r, g, b);
  return buffer;
}

Rgb SubgraphColor(int index) {
  // Twelve well separated hues of similar lightness (readable on white, distinct from the red of
  // removed edges as far as twelve colours allow).
  static constexpr std::array<Rgb, 12> kColors = {{{31, 119, 180},
                                                   {255, 127, 14},
                                                   {44, 160, 44},
                                                   {148, 103, 189},
                                                   {23, 190, 207},
                                                   {188, 189, 34},
                                                   {140, 86, 75},
                                                   {227, 119, 194},
                                                   {57, 59, 121},
                                                   {0, 128, 128},
                                                   {173, 73, 74},
                                                   {99, 121, 57}}};
  if (index < 0) return {150, 150, 150};
  return kColors[static_cast<size_t>(index) % kColors.size()];
}

}  // namespace sfm_pruning
