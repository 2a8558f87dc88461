// Pairs for the CGAL placement oracle (tests/cgal_classify_oracle.cpp), as pair-format JSON
// so that the oracle reads the same text the library does: random star-shaped parts with
// gently curved edges, holes and round loops; rings around pegs; openings (enclosures); two
// separate blocks. Also every bundled example. Kept apart from the oracle so the slow CGAL
// translation unit stays small, and so other tests can reuse the scenes.
#pragma once

#include <nlohmann/json.hpp>
#include <random>
#include <vector>

namespace cslice::testkit {

// Uniform in [lo, hi).
double uniform(std::mt19937_64& rng, double lo, double hi);

// A random pair named "random-<index>", about 10 units across. Only straight edges unless
// `curved`. Half of them name a tolerance. Not validated: the caller passes it to parse_pair
// and draws again if the reader rejects it (rare: an arc crossing a neighbouring edge).
nlohmann::json oracle_random_pair(std::mt19937_64& rng, int index, bool curved);

// Every examples/*.json of the source tree, sorted by file name (empty before they exist).
std::vector<nlohmann::json> example_pair_files();

}  // namespace cslice::testkit
