#include <gtest/gtest.h>

#include <map>
#include <set>
#include <type_traits>
#include <vector>

#include "engine/ecs/world.h"
#include "test_components.h"

namespace {

using ecs_test::Health;
using ecs_test::Position;
using ecs_test::Tag;
using ecs_test::Velocity;
using engine::ecs::Entity;
using engine::ecs::World;

// Counts visits per entity so tests can assert "exactly once".
using Visits = std::map<Entity, int>;

void expectEachVisitedOnce(const Visits& visits, const std::vector<Entity>& expected) {
  EXPECT_EQ(visits.size(), expected.size());
  for (const Entity e : expected) {
    const auto found = visits.find(e);
    ASSERT_NE(found, visits.end()) << "entity " << e.index << " not visited";
    EXPECT_EQ(found->second, 1) << "entity " << e.index << " visited " << found->second << "x";
  }
}

TEST(View, SingleComponentWithAndWithoutEntity) {
  World world;
  std::vector<Entity> all;
  for (int i = 0; i < 10; ++i) {
    const Entity e = world.create();
    world.emplace<Health>(e, i);
    all.push_back(e);
  }
  world.create();  // no component: not visited
  Visits visits;
  int sum = 0;
  world.view<Health>().each([&](Entity e, Health& h) {
    ++visits[e];
    sum += h.points;
    h.points *= 2;
  });
  expectEachVisitedOnce(visits, all);
  EXPECT_EQ(sum, 45);
  int doubled = 0;
  world.view<const Health>().each([&](const Health& h) { doubled += h.points; });
  EXPECT_EQ(doubled, 90);
}

TEST(View, TwoComponentsConstAndMutable) {
  World world;
  std::vector<Entity> moving;
  for (int i = 0; i < 20; ++i) {
    const Entity e = world.create();
    world.emplace<Position>(e, static_cast<float>(i), 0.0f);
    if (i % 2 == 0) {
      world.emplace<Velocity>(e, 1.0f, 2.0f);
      moving.push_back(e);
    }
  }
  Visits visits;
  world.view<Position, const Velocity>().each([&](Entity e, auto& p, auto& v) {
    static_assert(!std::is_const_v<std::remove_reference_t<decltype(p)>>);
    static_assert(std::is_const_v<std::remove_reference_t<decltype(v)>>);
    ++visits[e];
    p.x += v.dx;
    p.y += v.dy;
  });
  expectEachVisitedOnce(visits, moving);
  for (const Entity e : moving) EXPECT_EQ(world.get<Position>(e).y, 2.0f);
  EXPECT_EQ(world.get<Position>(Entity{1, 0}).y, 0.0f);  // no velocity: untouched

  auto view = world.view<const Position, const Velocity>();
  EXPECT_EQ(view.sizeHint(), moving.size());  // the smaller pool drives
  EXPECT_TRUE(view.contains(moving[0]));
  EXPECT_FALSE(view.contains(Entity{1, 0}));
}

TEST(View, ThreeComponentsOnlyFullMatches) {
  World world;
  std::vector<Entity> full;
  for (int i = 0; i < 60; ++i) {
    const Entity e = world.create();
    if (i % 2 == 0) world.emplace<Position>(e);
    if (i % 3 == 0) world.emplace<Velocity>(e);
    if (i % 5 == 0) world.emplace<Health>(e, i);
    if (i % 30 == 0) full.push_back(e);
  }
  Visits visits;
  world.view<Position, Velocity, const Health>().each(
      [&](Entity e, Position&, Velocity&, const Health& h) {
        ++visits[e];
        EXPECT_EQ(h.points % 30, 0);
      });
  expectEachVisitedOnce(visits, full);
  std::vector<Entity> ranged;
  for (const Entity e : world.view<Position, Velocity, Health>()) ranged.push_back(e);
  EXPECT_EQ(std::set<Entity>(ranged.begin(), ranged.end()),
            std::set<Entity>(full.begin(), full.end()));
}

TEST(View, DestroyingTheCurrentEntityVisitsEveryoneOnce) {
  for (const bool twoTypes : {false, true}) {
    World world;
    std::vector<Entity> all;
    for (int i = 0; i < 50; ++i) {
      const Entity e = world.create();
      world.emplace<Health>(e, i);
      world.emplace<Position>(e);
      all.push_back(e);
    }
    Visits visits;
    auto body = [&](Entity e, const Health& h) {
      ++visits[e];
      if (h.points % 3 != 1) world.destroy(e);
    };
    if (twoTypes) {
      world.view<const Health, Position>().each(
          [&](Entity e, const Health& h, Position&) { body(e, h); });
    } else {
      world.view<const Health>().each(body);
    }
    expectEachVisitedOnce(visits, all);
    EXPECT_EQ(world.count(), 17u);
    EXPECT_EQ(world.size<Health>(), 17u);
    world.view<const Health>().each([](const Health& h) { EXPECT_EQ(h.points % 3, 1); });
  }
}

TEST(View, RemovingComponentsOfTheCurrentEntity) {
  World world;
  std::vector<Entity> all;
  for (int i = 0; i < 40; ++i) {
    const Entity e = world.create();
    world.emplace<Health>(e, i);
    world.emplace<Velocity>(e);
    if (i < 30) world.emplace<Tag>(e);
    all.push_back(e);
  }
  Visits visits;
  world.view<Health, Velocity>().each([&](Entity e, Health& h, Velocity&) {
    ++visits[e];
    const int points = h.points;  // `h` dangles once Health is removed (swap and pop)
    if (points % 2 == 0) world.remove<Health>(e);  // possibly the driving pool
    world.remove<Tag>(e);                          // not part of the view
    if (points % 4 == 1) world.remove<Velocity>(e);
  });
  expectEachVisitedOnce(visits, all);
  EXPECT_EQ(world.size<Tag>(), 0u);
  EXPECT_EQ(world.size<Health>(), 20u);
  EXPECT_EQ(world.size<Velocity>(), 30u);
}

TEST(View, CreatingEntitiesAndAddingComponentsInsideEach) {
  World world;
  std::vector<Entity> original;
  for (int i = 0; i < 30; ++i) {
    const Entity e = world.create();
    world.emplace<Health>(e, i);
    world.emplace<Position>(e);
    original.push_back(e);
  }
  Visits visits;
  // Adds enough components to force the pools to reallocate mid-iteration.
  world.view<Health, Position>().each([&](Entity e, Health&, Position&) {
    ++visits[e];
    for (int k = 0; k < 10; ++k) {
      const Entity spawned = world.create();
      world.emplace<Health>(spawned, -1);
      world.emplace<Position>(spawned);
    }
    world.emplace<Tag>(e);
  });
  expectEachVisitedOnce(visits, original);  // spawned entities are never visited
  EXPECT_EQ(world.count(), 330u);
  EXPECT_EQ(world.size<Tag>(), 30u);
  for (std::size_t i = 0; i < original.size(); ++i) {
    EXPECT_EQ(world.get<Health>(original[i]).points, static_cast<int>(i));
  }
}

TEST(View, EntityGainingComponentsAheadOfTheCursorIsVisited) {
  World world;
  // Position drives (smaller). Iteration runs from the back, so the first-created entity is
  // visited last and sees the Velocity added while visiting the others.
  std::vector<Entity> entities;
  for (int i = 0; i < 3; ++i) {
    const Entity e = world.create();
    world.emplace<Position>(e);
    entities.push_back(e);
  }
  for (int i = 0; i < 10; ++i) world.emplace<Velocity>(world.create());
  world.emplace<Velocity>(entities[1]);
  world.emplace<Velocity>(entities[2]);
  Visits visits;
  world.view<Position, Velocity>().each([&](Entity e, Position&, Velocity&) {
    ++visits[e];
    if (!world.has<Velocity>(entities[0])) world.emplace<Velocity>(entities[0]);
  });
  expectEachVisitedOnce(visits, entities);
}

TEST(View, DeferredDestructionOfOtherEntities) {
  World world;
  std::vector<Entity> all;
  for (int i = 0; i < 40; ++i) {
    const Entity e = world.create();
    world.emplace<Health>(e, i);
    all.push_back(e);
  }
  Visits visits;
  world.view<Health>().each([&](Entity e, Health& h) {
    ++visits[e];
    // Everyone queues someone else, including entities not visited yet.
    world.destroyDeferred(all[static_cast<std::size_t>((h.points + 7) % 40)]);
  });
  expectEachVisitedOnce(visits, all);
  EXPECT_EQ(world.count(), 40u);  // nothing destroyed before the flush
  world.flushDeferred();
  EXPECT_EQ(world.count(), 0u);
  EXPECT_EQ(world.size<Health>(), 0u);
}

TEST(View, RangeForAllowsDestroyingTheCurrentEntity) {
  World world;
  std::vector<Entity> all;
  for (int i = 0; i < 25; ++i) {
    const Entity e = world.create();
    world.emplace<Health>(e, i);
    world.emplace<Velocity>(e);
    all.push_back(e);
  }
  Visits visits;
  for (const Entity e : world.view<Health, Velocity>()) {
    ++visits[e];
    if (world.get<Health>(e).points % 2 == 0) world.destroy(e);
  }
  expectEachVisitedOnce(visits, all);
  EXPECT_EQ(world.count(), 12u);
}

TEST(View, EmptyAndUnknownPools) {
  World world;
  int calls = 0;
  world.view<Position, Velocity>().each([&](Position&, Velocity&) { ++calls; });
  world.view<Health>().each([&](Health&) { ++calls; });
  for (const Entity e : world.view<Tag>()) {
    (void)e;
    ++calls;
  }
  EXPECT_EQ(calls, 0);
}

}  // namespace
