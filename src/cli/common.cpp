#include <cmath>
#include <sstream>

#include "cli/commands.hpp"

namespace cslice::cli {

Pair load_pair_or_exit(const std::string& path) {
  LoadResult result = load_pair(path);
  if (!result.ok()) throw ExitError(kExitBadInput, result.error->message());
  return std::move(*result.pair);
}

Pose parse_pose_or_exit(const std::string& text, const std::string& what) {
  std::string normalized = text;
  for (char& ch : normalized)
    if (ch == ',') ch = ' ';
  std::istringstream in(normalized);
  Pose p;
  std::string extra;
  if (!(in >> p.x >> p.y >> p.theta) || (in >> extra) || !std::isfinite(p.x) ||
      !std::isfinite(p.y) || !std::isfinite(p.theta)) {
    throw ExitError(kExitBadInput,
                    what + ": expected three finite numbers x,y,theta, got '" + text + "'");
  }
  return p;
}

}  // namespace cslice::cli
