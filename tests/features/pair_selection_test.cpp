#include <gtest/gtest.h>

#include <fstream>

#include "sfm_pruning/features/pair_selection.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {

TEST(PairSelection, ExhaustiveListsEveryPairOnce) {
  const PairSet pairs = ExhaustivePairs({0, 1, 2, 3, 4});
  EXPECT_EQ(pairs.size(), 10u);
  for (const ViewPair& p : pairs) EXPECT_LT(p.first, p.second);
  EXPECT_TRUE(ExhaustivePairs({7}).empty());
  EXPECT_EQ(ExhaustivePairs({9, 2}), (PairSet{{2, 9}}));
}

TEST(PairSelection, SequentialPairsEachViewWithTheNextWindow) {
  EXPECT_EQ(SequentialPairs({0, 1, 2, 3}, 2), (PairSet{{0, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 3}}));
  // A ring closes over the end.
  EXPECT_EQ(SequentialPairs({0, 1, 2, 3}, 1, true), (PairSet{{0, 1}, {1, 2}, {2, 3}, {0, 3}}));
  // A window longer than the sequence pairs everything, and only once.
  EXPECT_EQ(SequentialPairs({0, 1, 2}, 10, true), ExhaustivePairs({0, 1, 2}));
  // n views, window w: n*w - w*(w+1)/2 pairs.
  std::vector<IndexT> ids(100);
  for (IndexT k = 0; k < 100; ++k) ids[k] = k;
  EXPECT_EQ(SequentialPairs(ids, 5).size(), 100u * 5 - 15);
  EXPECT_THROW(SequentialPairs(ids, 0), Error);
}

TEST(PairSelection, PairListKeepsListedPairsAndNamesBadViews) {
  SfmData scene;
  for (IndexT id = 0; id < 4; ++id) scene.views[id].id_view = id;
  const std::filesystem::path dir = ScratchDir("pair_list_selection");
  std::ofstream(dir / "pairs.txt") << "0 1 2\n3 1\n";
  EXPECT_EQ(PairsFromList(dir / "pairs.txt", scene), (PairSet{{0, 1}, {0, 2}, {1, 3}}));
  scene.views.erase(2);
  try {
    PairsFromList(dir / "pairs.txt", scene);
    FAIL() << "view 2 is not in the scene";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("names view 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sfm_pruning::testing
