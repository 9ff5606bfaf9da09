#pragma once
// The text of clouds.h's Settings struct (CLOUDS_HEADER, from its opening line to its closing
// brace), for the tests that hold the code to what the header documents.
#include <fstream>
#include <sstream>
#include <string>

namespace test {

inline std::string settingsDeclaration() {
  std::ifstream header(CLOUDS_HEADER);
  std::stringstream text;
  text << header.rdbuf();
  const std::string all = text.str();
  const std::size_t begin = all.find("struct Settings {");
  const std::size_t end = all.find("\n};", begin);
  return all.substr(begin, end - begin);
}

}  // namespace test
