#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <vector>

#include "engine/core/error.h"
#include "engine/ecs/world.h"
#include "test_components.h"

namespace {

using ecs_test::Health;
using ecs_test::Position;
using ecs_test::Tag;
using ecs_test::Tracked;
using ecs_test::Velocity;
using engine::ecs::Entity;
using engine::ecs::World;

TEST(WorldComponents, EmplaceGetHasRemoveSize) {
  World world;
  const Entity e = world.create();
  EXPECT_FALSE(world.has<Position>(e));
  EXPECT_EQ(world.size<Position>(), 0u);
  Position& p = world.emplace<Position>(e, 1.0f, 2.0f);
  EXPECT_EQ(p.x, 1.0f);
  EXPECT_TRUE(world.has<Position>(e));
  EXPECT_FALSE(world.has<Velocity>(e));
  EXPECT_EQ(world.size<Position>(), 1u);
  world.get<Position>(e).y = 5.0f;
  EXPECT_EQ(world.tryGet<Position>(e)->y, 5.0f);
  EXPECT_EQ(world.tryGet<Velocity>(e), nullptr);

  static_assert(std::is_same_v<decltype(world.get<const Position>(e)), const Position&>);
  static_assert(std::is_same_v<decltype(world.tryGet<const Position>(e)), const Position*>);
  const World& constWorld = world;
  EXPECT_EQ(constWorld.get<Position>(e).y, 5.0f);
  EXPECT_EQ(constWorld.tryGet<Velocity>(e), nullptr);

  EXPECT_TRUE(world.remove<Position>(e));
  EXPECT_FALSE(world.remove<Position>(e));
  EXPECT_FALSE(world.remove<Velocity>(e));  // storage never created
  EXPECT_FALSE(world.has<Position>(e));
  EXPECT_EQ(world.size<Position>(), 0u);
  EXPECT_TRUE(world.alive(e));
}

TEST(WorldComponents, DuplicateEmplaceAndMissingGetNameTheType) {
  World world;
  const Entity e = world.create();
  world.emplace<Health>(e, 3);
  try {
    world.emplace<Health>(e, 4);
    FAIL() << "expected engine::Error";
  } catch (const engine::Error& error) {
    EXPECT_NE(std::string(error.what()).find("Health"), std::string::npos) << error.what();
  }
  EXPECT_EQ(world.get<Health>(e).points, 3);  // unchanged
  try {
    world.get<Velocity>(e);
    FAIL() << "expected engine::Error";
  } catch (const engine::Error& error) {
    EXPECT_NE(std::string(error.what()).find("Velocity"), std::string::npos) << error.what();
  }
}

TEST(WorldComponents, EmplaceOrReplace) {
  World world;
  const Entity e = world.create();
  world.emplaceOrReplace<std::string>(e, "first");
  EXPECT_EQ(world.get<std::string>(e), "first");
  world.emplaceOrReplace<std::string>(e, 3u, 'z');
  EXPECT_EQ(world.get<std::string>(e), "zzz");
  EXPECT_EQ(world.size<std::string>(), 1u);
}

TEST(WorldComponents, DestroyRemovesEveryComponentOfThatEntityOnly) {
  Tracked::reset();
  World world;
  const Entity a = world.create();
  const Entity b = world.create();
  world.emplace<Position>(a);
  world.emplace<Tracked>(a, 1);
  world.emplace<Tag>(a);
  world.emplace<Position>(b, 9.0f);
  world.emplace<Tracked>(b, 2);
  world.destroy(a);
  EXPECT_EQ(world.size<Position>(), 1u);
  EXPECT_EQ(world.size<Tracked>(), 1u);
  EXPECT_EQ(world.size<Tag>(), 0u);
  EXPECT_EQ(Tracked::live, 1);
  EXPECT_EQ(world.get<Tracked>(b).value, 2);
  EXPECT_EQ(world.get<Position>(b).x, 9.0f);
}

TEST(WorldComponents, DeferredDestroyWaitsForFlushAndToleratesStaleAndDuplicates) {
  World world;
  const Entity a = world.create();
  const Entity b = world.create();
  world.emplace<Health>(a, 1);
  world.destroyDeferred(a);
  world.destroyDeferred(a);
  world.destroyDeferred(b);
  world.destroy(b);  // already gone by flush time
  EXPECT_TRUE(world.alive(a));
  EXPECT_EQ(world.deferredCount(), 3u);
  world.flushDeferred();
  EXPECT_FALSE(world.alive(a));
  EXPECT_EQ(world.size<Health>(), 0u);
  EXPECT_EQ(world.deferredCount(), 0u);
  EXPECT_EQ(world.count(), 0u);
  // The recycled slot of a stale deferred handle is not destroyed by a later flush.
  const Entity c = world.create();
  world.destroyDeferred(a);
  world.flushDeferred();
  EXPECT_TRUE(world.alive(c));
}

TEST(WorldComponents, RandomisedWorldAgainstModel) {
  // Entities and one component type under random create/destroy/emplace/remove, checked
  // against a plain vector model.
  World world;
  struct ModelEntry {
    Entity entity;
    bool hasHealth;
    int points;
  };
  std::vector<ModelEntry> model;
  unsigned state = 7;
  auto next = [&state] {
    state = state * 1103515245u + 12345u;
    return (state >> 16) & 0x7fffu;
  };
  std::vector<Entity> dead;
  for (int step = 0; step < 5000; ++step) {
    const unsigned op = next() % 4;
    if (op == 0 || model.empty()) {
      model.push_back({world.create(), false, 0});
    } else {
      const std::size_t pick = next() % model.size();
      ModelEntry& entry = model[pick];
      if (op == 1) {
        world.destroy(entry.entity);
        dead.push_back(entry.entity);
        model.erase(model.begin() + static_cast<std::ptrdiff_t>(pick));
      } else if (op == 2) {
        entry.points = static_cast<int>(next());
        world.emplaceOrReplace<Health>(entry.entity, entry.points);
        entry.hasHealth = true;
      } else {
        EXPECT_EQ(world.remove<Health>(entry.entity), entry.hasHealth);
        entry.hasHealth = false;
      }
    }
  }
  EXPECT_EQ(world.count(), model.size());
  std::size_t withHealth = 0;
  for (const ModelEntry& entry : model) {
    ASSERT_TRUE(world.alive(entry.entity));
    ASSERT_EQ(world.has<Health>(entry.entity), entry.hasHealth);
    if (entry.hasHealth) {
      ++withHealth;
      ASSERT_EQ(world.get<Health>(entry.entity).points, entry.points);
    }
  }
  EXPECT_EQ(world.size<Health>(), withHealth);
  for (const Entity e : dead) {
    ASSERT_FALSE(world.alive(e));
    ASSERT_FALSE(world.has<Health>(e));
  }
}

}  // namespace
