// cslice: configuration spaces of planar parts bounded by segments and circular arcs.
#include <iostream>
#include <new>

#include "cli/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "cslice: the configuration space of a rigid planar part moving amidst fixed obstacles,\n"
      "both bounded by line segments and circular arcs."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "cslice 0.1.0");
  cslice::cli::register_info(app);
  cslice::cli::register_import(app);
  cslice::cli::register_classify(app);
  cslice::cli::register_render(app);
  cslice::cli::register_equivalent(app);
  cslice::cli::register_slice(app);
  cslice::cli::register_critical(app);
  cslice::cli::register_mesh(app);
  cslice::cli::register_compute(app);
  cslice::cli::register_stats(app);
  cslice::cli::register_analyze(app);
  cslice::cli::register_query(app);
  cslice::cli::register_path(app);
  cslice::cli::register_view(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : cslice::cli::kExitBadInput;
  } catch (const cslice::cli::ExitError& e) {
    if (*e.what() != '\0') std::cerr << "cslice: " << e.what() << "\n";
    return e.code;
  } catch (const std::bad_alloc&) {
    // Not a fault of the input or of cslice: the machine's memory ran out. The critical
    // orientations and slices of a pair grow fast with its features (600 features: 19,717
    // orientations, 4 GB to compute its space).
    std::cerr << "cslice: out of memory: this computation needs more memory than is available "
                 "(docs/performance.md, larger pairs)\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "cslice: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
