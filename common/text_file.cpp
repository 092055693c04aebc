#include "common/text_file.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "common/interrupt.hpp"

namespace grainmesh {

namespace fs = std::filesystem;

std::string read_text_file(const fs::path& file, const std::string& what) {
  std::error_code ec;
  if (fs::is_directory(file, ec)) throw IoError(file.string() + ": is a directory (expected the " + what + ")");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(file.string() + ": cannot open " + what);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text_file(const fs::path& file, const std::string& text) {
  // Of this process alone: shards of a sweep write its summary side by side.
  const fs::path tmp = file.string() + "." + std::to_string(::getpid()) + ".tmp";
  const TemporaryPath registered(tmp);  // removed on an interrupt
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.flush();
    if (!out) throw IoError(file.string() + ": cannot write");
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) throw IoError(file.string() + ": cannot write: " + ec.message());
}

}  // namespace grainmesh
