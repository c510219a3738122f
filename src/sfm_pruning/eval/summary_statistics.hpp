// Median and mean of error lists, shared by the evaluation code.
#pragma once

#include <vector>

namespace sfm_pruning {

// Median (mean of the two middle values for an even count); 0 for an empty list.
double Median(std::vector<double> values);
// Arithmetic mean; 0 for an empty list.
double Mean(const std::vector<double>& values);

}  // namespace sfm_pruning
