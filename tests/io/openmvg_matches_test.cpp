// OpenMVG match files (.txt / .bin), match-file discovery and pair lists: hand-made golden files,
// exact and byte-exact round trips, bad input, and the real OpenMVG 2.1 Sceaux Castle matches.
#include "sfm_pruning/io/openmvg_matches.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "openmvg_features_test_support.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/io/pair_list.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::openmvg_features_test {
namespace {
namespace fs = std::filesystem;

// The content of the golden matches.txt / matches.bin.
PairwiseMatches GoldenMatches() {
  PairwiseMatches matches;
  matches[{0, 1}] = {{0, 0}, {5, 3}};
  matches[{0, 3}] = {{4, 1}};
  matches[{2, 3}] = {};
  return matches;
}

TEST(OpenMvgMatches, ReadsGoldenTextBinaryAndSwappedPairs) {
  EXPECT_EQ(ReadOpenMvgMatches(Golden("matches.txt")), GoldenMatches());
  EXPECT_EQ(ReadOpenMvgMatches(Golden("matches.bin")), GoldenMatches());
  // "1 0" and "3 0" blocks: pairs swapped to I < J, and each match with them.
  EXPECT_EQ(ReadOpenMvgMatches(Golden("matches_swapped.txt")), GoldenMatches());
}

TEST(OpenMvgMatches, WritesGoldenFilesByteForByte) {
  const fs::path dir = testing::ScratchDir("matches_golden");
  WriteOpenMvgMatches(dir / "m.bin", GoldenMatches());
  WriteOpenMvgMatches(dir / "m.txt", GoldenMatches());
  EXPECT_EQ(ReadFileToString(dir / "m.bin"), ReadFileToString(Golden("matches.bin")));
  EXPECT_EQ(ReadFileToString(dir / "m.txt"), ReadFileToString(Golden("matches.txt")));
}

TEST(OpenMvgMatches, RandomMatchesRoundTripExactlyInBothFormats) {
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<IndexT> view(0, 40);
  std::uniform_int_distribution<IndexT> feature(0, std::numeric_limits<IndexT>::max());
  PairwiseMatches matches;
  for (int p = 0; p < 60; ++p) {
    const IndexT a = view(rng), b = view(rng);
    if (a == b) continue;
    auto& pair_matches = matches[MakeViewPair(a, b)];
    pair_matches.resize(rng() % 50);
    for (FeatureMatch& m : pair_matches) m = {feature(rng), feature(rng)};
  }
  const fs::path dir = testing::ScratchDir("matches_roundtrip");
  for (const char* name : {"m.txt", "m.bin"}) {
    WriteOpenMvgMatches(dir / name, matches);
    EXPECT_EQ(ReadOpenMvgMatches(dir / name), matches) << name;
  }
}

TEST(OpenMvgMatches, DropsPairsOfAbsentViewsAndChecksFeatureIndices) {
  SfmData scene;
  for (IndexT id : {0u, 1u, 2u}) {
    scene.views[id].id_view = id;
    scene.views[id].filename = "image_" + std::to_string(id) + ".jpg";
  }
  MatchReadOptions options;
  options.sfm_data = &scene;
  MatchReadReport report;
  const PairwiseMatches kept = ReadOpenMvgMatches(Golden("matches.bin"), options, &report);
  EXPECT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept.count({0, 1}), 1u);
  EXPECT_EQ(report.dropped_pairs, 2u);  // (0, 3) and (2, 3)
  EXPECT_EQ(report.dropped_matches, 1u);

  FeaturesPerView features;
  features[0].keypoints.resize(6);
  features[1].keypoints.resize(4);
  options.features = &features;
  EXPECT_NO_THROW(ReadOpenMvgMatches(Golden("matches.txt"), options));
  features[1].keypoints.resize(3);  // match (5, 3) now points past view 1's features
  const std::string message = ErrorMessage([&] { ReadOpenMvgMatches(Golden("matches.txt"), options); });
  EXPECT_NE(message.find("matches.txt"), std::string::npos) << message;
  EXPECT_NE(message.find("pair (0, 1)"), std::string::npos) << message;
  EXPECT_NE(message.find("feature index 3"), std::string::npos) << message;
  // A .feat file cut short shows up as indices past its end: the message names it.
  EXPECT_NE(message.find("(3 features in image_1.feat)"), std::string::npos) << message;
  features.erase(1);
  EXPECT_NE(ErrorMessage([&] { ReadOpenMvgMatches(Golden("matches.txt"), options); }).find("no features"),
            std::string::npos);
}

