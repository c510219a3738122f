// Every subcommand of prunesfm adds itself to the app through one of these functions, each
// defined in commands/<name>.cpp. main.cpp calls them in the order of the help text.
#pragma once

namespace CLI {
class App;
}

namespace prunesfm {

void AddConvertCommand(CLI::App& app);
void AddEpipolarCommand(CLI::App& app);
void AddEvaluateCommand(CLI::App& app);
void AddExportCommand(CLI::App& app);
void AddPruneCommand(CLI::App& app);
void AddFeaturesCommand(CLI::App& app);
void AddInitCommand(CLI::App& app);
void AddMatchCommand(CLI::App& app);
void AddReconstructCommand(CLI::App& app);
void AddReportCommand(CLI::App& app);
void AddRunCommand(CLI::App& app);
void AddSynthCommand(CLI::App& app);

}  // namespace prunesfm
