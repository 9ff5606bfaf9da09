#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/ecs/sparse_set.h"
#include "engine/ecs/storage.h"
#include "engine/ecs/world.h"
#include "test_components.h"

namespace {

using ecs_test::MoveOnly;
using ecs_test::Tracked;
using engine::ecs::Entity;
using engine::ecs::SparseSet;
using engine::ecs::Storage;
using engine::ecs::World;

// Checks every invariant of `storage` against `model`: same members and values, dense
// positions consistent with index(), no stale generation accepted.
void expectMatches(const Storage<std::string>& storage,
                   const std::map<Entity, std::string>& model) {
  ASSERT_EQ(storage.size(), model.size());
  ASSERT_EQ(storage.components().size(), storage.entities().size());
  for (std::size_t i = 0; i < storage.size(); ++i) {
    const Entity e = storage.entities()[i];
    ASSERT_EQ(storage.index(e), i);
    const auto found = model.find(e);
    ASSERT_NE(found, model.end());
    ASSERT_EQ(storage.components()[i], found->second);
  }
  for (const auto& [e, value] : model) {
    ASSERT_TRUE(storage.contains(e));
    ASSERT_EQ(storage.get(e), value);
    ASSERT_FALSE(storage.contains(Entity{e.index, e.generation + 1}));
    ASSERT_FALSE(storage.contains(Entity{e.index, e.generation - 1}));
  }
}

TEST(SparseSet, RandomisedOperationsMatchStdMap) {
  std::mt19937 rng(1234);
  Storage<std::string> storage;
  std::map<Entity, std::string> model;
  // Indices spread over several pages, plus a few far away, with small generations.
  std::vector<std::uint32_t> indices;
  for (std::uint32_t i = 0; i < 300; ++i) indices.push_back(i * 97u);
  indices.push_back(5'000'000u);
  indices.push_back(Entity::kNullIndex - 1);
  std::uniform_int_distribution<std::size_t> pickIndex(0, indices.size() - 1);
  std::uniform_int_distribution<std::uint32_t> pickGeneration(0, 2);
  std::uniform_int_distribution<int> pickOp(0, 9);

  for (int step = 0; step < 20000; ++step) {
    const Entity e{indices[pickIndex(rng)], pickGeneration(rng)};
    const std::string value =
        "value-" + std::to_string(step) + std::string(static_cast<std::size_t>(step % 40), 'x');
    const int op = pickOp(rng);
    const bool present = model.count(e) != 0;
    // Another generation of the same index present: e is a stale handle for the storage.
    bool otherGeneration = false;
    for (std::uint32_t g = 0; g <= 2; ++g) {
      if (g != e.generation && model.count(Entity{e.index, g}) != 0) otherGeneration = true;
    }
    ASSERT_EQ(storage.contains(e), present);
    if (op < 5) {
      if (present && op < 4) {
        EXPECT_THROW(storage.emplace(e, value), engine::Error);
      } else if (otherGeneration) {
        EXPECT_THROW(storage.emplaceOrReplace(e, value), engine::Error);
      } else {
        const std::string& stored =
            op < 4 ? storage.emplace(e, value) : storage.emplaceOrReplace(e, value);
        EXPECT_EQ(stored, value);
        model[e] = value;
      }
    } else if (op < 9) {
      EXPECT_EQ(storage.remove(e), present);
      model.erase(e);
    } else if (present) {
      ASSERT_EQ(*storage.tryGet(e), model[e]);
    } else {
      ASSERT_EQ(storage.tryGet(e), nullptr);
      EXPECT_THROW(storage.get(e), engine::Error);
    }
    if (step % 500 == 0) expectMatches(storage, model);
  }
  expectMatches(storage, model);
  storage.clear();
  model.clear();
  expectMatches(storage, model);
}

TEST(SparseSet, SwapAndPopMovesTheLastElementIntoTheHole) {
  Storage<int> storage;
  const Entity a{0, 0}, b{1, 0}, c{2, 0}, d{3, 0};
  storage.emplace(a, 10);
  storage.emplace(b, 11);
  storage.emplace(c, 12);
  storage.emplace(d, 13);
  ASSERT_TRUE(storage.remove(b));
  ASSERT_EQ(storage.size(), 3u);
  EXPECT_EQ(storage.entities()[1], d);
  EXPECT_EQ(storage.components()[1], 13);
  EXPECT_EQ(storage.index(d), 1u);
  ASSERT_TRUE(storage.remove(d));  // now in the middle again
  EXPECT_EQ(storage.entities()[1], c);
  ASSERT_TRUE(storage.remove(c));  // last element: removes itself
  EXPECT_EQ(storage.size(), 1u);
  EXPECT_FALSE(storage.contains(c));
  EXPECT_FALSE(storage.remove(c));
  EXPECT_EQ(storage.get(a), 10);
}

TEST(SparseSet, PagesAreAllocatedOnlyWhereIndicesLand) {
  SparseSet set;
  EXPECT_EQ(set.pageCount(), 0u);
  set.insert(Entity{3'000'000'000u, 0});
  EXPECT_EQ(set.pageCount(), 1u);
  set.insert(Entity{1, 0});
  set.insert(Entity{SparseSet::kPageSize - 1, 0});
  EXPECT_EQ(set.pageCount(), 2u);
  set.insert(Entity{SparseSet::kPageSize, 0});
  EXPECT_EQ(set.pageCount(), 3u);
  EXPECT_TRUE(set.contains(Entity{3'000'000'000u, 0}));
  EXPECT_FALSE(set.contains(Entity{3'000'000'001u, 0}));
  EXPECT_FALSE(set.contains(Entity::null()));
  EXPECT_THROW(set.insert(Entity::null()), engine::Error);
  EXPECT_THROW(set.insert(Entity{1, 0}), engine::Error);
  EXPECT_THROW(set.insert(Entity{1, 5}), engine::Error);  // same index, other generation
  EXPECT_EQ(set.size(), 4u);
  set.clear();
  EXPECT_EQ(set.size(), 0u);
  EXPECT_EQ(set.pageCount(), 3u);  // kept for reuse
  EXPECT_FALSE(set.contains(Entity{1, 0}));
}

TEST(Storage, NonTrivialComponentsAreDestroyedExactlyOnce) {
  Tracked::reset();
  {
    Storage<Tracked> storage;
    for (std::uint32_t i = 0; i < 100; ++i) storage.emplace(Entity{i, 0}, static_cast<int>(i));
    EXPECT_EQ(Tracked::live, 100);
    for (std::uint32_t i = 0; i < 100; i += 3) storage.remove(Entity{i, 0});
    EXPECT_EQ(Tracked::live, static_cast<int>(storage.size()));
    storage.emplaceOrReplace(Entity{1, 0}, 1000);
    EXPECT_EQ(storage.get(Entity{1, 0}).value, 1000);
    EXPECT_EQ(Tracked::live, static_cast<int>(storage.size()));
    // Values survive swap-and-pop moves.
    for (std::uint32_t i = 2; i < 100; ++i) {
      if (i % 3 != 0) {
        EXPECT_EQ(storage.get(Entity{i, 0}).value, static_cast<int>(i));
      }
    }
  }
  EXPECT_EQ(Tracked::live, 0);
  EXPECT_EQ(Tracked::constructed, Tracked::destroyed);
}

TEST(Storage, MoveOnlyComponentsAcrossGrowthRemovalAndClear) {
  Tracked::reset();
  {
    World world;
    std::vector<Entity> entities;
    for (int i = 0; i < 1000; ++i) {  // several reallocations of the component array
      const Entity e = world.create();
      world.emplace<MoveOnly>(e, i);
      world.emplace<std::unique_ptr<int>>(e, std::make_unique<int>(i));
      world.emplace<std::vector<std::string>>(e, 3u, std::string(50, 'v'));
      entities.push_back(e);
    }
    EXPECT_EQ(Tracked::live, 1000);
    for (std::size_t i = 0; i < entities.size(); i += 2) world.destroy(entities[i]);
    EXPECT_EQ(Tracked::live, 500);
    for (std::size_t i = 1; i < entities.size(); i += 4) world.remove<MoveOnly>(entities[i]);
    EXPECT_EQ(Tracked::live, 250);
    for (std::size_t i = 3; i < entities.size(); i += 4) {
      EXPECT_EQ(world.get<MoveOnly>(entities[i]).tracked->value, static_cast<int>(i));
      EXPECT_EQ(*world.get<std::unique_ptr<int>>(entities[i]), static_cast<int>(i));
    }
    world.emplaceOrReplace<MoveOnly>(entities[3], 42);
    EXPECT_EQ(Tracked::live, 250);
    world.clear();
    EXPECT_EQ(Tracked::live, 0);
    const Entity e = world.create();
    world.emplace<MoveOnly>(e, 1);
  }  // the world's destructor destroys the rest
  EXPECT_EQ(Tracked::live, 0);
  EXPECT_EQ(Tracked::constructed, Tracked::destroyed);
}

struct ThrowsOnConstruction {
  explicit ThrowsOnConstruction(bool fail) {
    if (fail) throw std::runtime_error("construction failed");
  }
};

TEST(Storage, ThrowingConstructorLeavesStorageUnchanged) {
  Storage<ThrowsOnConstruction> storage;
  storage.emplace(Entity{0, 0}, false);
  EXPECT_THROW(storage.emplace(Entity{1, 0}, true), std::runtime_error);
  EXPECT_EQ(storage.size(), 1u);
  EXPECT_FALSE(storage.contains(Entity{1, 0}));
  storage.emplace(Entity{1, 0}, false);
  EXPECT_EQ(storage.index(Entity{1, 0}), 1u);
}

}  // namespace
