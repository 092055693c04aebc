// The docs as a newcomer reads them: README.md a short front page, every config key
// documented once, in docs/keys.md, generated from the table the config readers check
// (so a key added, renamed or given a new default fails here until the page is
// regenerated: `build/grainmesh keys --markdown > docs/keys.md`), and every link between
// the pages leading somewhere.
#include <catch2/catch.hpp>

#include <regex>
#include <set>
#include <sstream>

#include "helpers.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/key_reference.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> pages() {
  std::vector<fs::path> all{test::source_dir() / "README.md"};
  for (const auto& e : fs::directory_iterator(test::source_dir() / "docs"))
    if (e.path().extension() == ".md") all.push_back(e.path());
  return all;
}

// GitHub's anchor of a heading: lower case, punctuation dropped, spaces as '-'.
std::string anchor(const std::string& heading) {
  std::string a;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_' || c >= 0x80) a += static_cast<char>(std::tolower(c));
    else if (c == ' ') a += '-';
  }
  return a;
}

std::set<std::string> anchors(const fs::path& page) {
  std::set<std::string> out;
  std::istringstream in(test::read_file(page));
  bool code = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) code = !code;
    if (!code && line.rfind('#', 0) == 0) out.insert(anchor(line.substr(line.find(' ') + 1)));
  }
  return out;
}

}  // namespace

TEST_CASE("docs/keys.md is the key table the config readers check, as grainmesh keys --markdown prints it",
          "[docs][cli]") {
  const auto r = test::run_grainmesh({"keys", "--markdown"});
  REQUIRE(r.exit_code == 0);
  CHECK(r.out == key_reference_markdown());
  CHECK(test::read_file(test::source_dir() / "docs/keys.md") == r.out);
  for (const ConfigKey& k : config_key_table()) CHECK(r.out.find(std::string("| `") + k.key + "` |") != std::string::npos);
}

TEST_CASE("every key is documented once: no page but docs/keys.md has a row of its own for a key", "[docs]") {
  for (const fs::path& page : pages()) {
    if (page.filename() == "keys.md") continue;
    const std::string text = test::read_file(page);
    for (const ConfigKey& k : config_key_table()) {
      INFO(page.filename().string() << ": " << k.key);
      CHECK(text.find(std::string("\n| `") + k.key + "` |") == std::string::npos);
    }
  }
}

TEST_CASE("README.md is a front page of under 250 lines, and every link of the docs leads to a page and a heading",
          "[docs]") {
  const std::string readme = test::read_file(test::source_dir() / "README.md");
  CHECK(std::count(readme.begin(), readme.end(), '\n') < 250);
  const std::regex link(R"(\]\(([^)\s]*)\))");
  for (const fs::path& page : pages()) {
    const std::string text = test::read_file(page);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
      const std::string target = (*it)[1];
      if (target.rfind("http", 0) == 0 || target.empty()) continue;
      INFO(page.filename().string() << " links to " << target);
      const auto hash = target.find('#');
      const fs::path file = hash == 0 ? page : page.parent_path() / target.substr(0, hash);
      REQUIRE(fs::exists(file));
      if (hash != std::string::npos) CHECK(anchors(file).count(target.substr(hash + 1)) == 1);
    }
  }
}
