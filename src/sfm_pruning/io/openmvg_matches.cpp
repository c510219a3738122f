#include "sfm_pruning/io/openmvg_matches.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sfm_pruning/io/colmap_binary.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_text_tokens.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

namespace {

enum class MatchFileFormat { kText, kBinary };

MatchFileFormat FormatFromExtension(const fs::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".txt") return MatchFileFormat::kText;
  if (extension == ".bin") return MatchFileFormat::kBinary;
  throw FileError(path.string(), "unknown match file extension '" + extension + "' (expected .txt or .bin)");
}

// cereal's PortableBinary header byte: 1 when the writer was little-endian.
constexpr uint8_t kLittleEndianFlag = 1;
constexpr uint8_t kBigEndianFlag = 0;

std::string PairName(IndexT I, IndexT J) {
  return "pair (" + std::to_string(I) + ", " + std::to_string(J) + ")";
}

// Collects the pairs of a file in the stored form (I < J) and applies the checks common to the
// text and binary readers.
class MatchCollector {
 public:
  MatchCollector(std::string source, const MatchReadOptions& options, MatchReadReport* report)
      : source_(std::move(source)), options_(options), report_(report) {}

  // `where` locates the pair in the file for error messages ("line 12", "record 3").
  void Add(IndexT I, IndexT J, std::vector<FeatureMatch> pair_matches, const std::string& where) {
    if (I == J) throw FileError(source_, where + ": " + PairName(I, J) + " matches a view with itself");
    if (I > J) {
      std::swap(I, J);
      for (FeatureMatch& m : pair_matches) std::swap(m.i, m.j);
    }
    if (options_.sfm_data != nullptr &&
        (options_.sfm_data->views.count(I) == 0 || options_.sfm_data->views.count(J) == 0)) {
      if (report_ != nullptr) {
        ++report_->dropped_pairs;
        report_->dropped_matches += pair_matches.size();
      }
      return;
    }
    if (options_.features != nullptr) CheckFeatureIndices(I, J, pair_matches, where);
    if (!matches_.emplace(ViewPair{I, J}, std::move(pair_matches)).second) {
      throw FileError(source_, where + ": " + PairName(I, J) + " is listed twice");
    }
  }

  PairwiseMatches Take() { return std::move(matches_); }

 private:
  size_t FeatureCount(IndexT view, IndexT I, IndexT J, const std::string& where) const {
    const auto found = options_.features->find(view);
    if (found == options_.features->end()) {
      throw FileError(source_,
                      where + ": " + PairName(I, J) + ": view " + std::to_string(view) + " has no features");
    }
    return found->second.size();
  }

  // "362 features", naming the view's feature file when the views are known: a .feat file cut
  // short shows up here, as indices past its end.
  std::string FeatureCountText(IndexT view, size_t count) const {
    std::string text = std::to_string(count) + " features";
    if (options_.sfm_data != nullptr) {
      const auto found = options_.sfm_data->views.find(view);
      if (found != options_.sfm_data->views.end()) {
        text += " in " + FeatureFilePath(found->second, {}, ".feat").string();
      }
    }
    return text;
  }

  void CheckFeatureIndices(IndexT I, IndexT J, const std::vector<FeatureMatch>& pair_matches,
                           const std::string& where) const {
    const size_t count_i = FeatureCount(I, I, J, where);
    const size_t count_j = FeatureCount(J, I, J, where);
    for (const FeatureMatch& m : pair_matches) {
      if (m.i >= count_i || m.j >= count_j) {
        const bool bad_i = m.i >= count_i;
        throw FileError(source_, where + ": " + PairName(I, J) + ": feature index " +
                                     std::to_string(bad_i ? m.i : m.j) + " out of range for view " +
                                     std::to_string(bad_i ? I : J) + " (" +
                                     FeatureCountText(bad_i ? I : J, bad_i ? count_i : count_j) + ")");
      }
    }
  }

  std::string source_;
  const MatchReadOptions& options_;
  MatchReadReport* report_;
  PairwiseMatches matches_;
};

PairwiseMatches ReadTextMatches(const fs::path& path, const MatchReadOptions& options,
                                MatchReadReport* report) {
  const std::string text = ReadFileToString(path, false);
  const std::string source = path.string();
  MatchCollector collector(source, options, report);
  openmvg_text::TokenScanner scanner(text);
  std::string_view token;
  std::string context;  // the pair being read, for errors; built once per pair, not per match
  // Reads the next token as an unsigned number no larger than `max_value`.
  const auto next_number = [&](const char* what, uint64_t max_value) {
    if (!scanner.Next(&token)) {
      throw FileError(source,
                      std::string("truncated file: missing ") + what + " of " + context + " at the end");
    }
    uint64_t value = 0;
    if (!openmvg_text::ParseUInt64(token, &value) || value > max_value) {
      throw FileError(source, "line " + std::to_string(scanner.line()) + ": expected " + what + " of " +
                                  context + ", found '" + std::string(token) + "'");
    }
    return value;
  };
  constexpr uint64_t kMaxIndex = std::numeric_limits<IndexT>::max();
  std::string_view first_token;
  while (scanner.Next(&first_token)) {
    uint32_t I = 0;
    if (!openmvg_text::ParseUInt32(first_token, &I)) {
      throw FileError(source, "line " + std::to_string(scanner.line()) + ": expected a view id, found '" +
                                  std::string(first_token) + "'");
    }
    const std::string where = "line " + std::to_string(scanner.line());
    context = "the pair starting at " + where;
    const auto J = static_cast<IndexT>(next_number("the second view id", kMaxIndex));
    context = PairName(I, J);
    const uint64_t count = next_number("the match count", std::numeric_limits<uint64_t>::max());
    std::vector<FeatureMatch> pair_matches;
    // Each match takes at least 4 characters ("i j\n"), which bounds a corrupt count.
    pair_matches.reserve(std::min<uint64_t>(count, text.size() / 4));
    for (uint64_t k = 0; k < count; ++k) {
      FeatureMatch m;
      m.i = static_cast<IndexT>(next_number("a feature index", kMaxIndex));
      m.j = static_cast<IndexT>(next_number("a feature index", kMaxIndex));
      pair_matches.push_back(m);
    }
    collector.Add(I, J, std::move(pair_matches), where);
  }
  return collector.Take();
}

