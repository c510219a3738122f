// Median, mean and maximum of error lists: one implementation for every report in the library
// (evaluation, rotation averaging residuals, pruning consistency tests).
#pragma once

#include <vector>

namespace sfm_pruning {

// Median (mean of the two middle values for an even count); 0 for an empty list.
double Median(std::vector<double> values);
// Arithmetic mean; 0 for an empty list.
double Mean(const std::vector<double>& values);
// Largest value; 0 for an empty list.
double Max(const std::vector<double>& values);

}  // namespace sfm_pruning
