// Output files of the commands: all or nothing.
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

#include <unistd.h>  // getpid, for unique temporary names

#include "cli/commands.hpp"

namespace cslice::cli {

namespace {

// Writes to a temporary file beside `path`, so a failed write never leaves a half file; the
// temporary goes too when `write` throws (out of memory halfway).
std::string write_temp(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string temp = path + ".tmp" + std::to_string(::getpid());
  std::ofstream out(temp, std::ios::binary);
  bool written = false;
  try {
    if (out) write(out);
    out.close();
    written = static_cast<bool>(out);
  } catch (...) {
    std::error_code ignored;
    out.close();
    std::filesystem::remove(temp, ignored);
    throw;
  }
  if (!written) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw ExitError(kExitBadInput, "cannot write '" + path + "'");
  }
  return temp;
}
std::string write_temp(const std::string& path, const std::string& text) {
  return write_temp(path, [&](std::ostream& out) { out << text; });
}

void rename_into_place(const std::string& temp, const std::string& path) {
  std::error_code error;
  std::filesystem::rename(temp, path, error);
  if (error) throw ExitError(kExitBadInput, "cannot write '" + path + "': " + error.message());
}

// All outputs or none: every file goes to a temporary first and is renamed into place only
// when all of them were written.
void write_files(const std::vector<std::pair<std::string, std::string>>& outputs) {
  std::vector<std::pair<std::string, std::string>> temps;  // (temp, final)
  try {
    for (const auto& [path, text] : outputs) temps.emplace_back(write_temp(path, text), path);
  } catch (...) {
    std::error_code ignored;
    for (const auto& t : temps) std::filesystem::remove(t.first, ignored);
    throw;
  }
  for (const auto& [temp, path] : temps) rename_into_place(temp, path);
}

}  // namespace

void deliver_outputs(std::vector<std::pair<std::string, std::string>> outputs) {
  // Standard output last: it cannot be taken back if a file then failed.
  std::string to_stdout;
  std::erase_if(outputs, [&](const auto& o) {
    if (o.first != kStdout) return false;
    to_stdout = std::move(o.second);
    return true;
  });
  write_files(outputs);
  std::cout << to_stdout << std::flush;
}

void deliver_output(const std::string& path, std::string text) {
  std::vector<std::pair<std::string, std::string>> outputs;
  outputs.emplace_back(path, std::move(text));
  deliver_outputs(std::move(outputs));
}

void deliver_written(const std::string& path, const std::function<void(std::ostream&)>& write) {
  if (path == kStdout) {  // made whole first: printed text cannot be taken back
    std::ostringstream text;
    write(text);
    std::cout << std::move(text).str() << std::flush;
    return;
  }
  rename_into_place(write_temp(path, write), path);
}

}  // namespace cslice::cli