// Reads the integers of a cereal PortableBinary archive, swapping them when the archive was
// written on a host of the other byte order (we run on little-endian hosts only).
class PortableBinaryReader {
 public:
  PortableBinaryReader(const std::string& bytes, const std::string& source) : reader_(bytes, source) {
    const auto flag = reader_.Read<uint8_t>();
    if (flag != kLittleEndianFlag && flag != kBigEndianFlag) {
      throw FileError(source,
                      "not a cereal portable binary file (endianness flag " + std::to_string(flag) + ")");
    }
    swap_bytes_ = flag == kBigEndianFlag;
  }

  template <typename T>
  T Read() {
    T value = reader_.Read<T>();
    if (swap_bytes_) {
      unsigned char raw[sizeof(T)];
      std::memcpy(raw, &value, sizeof(T));
      std::reverse(raw, raw + sizeof(T));
      std::memcpy(&value, raw, sizeof(T));
    }
    return value;
  }

  colmap_binary::Reader& bytes() { return reader_; }

 private:
  colmap_binary::Reader reader_;
  bool swap_bytes_ = false;
};

PairwiseMatches ReadBinaryMatches(const fs::path& path, const MatchReadOptions& options,
                                  MatchReadReport* report) {
  const std::string bytes = ReadFileToString(path);
  const std::string source = path.string();
  PortableBinaryReader reader(bytes, source);
  MatchCollector collector(source, options, report);
  const auto pair_count = reader.Read<uint64_t>();
  constexpr size_t kPairHeaderBytes = 2 * sizeof(uint32_t) + sizeof(uint64_t);
  constexpr size_t kMatchBytes = 2 * sizeof(uint32_t);
  reader.bytes().RequireRecords(pair_count, kPairHeaderBytes);
  for (uint64_t p = 0; p < pair_count; ++p) {
    const auto I = reader.Read<uint32_t>();
    const auto J = reader.Read<uint32_t>();
    const auto count = reader.Read<uint64_t>();
    reader.bytes().RequireRecords(count, kMatchBytes);
    std::vector<FeatureMatch> pair_matches(count);
    for (FeatureMatch& m : pair_matches) {
      m.i = reader.Read<uint32_t>();
      m.j = reader.Read<uint32_t>();
    }
    collector.Add(I, J, std::move(pair_matches), "record " + std::to_string(p));
  }
  if (!reader.bytes().AtEnd()) throw FileError(source, "unexpected bytes after the last pair");
  return collector.Take();
}

}  // namespace

PairwiseMatches ReadOpenMvgMatches(const fs::path& path, const MatchReadOptions& options,
                                   MatchReadReport* report) {
  options.Check();
  if (report != nullptr) *report = {};
  return FormatFromExtension(path) == MatchFileFormat::kText ? ReadTextMatches(path, options, report)
                                                             : ReadBinaryMatches(path, options, report);
}

void WriteOpenMvgMatches(const fs::path& path, const PairwiseMatches& matches) {
  if (FormatFromExtension(path) == MatchFileFormat::kText) {
    WriteFileAtomically(path, false, [&](std::ostream& out) {
      for (const auto& [pair, pair_matches] : matches) {
        out << pair.first << ' ' << pair.second << '\n' << pair_matches.size() << '\n';
        for (const FeatureMatch& m : pair_matches) out << m.i << ' ' << m.j << '\n';
      }
    });
    return;
  }
  WriteFileAtomically(path, true, [&](std::ostream& out) {
    colmap_binary::Write<uint8_t>(out, kLittleEndianFlag);
    colmap_binary::Write<uint64_t>(out, matches.size());
    for (const auto& [pair, pair_matches] : matches) {
      colmap_binary::Write<uint32_t>(out, pair.first);
      colmap_binary::Write<uint32_t>(out, pair.second);
      colmap_binary::Write<uint64_t>(out, pair_matches.size());
      for (const FeatureMatch& m : pair_matches) {
        colmap_binary::Write<uint32_t>(out, m.i);
        colmap_binary::Write<uint32_t>(out, m.j);
      }
    }
  });
}

fs::path FindOpenMvgMatchesFile(const fs::path& matches_dir, const fs::path& explicit_file) {
  if (!explicit_file.empty()) {
    if (!fs::is_regular_file(explicit_file)) throw FileError(explicit_file.string(), "match file not found");
    return explicit_file;
  }
  static const std::array<const char*, 6> kPreferredNames = {"matches.e.bin",        "matches.e.txt",
                                                             "matches.f.bin",        "matches.f.txt",
                                                             "matches.putative.bin", "matches.putative.txt"};
  for (const char* name : kPreferredNames) {
    const fs::path candidate = matches_dir / name;
    if (fs::is_regular_file(candidate)) return candidate;
  }
  throw FileError(matches_dir.string(),
                  "no match file (looked for matches.{e,f,putative}.{bin,txt}); give one explicitly");
}

void MatchReadOptions::Check() const {}

}  // namespace sfm_pruning
