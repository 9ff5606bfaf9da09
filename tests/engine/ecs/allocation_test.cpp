// Global operator new/delete are replaced in this file (for the whole test executable) with
// versions that count allocations, so tests can assert that warm frames allocate nothing.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#include "engine/ecs/events.h"
#include "engine/ecs/frame_time.h"
#include "engine/ecs/scheduler.h"
#include "engine/ecs/world.h"
#include "test_components.h"

namespace {

std::atomic<std::size_t> gAllocations{0};

void* countedAlloc(std::size_t size) noexcept {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}

void* countedAlignedAlloc(std::size_t size, std::align_val_t alignment) noexcept {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  const auto align = static_cast<std::size_t>(alignment);
  const std::size_t rounded = (size + align - 1) / align * align;  // aligned_alloc requires it
  return std::aligned_alloc(align, rounded == 0 ? align : rounded);
}

void* orThrow(void* p) {
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

}  // namespace

void* operator new(std::size_t size) {
  return orThrow(countedAlloc(size));
}
void* operator new[](std::size_t size) {
  return orThrow(countedAlloc(size));
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  return countedAlloc(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  return countedAlloc(size);
}
void* operator new(std::size_t size, std::align_val_t a) {
  return orThrow(countedAlignedAlloc(size, a));
}
void* operator new[](std::size_t size, std::align_val_t a) {
  return orThrow(countedAlignedAlloc(size, a));
}
void* operator new(std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  return countedAlignedAlloc(size, a);
}
void* operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  return countedAlignedAlloc(size, a);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}

namespace {

using ecs_test::Health;
using ecs_test::Position;
using ecs_test::Tag;
using ecs_test::Velocity;
using engine::ecs::Entity;
using engine::ecs::EventReader;
using engine::ecs::FrameTime;
using engine::ecs::Phase;
using engine::ecs::Scheduler;
using engine::ecs::World;

struct Hit {
  Entity target;
  int damage = 0;
};

std::size_t allocationsDuring(auto&& work) {
  const std::size_t before = gAllocations.load(std::memory_order_relaxed);
  work();
  return gAllocations.load(std::memory_order_relaxed) - before;
}

TEST(Allocation, CounterSeesAllocations) {
  // Guards against a counter that silently sees nothing, which would make the test below
  // pass vacuously.
  World world;  // nothing reserved: the first create() must grow the entity table
  const std::size_t seen = allocationsDuring([&] {
    const Entity e = world.create();
    world.emplace<Health>(e, 1);  // new storage, new page, new arrays
  });
  EXPECT_GE(seen, 3u);
  std::vector<int>* vector = nullptr;
  EXPECT_EQ(allocationsDuring([&] { vector = new std::vector<int>(100); }), 2u);
  delete vector;
}

TEST(Allocation, WarmFramesDoNotAllocate) {
  constexpr int kEntities = 1000;
  constexpr int kSpawnPerFrame = 50;
  constexpr int kHitsPerFrame = 16;

  World world;
  Scheduler scheduler;
  world.ctx().emplace<FrameTime>();
  std::vector<Entity> persistent;
  for (int i = 0; i < kEntities; ++i) {
    const Entity e = world.create();
    world.emplace<Position>(e, static_cast<float>(i), 0.0f);
    world.emplace<Velocity>(e, 1.0f, 0.5f);
    if (i % 2 == 0) world.emplace<Health>(e, 100);
    persistent.push_back(e);
  }

  // Workload state, allocated before the measured frames.
  std::vector<Entity> spawned;
  spawned.reserve(kSpawnPerFrame);
  EventReader<Hit> hitReader;
  struct Stats {
    std::size_t moved = 0, hitsRead = 0, rendered = 0, tagged = 0;
  } stats;

  scheduler.add(Phase::Input, "input.hits", [&](World& w) {
    auto& hits = w.events<Hit>();
    const auto frame = w.ctx().get<FrameTime>().frameIndex;
    for (int i = 0; i < kHitsPerFrame; ++i) {
      hits.send(Hit{persistent[(frame * 7u + static_cast<unsigned>(i) * 2u) % kEntities], 1});
    }
  });
  scheduler.add(Phase::Simulate, "sim.move", [&](World& w) {
    w.view<Position, const Velocity>().each([&](Position& p, const Velocity& v) {
      p.x += v.dx;
      p.y += v.dy;
      ++stats.moved;
    });
  });
  scheduler.add(Phase::Simulate, "sim.damage", [&](World& w) {
    for (const Hit& hit : hitReader.read(w.events<Hit>())) {
      if (Health* health = w.tryGet<Health>(hit.target)) health->points -= hit.damage;
      ++stats.hitsRead;
    }
  });
  scheduler.add(Phase::Simulate, "sim.spawn", [&](World& w) {
    // Last frame's spawn is destroyed (deferred, flushed after this system) and replaced.
    for (const Entity e : spawned) w.destroyDeferred(e);
    spawned.clear();
    for (int i = 0; i < kSpawnPerFrame; ++i) {
      const Entity e = w.create();
      w.emplace<Position>(e);
      w.emplace<Velocity>(e, 0.0f, 1.0f);
      w.emplace<Health>(e, 5);
      spawned.push_back(e);
    }
  });
  scheduler.add(Phase::Simulate, "sim.tag", [&](World& w) {
    w.view<const Health>().each([&](Entity e, const Health& h) {
      if (h.points < 100) w.emplaceOrReplace<Tag>(e);
    });
  });
  scheduler.add(Phase::PreRender, "pre.untag-and-cull", [&](World& w) {
    w.view<Tag, Health>().each([&](Entity e, Tag&, Health& h) {
      ++stats.tagged;
      h.points = 100;    // healed, so the tagged set stays bounded
      w.remove<Tag>(e);  // current entity: allowed inside each
    });
  });
  scheduler.add(Phase::Render, "render.collect", [&](World& w) {
    w.view<const Position>().each([&](const Position&) { ++stats.rendered; });
  });
  scheduler.add(Phase::PostRender, "post.stats",
                [&](World& w) { (void)w.ctx().get<FrameTime>().deltaSeconds; });

  auto frame = [&] {
    FrameTime& time = world.ctx().get<FrameTime>();
    time = time.next(1.0 / 60.0);
    scheduler.runFrame(world);
  };
  for (int i = 0; i < 10; ++i) frame();  // warm up: pools, free list and buffers reach size

  stats = {};
  constexpr int kFrames = 200;
  const std::size_t allocations = allocationsDuring([&] {
    for (int i = 0; i < kFrames; ++i) frame();
  });
  EXPECT_EQ(allocations, 0u);
  // The workload really ran.
  EXPECT_EQ(stats.moved, static_cast<std::size_t>(kFrames * (kEntities + kSpawnPerFrame)));
  EXPECT_EQ(stats.hitsRead, static_cast<std::size_t>(kFrames * kHitsPerFrame));
  EXPECT_GT(stats.tagged, 0u);
  EXPECT_EQ(world.count(), static_cast<std::size_t>(kEntities + kSpawnPerFrame));
}

}  // namespace
