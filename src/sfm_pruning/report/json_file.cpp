#include "sfm_pruning/report/json_file.hpp"

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {

nlohmann::json ReadJsonObject(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) throw FileError(path.string(), "no such file");
  nlohmann::json json = nlohmann::json::parse(ReadFileToString(path, false), nullptr, false);
  if (json.is_discarded()) throw FileError(path.string(), "not valid JSON");
  if (!json.is_object()) throw FileError(path.string(), "not a JSON object");
  return json;
}

void ReadJsonFields(const std::filesystem::path& path, const std::string& description,
                    const std::function<void()>& read) {
  try {
    read();
  } catch (const nlohmann::json::exception& e) {
    throw FileError(path.string(), description + ": " + e.what());
  }
}

}  // namespace sfm_pruning
