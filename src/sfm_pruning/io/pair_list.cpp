#include "sfm_pruning/io/pair_list.hpp"

#include <string>
#include <string_view>
#include <vector>

#include "sfm_pruning/io/openmvg_text_tokens.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

PairSet ReadPairList(const fs::path& path, size_t num_views) {
  const std::string text = ReadFileToString(path, false);
  const std::string source = path.string();
  PairSet pairs;
  openmvg_text::ForEachLine(text, [&](std::string_view line, size_t line_number) {
    const std::vector<std::string_view> tokens = openmvg_text::SplitWhitespace(line);
    if (tokens.empty()) return;
    const std::string where = "line " + std::to_string(line_number) + ": ";
    if (tokens.size() < 2) throw FileError(source, where + "a pair needs two view ids, found one");
    std::vector<IndexT> ids(tokens.size());
    for (size_t t = 0; t < tokens.size(); ++t) {
      if (!openmvg_text::ParseUInt32(tokens[t], &ids[t])) {
        throw FileError(source, where + "'" + std::string(tokens[t]) + "' is not a view id");
      }
      if (ids[t] >= num_views) {
        throw FileError(source, where + "view id " + std::to_string(ids[t]) +
                                    " is not below the number of views (" + std::to_string(num_views) + ")");
      }
    }
    for (size_t t = 1; t < ids.size(); ++t) {
      if (ids[t] == ids[0]) {
        throw FileError(source, where + "pair (" + std::to_string(ids[0]) + ", " + std::to_string(ids[t]) +
                                    ") pairs a view with itself");
      }
      pairs.insert(MakeViewPair(ids[0], ids[t]));
    }
  });
  return pairs;
}

void WritePairList(const fs::path& path, const PairSet& pairs) {
  WriteFileAtomically(path, false, [&](std::ostream& out) {
    for (const ViewPair& pair : pairs) out << pair.first << ' ' << pair.second << '\n';
  });
}

}  // namespace sfm_pruning
