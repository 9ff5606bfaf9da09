#include <gtest/gtest.h>

#include <string>
#include <unordered_set>

#include "engine/core/error.h"
#include "engine/ecs/world.h"
#include "test_components.h"

namespace {

using ecs_test::Position;
using engine::ecs::Entity;
using engine::ecs::World;

TEST(Entity, NullDefaultComparisonAndHash) {
  constexpr Entity none;
  static_assert(none == Entity::null());
  static_assert(none.isNull());
  const Entity a{1, 0};
  const Entity b{1, 1};
  const Entity c{2, 0};
  EXPECT_NE(a, b);
  EXPECT_LT(a, b);
  EXPECT_LT(b, c);
  EXPECT_FALSE(a.isNull());
  std::unordered_set<Entity> set{a, b, c, a};
  EXPECT_EQ(set.size(), 3u);
  EXPECT_EQ(std::hash<Entity>{}(a), std::hash<Entity>{}(Entity{1, 0}));
}

TEST(World, CreateDestroyAlive) {
  World world;
  EXPECT_EQ(world.count(), 0u);
  const Entity a = world.create();
  const Entity b = world.create();
  EXPECT_NE(a, b);
  EXPECT_TRUE(world.alive(a));
  EXPECT_TRUE(world.alive(b));
  EXPECT_FALSE(world.alive(Entity::null()));
  EXPECT_FALSE(world.alive(Entity{57, 0}));  // never created
  EXPECT_EQ(world.count(), 2u);
  world.destroy(a);
  EXPECT_FALSE(world.alive(a));
  EXPECT_TRUE(world.alive(b));
  EXPECT_EQ(world.count(), 1u);
  EXPECT_THROW(world.destroy(a), engine::Error);  // destroying twice is a bug
  EXPECT_THROW(world.destroy(Entity::null()), engine::Error);
}

TEST(World, RecyclesIndexWithBumpedGeneration) {
  World world;
  const Entity first = world.create();
  const Entity other = world.create();
  world.destroy(first);
  const Entity reused = world.create();
  EXPECT_EQ(reused.index, first.index);
  EXPECT_EQ(reused.generation, first.generation + 1);
  EXPECT_NE(reused, first);
  EXPECT_FALSE(world.alive(first));
  EXPECT_TRUE(world.alive(reused));

  // Several generations of the same slot: only the newest is alive.
  Entity current = reused;
  for (int i = 0; i < 5; ++i) {
    world.destroy(current);
    const Entity next = world.create();
    EXPECT_EQ(next.index, first.index);
    EXPECT_EQ(next.generation, current.generation + 1);
    current = next;
  }
  EXPECT_FALSE(world.alive(reused));
  EXPECT_TRUE(world.alive(other));
  EXPECT_EQ(world.count(), 2u);
}

TEST(World, StaleHandleNeverReachesTheNewOwnersComponents) {
  World world;
  const Entity stale = world.create();
  world.emplace<Position>(stale, 1.0f, 2.0f);
  world.destroy(stale);
  const Entity owner = world.create();
  ASSERT_EQ(owner.index, stale.index);
  world.emplace<Position>(owner, 7.0f, 8.0f);

  EXPECT_FALSE(world.has<Position>(stale));
  EXPECT_EQ(world.tryGet<Position>(stale), nullptr);
  EXPECT_FALSE(world.remove<Position>(stale));
  EXPECT_TRUE(world.has<Position>(owner));
  try {
    world.get<Position>(stale);
    FAIL() << "expected engine::Error";
  } catch (const engine::Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("Position"), std::string::npos) << message;
    EXPECT_NE(message.find("not alive"), std::string::npos) << message;
  }
  EXPECT_THROW(world.emplace<Position>(stale), engine::Error);
  EXPECT_THROW(world.emplaceOrReplace<Position>(stale), engine::Error);
  const World& constWorld = world;
  EXPECT_THROW(constWorld.get<Position>(stale), engine::Error);
  EXPECT_EQ(world.get<Position>(owner).x, 7.0f);  // untouched
}

TEST(World, ClearMakesEveryHandleStaleAndReusesLowIndicesFirst) {
  World world;
  Entity handles[4];
  for (Entity& e : handles) {
    e = world.create();
    world.emplace<Position>(e);
  }
  world.clear();
  EXPECT_EQ(world.count(), 0u);
  EXPECT_EQ(world.size<Position>(), 0u);
  for (const Entity e : handles) EXPECT_FALSE(world.alive(e));
  const Entity again = world.create();
  EXPECT_EQ(again.index, 0u);
  EXPECT_EQ(again.generation, 1u);
  EXPECT_FALSE(world.has<Position>(again));
}

TEST(World, MovedWorldKeepsEntitiesAndSourceIsEmpty) {
  World source;
  const Entity e = source.create();
  source.emplace<Position>(e, 3.0f, 4.0f);
  World moved(std::move(source));
  EXPECT_TRUE(moved.alive(e));
  EXPECT_EQ(moved.get<Position>(e).y, 4.0f);
  EXPECT_EQ(source.count(), 0u);  // NOLINT(bugprone-use-after-move): documented as empty
  const Entity fresh = source.create();
  EXPECT_EQ(fresh.index, 0u);
}

}  // namespace
