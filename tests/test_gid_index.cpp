// GidIndex against std::unordered_map, the brute-force reference; and the carried memories of
// a pair list keyed through it (group_records), which no longer need an array per global id.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

#include "talus/body/gid_index.h"
#include "talus/collide/pair_list.h"

using namespace talus;

TEST(GidIndex, AgreesWithAHashMapUnderPutsOverwritesAndGrowth) {
  std::mt19937 rng(7);
  // Ids in runs (as insertion makes them) and scattered over the whole 32-bit range.
  std::uniform_int_distribution<std::uint32_t> scattered(0, 0xfffffffeu);
  GidIndex index;
  index.reset(4);  // far too small: put must grow the table
  std::unordered_map<std::uint32_t, std::int32_t> reference;
  for (int n = 0; n < 20000; ++n) {
    const std::uint32_t gid = n % 3 == 0 ? scattered(rng) : static_cast<std::uint32_t>(n / 2);
    const std::int32_t value = static_cast<std::int32_t>(rng() % 1000);
    index.put(gid, value);
    reference[gid] = value;
  }
  EXPECT_EQ(index.size(), reference.size());
  for (const auto& [gid, value] : reference) ASSERT_EQ(index.find(gid), value) << gid;
  int absent = 0;
  for (int n = 0; n < 20000; ++n) {
    const std::uint32_t gid = scattered(rng);
    if (reference.count(gid)) continue;
    ++absent;
    ASSERT_EQ(index.find(gid), GidIndex::kAbsent) << gid;
  }
  EXPECT_GT(absent, 19000);
}

TEST(GidIndex, ResetForgetsEveryIdAndKeepsItsTable) {
  GidIndex index;
  const std::vector<std::uint32_t> gids = {5, 900000000, 17, 3, 4000000000u};
  index.index_positions(gids);
  for (std::size_t i = 0; i < gids.size(); ++i) EXPECT_EQ(index.find(gids[i]), static_cast<std::int32_t>(i));
  const std::size_t bytes = index.bytes();
  index.reset(2);
  EXPECT_EQ(index.size(), 0u);
  EXPECT_EQ(index.bytes(), bytes);
  for (const std::uint32_t g : gids) EXPECT_EQ(index.find(g), GidIndex::kAbsent);
  EXPECT_EQ(GidIndex{}.find(3), GidIndex::kAbsent);  // a map never filled
}

TEST(CarriedContacts, RecordsGroupByKeyInTheirOrderWhateverTheIds) {
  // Keys far beyond the number of records: grouping must not size anything by the ids.
  const std::vector<std::uint32_t> a = {4000000000u, 12, 4000000000u, 7, 12, 12};
  const std::vector<std::uint32_t> b = {1, 2, 3, 4, 5, 6};
  std::vector<CarriedRecord> records;
  for (std::size_t n = 0; n < a.size(); ++n)
    records.push_back({a[n], b[n], Vec3{double(n), 0, 0}, Vec3{}, Vec3{0, 0, double(n)}});
  MemoryLayout layout;
  layout.spring = true;
  layout.rolling = true;
  CarriedContacts c;
  group_records(records, layout, c);
  ASSERT_EQ(c.groups(), 3u);
  EXPECT_EQ(c.key, (std::vector<std::uint32_t>{4000000000u, 12, 7}));  // first appearances
  const auto others_of = [&](std::uint32_t key) {
    std::vector<std::uint32_t> out;
    const std::int32_t g = c.group_of.find(key);
    if (g < 0) return out;
    for (std::uint32_t k = c.start[g]; k < c.start[g + 1]; ++k) {
      out.push_back(c.other[k]);
      EXPECT_EQ(c.memory.spring[k].x, static_cast<double>(c.other[k] - 1));  // memory went with its record
      EXPECT_EQ(c.memory.rolling[k].z, static_cast<double>(c.other[k] - 1));
    }
    return out;
  };
  EXPECT_EQ(others_of(4000000000u), (std::vector<std::uint32_t>{1, 3}));
  EXPECT_EQ(others_of(12), (std::vector<std::uint32_t>{2, 5, 6}));
  EXPECT_EQ(others_of(7), (std::vector<std::uint32_t>{4}));
  EXPECT_TRUE(others_of(8).empty());
  EXPECT_TRUE(c.memory.normal_prev.empty());  // not in the layout
}
