#include "sfm_pruning/report/timings_drawing.hpp"

#include <algorithm>
#include <map>

#include "sfm_pruning/report/palette.hpp"
#include "sfm_pruning/report/svg_builder.hpp"

namespace sfm_pruning {

Rgb RunColor(size_t index) { return index == 0 ? Rgb{31, 119, 180} : Rgb{255, 127, 14}; }

std::string DrawTimingsSvg(const std::vector<TimedRun>& runs, double width) {
  std::vector<std::string> stages;
  std::vector<std::map<std::string, double>> seconds(runs.size());
  double longest = 1e-9;
  for (size_t r = 0; r < runs.size(); ++r) {
    for (const StageTotal& total : TotalsByStage(runs[r].stages)) {
      if (std::find(stages.begin(), stages.end(), total.stage) == stages.end()) stages.push_back(total.stage);
      seconds[r][total.stage] = total.seconds;
      longest = std::max(longest, total.seconds);
    }
  }
  const double label_width = 190.0, value_width = 70.0, bar_height = 13.0, row_gap = 9.0;
  const double row_height = static_cast<double>(runs.size()) * bar_height + row_gap;
  const double height = static_cast<double>(stages.size() + 1) * row_height + 12.0;
  const double bar_space = width - label_width - value_width;
  SvgBuilder svg(width, height);
  for (size_t s = 0; s < stages.size(); ++s) {
    const double top = 6.0 + static_cast<double>(s) * row_height;
    svg.Text({label_width - 8.0, top + row_height / 2.0}, stages[s],
             "text-anchor=\"end\" dominant-baseline=\"middle\" class=\"label\"");
    for (size_t r = 0; r < runs.size(); ++r) {
      const auto it = seconds[r].find(stages[s]);
      const double value = it == seconds[r].end() ? 0.0 : it->second;
      const double y = top + static_cast<double>(r) * bar_height;
      const double length = std::max(1.0, bar_space * value / longest);
      svg.Rect(label_width, y, it == seconds[r].end() ? 0.0 : length, bar_height - 2.0,
               "fill=\"" + RunColor(r).Hex() + "\" rx=\"2\"",
               runs[r].label + ": " + stages[s] + " " + FormatNumber(value, 3) + " s");
      svg.Text({label_width + length + 5.0, y + (bar_height - 2.0) / 2.0},
               it == seconds[r].end() ? "-" : FormatNumber(value, 2) + " s",
               "dominant-baseline=\"middle\" class=\"value\"");
    }
  }
  // Totals under the stages.
  const double top = 6.0 + static_cast<double>(stages.size()) * row_height;
  std::string totals;
  for (size_t r = 0; r < runs.size(); ++r) {
    double total = 0.0;
    for (const auto& [stage, value] : seconds[r]) total += value;
    totals += (r == 0 ? "" : "    ") + runs[r].label + ": " + FormatNumber(total, 2) + " s";
  }
  svg.Text({label_width, top + row_height / 2.0}, "total  " + totals, "dominant-baseline=\"middle\" class=\"total\"");
  return svg.Finish("timings", "per-stage wall time");
}

}  // namespace sfm_pruning
