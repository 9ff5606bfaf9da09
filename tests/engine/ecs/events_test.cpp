#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/ecs/events.h"
#include "engine/ecs/world.h"

namespace {

using engine::ecs::EventQueue;
using engine::ecs::EventReader;
using engine::ecs::World;

struct Hit {
  int damage = 0;
};

std::vector<int> drain(EventReader<Hit>& reader, const EventQueue<Hit>& queue) {
  std::vector<int> out;
  for (const Hit& hit : reader.read(queue)) out.push_back(hit.damage);
  return out;
}

TEST(Events, VisibleThisFrameAndNextThenDropped) {
  EventQueue<Hit> queue;
  EventReader<Hit> early;  // reads every frame
  EventReader<Hit> late;   // reads only after two updates
  EventReader<Hit> next;   // reads once, one frame later

  queue.send(Hit{1});
  queue.emplace(2);
  EXPECT_EQ(drain(early, queue), (std::vector<int>{1, 2}));
  EXPECT_EQ(drain(early, queue), std::vector<int>{});  // never the same event twice

  queue.update();  // end of frame 0
  queue.send(Hit{3});
  EXPECT_EQ(queue.size(), 3u);
  EXPECT_EQ(next.unreadCount(queue), 3u);
  EXPECT_EQ(drain(next, queue), (std::vector<int>{1, 2, 3}));  // last frame's too
  EXPECT_EQ(drain(early, queue), (std::vector<int>{3}));

  queue.update();  // end of frame 1: frame 0's events are dropped
  EXPECT_EQ(queue.size(), 1u);
  EXPECT_EQ(drain(late, queue), (std::vector<int>{3}));
  EXPECT_EQ(late.missedCount(), 2u);

  queue.update();  // end of frame 2: everything dropped
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(drain(early, queue), std::vector<int>{});
  EXPECT_EQ(early.missedCount(), 0u);
  EXPECT_EQ(queue.sentCount(), 3u);
}

TEST(Events, ReaderCreatedFromQueueSeesOnlyNewEvents) {
  EventQueue<std::string> queue;
  queue.send("before");
  EventReader<std::string> reader(queue);
  queue.send("after");
  const auto range = reader.read(queue);
  ASSERT_EQ(range.size(), 1u);
  EXPECT_EQ(range[0], "after");
  queue.send("again");
  reader.skipAll(queue);
  EXPECT_TRUE(reader.read(queue).empty());
}

TEST(Events, RangeSpansBothBuffersInOrder) {
  EventQueue<Hit> queue;
  EventReader<Hit> reader;
  for (int i = 0; i < 3; ++i) queue.send(Hit{i});
  queue.update();
  for (int i = 3; i < 5; ++i) queue.send(Hit{i});
  const auto range = reader.read(queue);
  ASSERT_EQ(range.size(), 5u);
  std::vector<int> seen;
  for (auto it = range.begin(); it != range.end(); ++it) seen.push_back(it->damage);
  EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3, 4}));
  for (std::size_t i = 0; i < range.size(); ++i) EXPECT_EQ(range[i].damage, static_cast<int>(i));
  // Older buffer only (nothing sent this frame).
  EventReader<Hit> other;
  queue.update();
  EXPECT_EQ(drain(other, queue), (std::vector<int>{3, 4}));
}

TEST(Events, ClearDropsStoredEvents) {
  EventQueue<Hit> queue;
  EventReader<Hit> reader;
  queue.send(Hit{1});
  queue.clear();
  EXPECT_TRUE(reader.read(queue).empty());
  EXPECT_EQ(reader.missedCount(), 1u);
  queue.send(Hit{2});
  EXPECT_EQ(drain(reader, queue), (std::vector<int>{2}));
}

TEST(Events, WorldOwnsOneQueuePerTypeAndUpdatesThemAll) {
  World world;
  EXPECT_EQ(world.findEvents<Hit>(), nullptr);
  EventQueue<Hit>& hits = world.events<Hit>();
  EXPECT_EQ(&world.events<Hit>(), &hits);
  EXPECT_EQ(world.findEvents<Hit>(), &hits);
  EventQueue<int>& numbers = world.events<int>();
  hits.send(Hit{1});
  numbers.send(7);
  world.updateEvents();
  world.updateEvents();
  EXPECT_TRUE(hits.empty());
  EXPECT_TRUE(numbers.empty());
}

}  // namespace
