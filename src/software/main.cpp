// prunesfm: the command-line entry point. Each subcommand lives in commands/<name>.cpp.
//
// Exit codes: 0 success; 1 bad input or a failed step (one line on stderr naming the file and
// the problem); CLI11's own codes (105 and up) for malformed command lines.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "sfm_pruning/util/error.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"
#include "software/help_format.hpp"

int main(int argc, char** argv) {
  prunesfm::SilenceSolverLogging();
  std::string engines;
  for (const char* engine : prunesfm::kEngineNames) engines += std::string(engines.empty() ? "" : ", ") + engine;
  CLI::App app{
      "PruneSfM: global structure-from-motion that survives repeated and symmetric structure.\n"
      "Engines: " + engines + " (GLOBAL_PRUNED removes spurious view-graph edges first).\n"
      "Run 'prunesfm <subcommand> --help' for the options of each step (--help_all: every option).",
      "prunesfm"};
  app.require_subcommand(1);
  prunesfm::UseCompactHelp(&app);
  // A malformed command line gets the same one-line error as a bad file, and where to look.
  app.failure_message([](const CLI::App* parsed, const CLI::Error& error) {
    std::string help = "prunesfm --help";
    for (const CLI::App* subcommand : parsed->get_subcommands()) {
      help = "prunesfm " + subcommand->get_name() + " --help";
    }
    return "prunesfm: error: " + std::string(error.what()) + " (see '" + help + "')\n";
  });
  app.set_version_flag("--version", "prunesfm 0.1.0");
  prunesfm::AddQuietFlag(&app);

  prunesfm::AddInitCommand(app);
  prunesfm::AddFeaturesCommand(app);
  prunesfm::AddMatchCommand(app);
  prunesfm::AddReconstructCommand(app);
  prunesfm::AddRunCommand(app);
  prunesfm::AddPruneCommand(app);
  prunesfm::AddConvertCommand(app);
  prunesfm::AddEvaluateCommand(app);
  prunesfm::AddExportCommand(app);
  prunesfm::AddSynthCommand(app);
  prunesfm::AddReportCommand(app);
  prunesfm::AddEpipolarCommand(app);
  prunesfm::CheckEveryNumber(&app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const sfm_pruning::Error& e) {
    std::fprintf(stderr, "prunesfm: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "prunesfm: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
