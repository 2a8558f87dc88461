// Output files of the commands: all or nothing.
#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>  // getpid, for unique temporary names

#include "cli/commands.hpp"

namespace cslice::cli {

namespace {

// Writes to a temporary file beside `path`, so a failed write never leaves a half file.
std::string write_temp(const std::string& path, const std::string& text) {
  const std::string temp = path + ".tmp" + std::to_string(::getpid());
  std::ofstream out(temp, std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw ExitError(kExitBadInput, "cannot write '" + path + "'");
  }
  return temp;
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
  for (const auto& [temp, path] : temps) {
    std::error_code error;
    std::filesystem::rename(temp, path, error);
    if (error) throw ExitError(kExitBadInput, "cannot write '" + path + "': " + error.message());
  }
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

}  // namespace cslice::cli
