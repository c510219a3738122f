#include "software/help_format.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace prunesfm {
namespace {

size_t CountExpertOptions(const CLI::App* app) {
  return app->get_options([](const CLI::Option* option) { return option->get_group() == kExpertOptionsGroup; })
      .size();
}

// An option group whose expert options are hidden leaves a line of indentation only where their
// heading would be.
std::string WithoutBlankIndentedLines(const std::string& help) {
  std::string kept;
  size_t start = 0;
  while (start < help.size()) {
    size_t end = help.find('\n', start);
    end = end == std::string::npos ? help.size() : end + 1;
    const std::string line = help.substr(start, end - start);
    const bool indentation_only = line.size() > 1 && line.find_first_not_of(" \n") == std::string::npos;
    if (!indentation_only) kept += line;
    start = end;
  }
  return kept;
}

class CompactHelpFormatter : public CLI::Formatter {
 public:
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override {
    // Sub is the nested call for an option group or, under --help_all, a listed subcommand: it
    // keeps the mode of the help being printed.
    if (mode == CLI::AppFormatMode::Sub) return CLI::Formatter::make_help(app, std::move(name), mode);
    expand_expert_ = mode == CLI::AppFormatMode::All;
    return WithoutBlankIndentedLines(CLI::Formatter::make_help(app, std::move(name), mode));
  }

  std::string make_group(std::string group, bool is_positional,
                         std::vector<const CLI::Option*> options) const override {
    if (group == kExpertOptionsGroup && !expand_expert_) return "";  // counted in the footer
    return CLI::Formatter::make_group(std::move(group), is_positional, std::move(options));
  }

  std::string make_footer(const CLI::App* app) const override {
    std::string footer = CLI::Formatter::make_footer(app);
    if (expand_expert_) return footer;
    size_t hidden = CountExpertOptions(app);
    for (const CLI::App* group : app->get_subcommands({})) {
      if (group->get_name().empty()) hidden += CountExpertOptions(group);  // an option group
    }
    if (hidden == 0) return footer;
    return footer + std::to_string(hidden) + " expert options are not shown: --help_all lists them.\n";
  }

 private:
  // Help is printed once per process, from the parsing thread.
  mutable bool expand_expert_ = false;
};

}  // namespace

CLI::Option* MarkExpert(CLI::Option* option) { return option->group(kExpertOptionsGroup); }

void MarkExpertExcept(CLI::App* group, const std::string& shown) {
  for (CLI::Option* option : group->get_options()) {
    const bool help_flag = option == group->get_help_ptr() || option == group->get_help_all_ptr();
    if (!help_flag && option->get_name() != shown) MarkExpert(option);
  }
}

void UseCompactHelp(CLI::App* app) {
  app->formatter(std::make_shared<CompactHelpFormatter>());
  app->set_help_all_flag("--help_all", "Print this help with the expert options too and exit");
}

}  // namespace prunesfm
