// Reading the JSON files of a run folder with one-line errors: parse failures and wrong or
// missing fields become Error("<file>: <what>") instead of nlohmann's exceptions.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

namespace sfm_pruning {

// Parses `path`; throws Error naming it when it cannot be read or is not a JSON object.
nlohmann::json ReadJsonObject(const std::filesystem::path& path);

// Runs `read` (which navigates `json` with at()/get<>()) and turns any nlohmann exception into
// Error("<path>: <description>: <nlohmann message>").
void ReadJsonFields(const std::filesystem::path& path, const std::string& description,
                    const std::function<void()>& read);

}  // namespace sfm_pruning
