#include <gtest/gtest.h>

#include <filesystem>

#include "engine/core/error.h"
#include "engine/core/file_io.h"

namespace {

TEST(FileIo, MissingFileNamesThePath) {
  try {
    engine::readTextFile("/nonexistent/dir/scene.json");
    FAIL() << "expected engine::Error";
  } catch (const engine::Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.json"), std::string::npos);
  }
}

TEST(FileIo, RoundTripsTextAndRejectsOversizedFiles) {
  const auto path = std::filesystem::temp_directory_path() / "cloudscape_file_io_test/a.txt";
  engine::writeTextFile(path, "hello");
  EXPECT_EQ(engine::readTextFile(path), "hello");
  EXPECT_THROW(engine::readTextFile(path, 3), engine::Error);
  std::filesystem::remove_all(path.parent_path());
}

}  // namespace
