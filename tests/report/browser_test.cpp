// The report page in a real browser: Debian's headless Chromium loads it with no console message
// (the page logs nothing when its script runs cleanly) and renders a screenshot. Skipped with a
// message when chromium is not installed.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "report_test_run.hpp"
#include "sfm_pruning/report/html_report.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

constexpr const char* kChromium = "/usr/bin/chromium";

struct BrowserRun {
  int exit_code = -1;
  std::vector<std::string> console;  // the page's console messages (Chromium logs them as INFO:CONSOLE)
};

BrowserRun LoadInChromium(const fs::path& page, const fs::path& screenshot, const fs::path& log) {
  // A fresh profile per run: no first-run state, no clash between parallel tests.
  // A hung browser must not hang the test suite: coreutils' timeout ends it (exit 124).
  const std::string command = "timeout 120 " + std::string(kChromium) + " --headless --disable-gpu --no-sandbox --hide-scrollbars" +
                              " --user-data-dir=" + (log.parent_path() / "profile").string() +
                              " --window-size=1280,2400 --enable-logging=stderr --v=0 --screenshot=" +
                              screenshot.string() + " file://" + page.string() + " > " + log.string() + " 2>&1";
  BrowserRun run;
  run.exit_code = std::system(command.c_str());
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);) {
    if (line.find(":CONSOLE") != std::string::npos) run.console.push_back(line);
  }
  return run;
}

TEST(ReportBrowser, ChromiumLoadsThePageWithoutConsoleMessagesAndScreenshotsIt) {
  if (!fs::exists(kChromium)) GTEST_SKIP() << "chromium not installed (scripts/install_deps.sh installs it)";
  const fs::path dir = ScratchDir("report_browser");

  // The capture works: a page that throws is seen.
  std::ofstream(dir / "throws.html") << "<!DOCTYPE html><html><body><script>notDefined();</script></body></html>";
  const BrowserRun control = LoadInChromium(dir / "throws.html", dir / "throws.png", dir / "throws.log");
  ASSERT_EQ(control.exit_code, 0);
  ASSERT_EQ(control.console.size(), 1u);
  EXPECT_NE(control.console[0].find("Uncaught ReferenceError"), std::string::npos);

  const SfmData scene = RingScene(12);
  WriteTestRun(scene, "GLOBAL_PRUNED", dir / "pruned");
  WriteTestRun(scene, "GLOBAL", dir / "folded");
  HtmlReportInput input;
  input.runs = {ReadRunFolder(dir / "pruned"), ReadRunFolder(dir / "folded")};
  input.ground_truth = scene;
  input.ground_truth_source = "truth";
  std::ofstream(dir / "report.html") << BuildHtmlReport(input);

  const BrowserRun run = LoadInChromium(dir / "report.html", dir / "report.png", dir / "report.log");
  ASSERT_EQ(run.exit_code, 0);
  EXPECT_TRUE(run.console.empty()) << run.console.front();
  // A PNG of the requested width and height.
  std::ifstream png(dir / "report.png", std::ios::binary);
  std::string header(24, '\0');
  png.read(header.data(), 24);
  ASSERT_EQ(header.substr(1, 3), "PNG");
  const auto be32 = [&](size_t at) {
    return (uint32_t(uint8_t(header[at])) << 24) | (uint32_t(uint8_t(header[at + 1])) << 16) |
           (uint32_t(uint8_t(header[at + 2])) << 8) | uint32_t(uint8_t(header[at + 3]));
  };
  EXPECT_EQ(be32(16), 1280u);
  EXPECT_EQ(be32(20), 2400u);
  EXPECT_GT(fs::file_size(dir / "report.png"), 50000u) << "a rendered page, not a blank one";
}

}  // namespace
}  // namespace sfm_pruning::testing
