// Every view-graph options struct's Check(): the defaults pass, and a value out of range fails with
// one line naming the field.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "sfm_pruning/view_graph/cycles.hpp"
#include "sfm_pruning/view_graph/louvain.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning {
namespace {

using testing::CheckMessage;
using testing::ExpectEachCaseNamesItsField;

TEST(ViewGraphOptions, DefaultsPass) {
  EXPECT_NO_THROW(CycleSearchOptions().Check());
  EXPECT_NO_THROW(LouvainOptions().Check());
}

TEST(ViewGraphOptions, CycleSearchNamesItsBadField) {
  using O = CycleSearchOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->max_cycle_length = 2; }, "CycleSearchOptions::max_cycle_length"},
      {[](O* o) { o->max_cycle_length = 0; }, "CycleSearchOptions::max_cycle_length"},
      {[](O* o) { o->max_num_cycles = 0; }, "CycleSearchOptions::max_num_cycles"},
  });
  // Triangles only (the shortest length) with both steps off is a legal, empty search.
  EXPECT_EQ(CheckMessage<O>([](O* o) {
              o->max_cycle_length = 3;
              o->max_num_cycles = 1;
              o->include_shortest_alternatives = false;
              o->include_triangles = false;
            }),
            "");
}

TEST(ViewGraphOptions, LouvainNamesItsBadField) {
  using O = LouvainOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->resolution = 0.0; }, "LouvainOptions::resolution"},
      {[](O* o) { o->resolution = -1.0; }, "LouvainOptions::resolution"},
      {[](O* o) { o->resolution = std::numeric_limits<double>::quiet_NaN(); }, "LouvainOptions::resolution"},
      {[](O* o) { o->resolution = std::numeric_limits<double>::infinity(); }, "LouvainOptions::resolution"},
  });
  EXPECT_EQ(CheckMessage<O>([](O* o) { o->resolution = 0.5; }), "");
}

// The entry functions refuse bad options before any work, also on an empty graph.
TEST(ViewGraphOptions, EntryFunctionsRefuseBadOptions) {
  CycleSearchOptions cycles;
  cycles.max_cycle_length = 1;
  EXPECT_THROW(FindBoundedCycles(ViewGraph(), cycles), std::invalid_argument);
  LouvainOptions louvain;
  louvain.resolution = -2.0;
  EXPECT_THROW(DetectCommunitiesLouvain(ViewGraph(), louvain), std::invalid_argument);
}

}  // namespace
}  // namespace sfm_pruning
