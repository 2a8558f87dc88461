// cslice equivalent PAIR.json T1 T2: whether two slices have label-preserving isomorphic
// contact graphs. Exit status 0 when equivalent, 1 when not (like diff), 2 on bad input.
#include <cmath>
#include <iostream>

#include "cli/commands.hpp"
#include "cslice/equivalence.hpp"

namespace cslice::cli {

void register_equivalent(CLI::App& app) {
  auto* cmd = app.add_subcommand("equivalent",
                                 "Whether the slices at two orientations are equivalent (paper, "
                                 "section 4); prints 'equivalent' or the first difference");
  auto path = std::make_shared<std::string>();
  auto thetas = std::make_shared<std::vector<double>>();
  cmd->add_option("pair", *path, "pair file (JSON)")->required();
  cmd->add_option("thetas", *thetas, "two orientations, radians")->required()->expected(2);
  cmd->callback([path, thetas] {
    for (double t : *thetas)
      if (!std::isfinite(t)) throw ExitError(kExitBadInput, "orientations must be finite numbers");
    const Pair pair = load_pair_or_exit(*path);
    const EquivalenceResult r =
        slices_equivalent(compute_slice(pair, (*thetas)[0]), compute_slice(pair, (*thetas)[1]));
    if (r.equivalent) {
      std::cout << "equivalent\n";
      return;
    }
    std::cout << "not equivalent: " << r.difference << "\n";
    throw ExitError(1, "");  // the answer is on standard output
  });
}

}  // namespace cslice::cli
