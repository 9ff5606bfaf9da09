#include "gpu_test.h"

#include "engine/core/log.h"

namespace test {
namespace {

struct Shared {
  std::unique_ptr<engine::gfx::Instance> instance;
  std::unique_ptr<engine::gfx::Device> device;
  std::mutex mutex;
  std::vector<engine::gfx::ValidationMessage> messages;
};

Shared& shared() {
  // Created on first use and deliberately leaked: static destruction order across test
  // translation units is unspecified, and the process is about to exit anyway.
  static Shared* state = [] {
    auto* s = new Shared();
    engine::gfx::InstanceDesc desc;
    desc.appName = "cloudscape tests";
    desc.validation = true;
    s->instance = std::make_unique<engine::gfx::Instance>(desc);
    s->instance->setValidationHandler([s](const engine::gfx::ValidationMessage& message) {
      std::lock_guard lock(s->mutex);
      s->messages.push_back(message);
    });
    s->device = std::make_unique<engine::gfx::Device>(*s->instance, engine::gfx::DeviceDesc{});
    return s;
  }();
  return *state;
}

}  // namespace

engine::gfx::Instance& GpuTest::instance() {
  return *shared().instance;
}
engine::gfx::Device& GpuTest::device() {
  return *shared().device;
}

std::vector<engine::gfx::ValidationMessage> GpuTest::takeMessages() {
  Shared& s = shared();
  std::lock_guard lock(s.mutex);
  return std::exchange(s.messages, {});
}

void GpuTest::SetUp() {
  engine::log::setMinimumLevel(engine::log::Level::Warning);
  device();
  takeMessages();  // anything before this test belongs to no test
}

void GpuTest::TearDown() {
  device().waitIdle();
  for (const auto& message : takeMessages()) {
    ADD_FAILURE() << "Vulkan validation message [" << message.idName << "]: " << message.text;
  }
}

}  // namespace test
