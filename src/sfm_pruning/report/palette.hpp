// Colours of the report: one categorical colour per subgraph (cycled past the table), and the
// fixed colours of kept, removed and ground-truth elements, shared by the SVG and PNG drawings.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace sfm_pruning {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  std::string Hex() const;  // "#rrggbb"
};

// Colour of accepted subgraph `index` (>= 0); index -1 (no subgraph) is neutral grey.
Rgb SubgraphColor(int index);

namespace report_colors {
inline constexpr Rgb kRemoved{214, 39, 40};       // removed edges, the estimated epipolar line
inline constexpr Rgb kKept{90, 98, 112};          // kept edges between subgraphs, plain edges
inline constexpr Rgb kTruth{44, 160, 44};         // ground truth (epipolar line, camera centres)
inline constexpr Rgb kCamera{31, 119, 180};       // estimated cameras without a subgraph
inline constexpr Rgb kPoint{110, 110, 110};       // points without colour
}  // namespace report_colors

}  // namespace sfm_pruning
