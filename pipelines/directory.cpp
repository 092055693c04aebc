#include "pipelines/directory.hpp"

#include <algorithm>
#include <system_error>

#include "common/errors.hpp"

namespace grainmesh {

namespace fs = std::filesystem;

fs::path absolute_path(fs::path p) {
  std::error_code ec;
  fs::path a = fs::weakly_canonical(fs::absolute(p), ec);
  if (ec) a = fs::absolute(p).lexically_normal();
  if (a.filename().empty()) a = a.parent_path();
  return a;
}

bool holds_current_directory(const fs::path& dir) {
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  if (ec) return false;
  const fs::path d = absolute_path(dir), here = absolute_path(cwd);
  const auto [d_end, h_end] = std::mismatch(d.begin(), d.end(), here.begin(), here.end());
  return d_end == d.end();  // every part of dir begins the current directory
}

std::vector<std::string> entry_names(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string entry_list(const fs::path& dir) {
  std::string list;
  bool cases_listed = false;
  for (const std::string& name : entry_names(dir)) {
    const bool load_case = name.rfind("case_", 0) == 0;
    if (load_case && cases_listed) continue;
    cases_listed = cases_listed || load_case;
    std::error_code ec;
    list += (list.empty() ? "" : ", ") + (load_case ? std::string("case_*") : name) +
            (fs::is_directory(dir / name, ec) ? "/" : "");
  }
  return list;
}

bool occupied_directory(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return false;
  const std::string where = absolute_path(dir).string();
  if (!fs::is_directory(dir, ec)) throw IoError(where + ": exists and is not a directory");
  if (holds_current_directory(dir))
    throw IoError(where + ": is the current directory or holds it; refusing to write into it (give a new directory)");
  return !fs::is_empty(dir, ec);
}

}  // namespace grainmesh
