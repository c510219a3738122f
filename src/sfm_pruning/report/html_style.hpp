// The stylesheet and script embedded in every report page.
#pragma once

namespace sfm_pruning {

extern const char* const kReportCss;
// Toggles the removed edges of the view-graph panels; logs nothing on success.
extern const char* const kReportScript;

}  // namespace sfm_pruning
