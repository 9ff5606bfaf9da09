// Compiles against the module's one public header only; creating a context without a device
// must fail cleanly with a message (no crash).
#include <clouds/clouds.h>

#include <cstdio>

int main() {
  std::string error;
  auto context = clouds::Context::create(clouds::CreateInfo{}, &error);
  std::printf("%s\n", error.c_str());
  return context == nullptr && !error.empty() ? 0 : 1;
}
