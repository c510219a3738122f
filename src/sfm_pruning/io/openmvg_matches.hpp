// OpenMVG match files (FORMATS.md §2.5): pairwise feature matches keyed by view-id pair.
//   .txt  repeated blocks "I J\nN\n" followed by N lines "i j"
//   .bin  cereal PortableBinary: uint8 endianness flag (1 = little), uint64 #pairs, then per pair
//         uint32 I, uint32 J, uint64 N, N x (uint32 i, uint32 j)
// The format is chosen by the extension. Pairs are stored with I < J: a block written as J I is
// swapped together with each of its matches.
#pragma once

#include <cstddef>
#include <filesystem>

#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct MatchReadOptions {
  // When set, pairs naming a view absent from the scene are dropped (as OpenMVG's matches
  // provider does) and counted in MatchReadReport::dropped_pairs.
  const SfmData* sfm_data = nullptr;
  // When set, every feature index is checked against the feature count of its view.
  const FeaturesPerView* features = nullptr;

  // Either pointer may be null (that check is then skipped): there is nothing to refuse. Kept so
  // that every options struct has one (util/option_checks.hpp).
  void Check() const;
};

struct MatchReadReport {
  size_t dropped_pairs = 0;    // pairs whose views are not in MatchReadOptions::sfm_data
  size_t dropped_matches = 0;  // matches in those pairs
};

// Reads a .txt or .bin match file. Throws Error naming the file (and the pair, line or offset)
// on truncation, non-numeric tokens, I == J, a pair listed twice, or, with features, a feature
// index out of range. `report` may be null.
PairwiseMatches ReadOpenMvgMatches(const std::filesystem::path& path, const MatchReadOptions& options = {},
                                   MatchReadReport* report = nullptr);

// Writes a .txt or .bin match file (by extension), pairs in map order. The .bin output is
// byte-identical to what OpenMVG writes for the same matches. Atomic.
void WriteOpenMvgMatches(const std::filesystem::path& path, const PairwiseMatches& matches);

// The match file a GLOBAL reconstruction should use. An explicit file is returned as is (Error
// when it does not exist). Otherwise the first existing file of `matches_dir` in this order:
//   matches.e.bin, matches.e.txt        geometric, essential matrix (what GLOBAL expects)
//   matches.f.bin, matches.f.txt        geometric, fundamental matrix
//   matches.putative.bin, matches.putative.txt   photometric only
// (.bin before .txt because it is what OpenMVG's tools write by default). Error when none exists.
std::filesystem::path FindOpenMvgMatchesFile(const std::filesystem::path& matches_dir,
                                             const std::filesystem::path& explicit_file = {});

}  // namespace sfm_pruning