TEST(OpenMvgMatches, RejectsBadFiles) {
  EXPECT_NE(ErrorMessage([] { ReadOpenMvgMatches(Golden("matches_truncated.bin")); }).find("truncated"),
            std::string::npos);
  const fs::path dir = testing::ScratchDir("matches_bad");
  const std::vector<std::pair<std::string, std::string>> bad_texts = {
      {"truncated.txt", "0 1\n3\n1 2\n3 4\n"}, {"letters.txt", "0 1\n1\n1 x\n"},
      {"negative.txt", "0 1\n1\n-1 2\n"},      {"self.txt", "2 2\n1\n1 1\n"},
      {"twice.txt", "0 1\n0\n1 0\n0\n"},       {"no_count.txt", "0 1\n"},
  };
  for (const auto& [name, text] : bad_texts) {
    WriteText(dir / name, text);
    const std::string message = ErrorMessage([&, &n = name] { ReadOpenMvgMatches(dir / n); });
    EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  EXPECT_NE(ErrorMessage([&] { ReadOpenMvgMatches(dir / "letters.txt"); }).find("line 3"), std::string::npos);

  WriteFileAtomically(dir / "flag.bin", true,
                      [](std::ostream& out) { out << '\x07' << std::string(8, '\0'); });
  EXPECT_THROW(ReadOpenMvgMatches(dir / "flag.bin"), Error);
  std::string trailing = ReadFileToString(Golden("matches.bin")) + "x";
  WriteFileAtomically(dir / "trailing.bin", true, [&](std::ostream& out) { out << trailing; });
  EXPECT_THROW(ReadOpenMvgMatches(dir / "trailing.bin"), Error);
  std::string huge_count = ReadFileToString(Golden("matches.bin"));
  huge_count[1] = '\xff';  // claims far more pairs than the file holds
  WriteFileAtomically(dir / "huge.bin", true, [&](std::ostream& out) { out << huge_count; });
  EXPECT_THROW(ReadOpenMvgMatches(dir / "huge.bin"), Error);

  EXPECT_THROW(ReadOpenMvgMatches(dir / "missing.bin"), Error);
  EXPECT_THROW(ReadOpenMvgMatches(Golden("sift.feat")), Error);  // unknown extension
  EXPECT_THROW(WriteOpenMvgMatches(dir / "m.json", GoldenMatches()), Error);
}

TEST(OpenMvgMatches, BigEndianArchivesAreSwapped) {
  std::string bytes = ReadFileToString(Golden("matches.bin"));
  // Re-encode every integer field big-endian: 8-byte count, then per pair 4 + 4 + 8, matches 4 + 4.
  std::string big(1, '\0');
  size_t pos = 1;
  const auto flip = [&](size_t size) {
    std::string field = bytes.substr(pos, size);
    std::reverse(field.begin(), field.end());
    big += field;
    pos += size;
  };
  flip(8);
  for (const auto& [pair, pair_matches] : GoldenMatches()) {
    flip(4), flip(4), flip(8);
    for (size_t k = 0; k < 2 * pair_matches.size(); ++k) flip(4);
  }
  const fs::path path = testing::ScratchDir("matches_big_endian") / "m.bin";
  WriteFileAtomically(path, true, [&](std::ostream& out) { out << big; });
  EXPECT_EQ(ReadOpenMvgMatches(path), GoldenMatches());
}

TEST(OpenMvgMatchesFile, PrefersEssentialThenFundamentalThenPutative) {
  const fs::path dir = testing::ScratchDir("find_matches");
  EXPECT_THROW(FindOpenMvgMatchesFile(dir), Error);
  WriteText(dir / "matches.putative.txt", "");
  EXPECT_EQ(FindOpenMvgMatchesFile(dir), dir / "matches.putative.txt");
  WriteText(dir / "matches.putative.bin", "");
  EXPECT_EQ(FindOpenMvgMatchesFile(dir), dir / "matches.putative.bin");
  WriteText(dir / "matches.f.txt", "");
  EXPECT_EQ(FindOpenMvgMatchesFile(dir), dir / "matches.f.txt");
  WriteText(dir / "matches.e.txt", "");
  EXPECT_EQ(FindOpenMvgMatchesFile(dir), dir / "matches.e.txt");
  WriteText(dir / "matches.e.bin", "");
  EXPECT_EQ(FindOpenMvgMatchesFile(dir), dir / "matches.e.bin");
  EXPECT_EQ(FindOpenMvgMatchesFile(dir, dir / "matches.f.txt"), dir / "matches.f.txt");
  EXPECT_THROW(FindOpenMvgMatchesFile(dir, dir / "matches.h.bin"), Error);
}

TEST(PairList, ReadsMultiPairLinesAndWritesOnePairPerLine) {
  const PairSet pairs = ReadPairList(Golden("pairs.txt"), 4);
  EXPECT_EQ(pairs, (PairSet{{0, 1}, {0, 2}, {1, 3}, {2, 3}}));
  const PairSet all = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  const fs::path out = testing::ScratchDir("pair_list") / "pairs.txt";
  WritePairList(out, all);
  EXPECT_EQ(ReadFileToString(out), ReadFileToString(Golden("pairs_written.txt")));
  EXPECT_EQ(ReadPairList(out, 4), all);
}

TEST(PairList, RejectsSelfPairsOutOfRangeIdsAndSingleTokens) {
  EXPECT_NE(ErrorMessage([] { ReadPairList(Golden("pairs_self.txt"), 4); }).find("pairs_self.txt: line 2"),
            std::string::npos);
  EXPECT_NE(ErrorMessage([] { ReadPairList(Golden("pairs.txt"), 3); }).find("view id 3"), std::string::npos);
  const fs::path dir = testing::ScratchDir("pair_list_bad");
  WriteText(dir / "single.txt", "0 1\n2\n");
  EXPECT_THROW(ReadPairList(dir / "single.txt", 4), Error);
  WriteText(dir / "text.txt", "0 one\n");
  EXPECT_THROW(ReadPairList(dir / "text.txt", 4), Error);
  EXPECT_THROW(ReadPairList(dir / "missing.txt", 4), Error);
}

// Matches of a pair as a set, to test inclusion.
std::set<std::pair<IndexT, IndexT>> MatchSet(const std::vector<FeatureMatch>& matches) {
  std::set<std::pair<IndexT, IndexT>> set;
  for (const FeatureMatch& m : matches) set.emplace(m.i, m.j);
  return set;
}

TEST(OpenMvgMatches, ReadsAndRewritesTheRealSceauxCastleMatches) {
  PRUNESFM_REQUIRE_SHARED("formats/openmvg/sceaux_castle/matches", matches_dir);
  const SfmData scene =
      ReadSfmData(matches_dir / "sfm_data.json", SfmDataParts::kViews | SfmDataParts::kIntrinsics);
  const FeaturesPerView features = ReadOpenMvgFeatures(scene, matches_dir, false);
  MatchReadOptions options;
  options.sfm_data = &scene;
  options.features = &features;  // every index checked against its view's .feat

  const PairSet pairs = ReadPairList(matches_dir / "pairs.bin", scene.views.size());
  EXPECT_EQ(pairs.size(), 11u * 10u / 2u);  // exhaustive pairs

  std::map<std::string, PairwiseMatches> by_name;
  const fs::path out = testing::ScratchDir("sceaux_matches");
  for (const char* name : {"matches.putative.bin", "matches.e.bin", "matches.f.bin"}) {
    MatchReadReport report;
    const PairwiseMatches matches = ReadOpenMvgMatches(matches_dir / name, options, &report);
    EXPECT_EQ(report.dropped_pairs, 0u) << name;
    for (const auto& [pair, pair_matches] : matches) {
      EXPECT_LT(pair.first, pair.second);
      EXPECT_EQ(pairs.count(pair), 1u) << name;
    }
    // Byte-exact .bin writing, and .bin -> .txt -> .bin without loss.
    WriteOpenMvgMatches(out / name, matches);
    EXPECT_EQ(ReadFileToString(out / name), ReadFileToString(matches_dir / name)) << name;
    const fs::path text = fs::path(out / name).replace_extension(".txt");
    WriteOpenMvgMatches(text, matches);
    EXPECT_EQ(ReadOpenMvgMatches(text, options), matches) << name;
    const fs::path again = fs::path(out / name).replace_extension(".again.bin");
    WriteOpenMvgMatches(again, ReadOpenMvgMatches(text));
    EXPECT_EQ(ReadFileToString(again), ReadFileToString(matches_dir / name)) << name;
    by_name[name] = matches;
  }
  const PairwiseMatches& putative = by_name["matches.putative.bin"];
  EXPECT_EQ(putative.size(), 55u);
  EXPECT_EQ(by_name["matches.e.bin"].size(), 43u);
  EXPECT_EQ(by_name["matches.f.bin"].size(), 50u);
  // Geometric filtering keeps a subset of the putative matches of each pair.
  for (const char* filtered : {"matches.e.bin", "matches.f.bin"}) {
    for (const auto& [pair, pair_matches] : by_name[filtered]) {
      ASSERT_EQ(putative.count(pair), 1u) << filtered;
      const auto all = MatchSet(putative.at(pair));
      const auto kept = MatchSet(pair_matches);
      EXPECT_EQ(kept.size(), pair_matches.size()) << filtered << " has duplicate matches";
      EXPECT_TRUE(std::includes(all.begin(), all.end(), kept.begin(), kept.end()))
          << filtered << " pair " << pair.first << "-" << pair.second;
      EXPECT_LE(pair_matches.size(), putative.at(pair).size());
    }
  }
  const fs::path pairs_out = out / "pairs.bin";
  WritePairList(pairs_out, pairs);
  EXPECT_EQ(ReadFileToString(pairs_out), ReadFileToString(matches_dir / "pairs.bin"));
}

}  // namespace
}  // namespace sfm_pruning::openmvg_features_test
