// pagor: the command-line front end of Pagor Studio.

#include <csignal>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "command.hpp"
#include "common/allocator.hpp"
#include "pagor/errors.hpp"

namespace pagor::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> kCommands = {
      {"demo", "run the main job on the shared KITTI data, or on the synthetic scene", demo_options,
       run_demo},
      {"register", "register a source cloud to a target cloud", register_options, run_register},
      {"bench", "run every pair of a KITTI pairs file and summarise", bench_options, run_bench},
      {"sweep", "run a grid of settings over a pairs set (ablation table, CSV, plot)",
       sweep_options, run_sweep_command},
      {"landmarks", "extract semantic landmarks from one cloud", landmarks_options, run_landmarks},
      {"config", "print or check a configuration", config_options, run_config},
      {"indoor", "generate an indoor sequence (car park, floor plan, scans) for bench",
       indoor_options, run_indoor},
      {"self-similar", "generate scenes that repeat themselves (corridors, facades) for bench",
       self_similar_options, run_self_similar},
  };
  return kCommands;
}

namespace {

void print_usage() {
  std::cout << "usage: pagor <command> [options]     (pagor <command> --help for its options;\n"
               "                                      pagor --version)\n\n"
               "commands:\n";
  for (const auto& c : commands()) {
    std::string name = c.name;
    name.resize(14, ' ');
    std::cout << "  " << name << c.summary << "\n";
  }
}

int dispatch(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    print_usage();
    return argc < 2 ? 2 : 0;
  }
  if (std::string(argv[1]) == "--version") {
    std::cout << "pagor " << PAGOR_VERSION << "\n";
    return 0;
  }
  const std::string name = argv[1];
  for (const auto& c : commands()) {
    if (name != c.name) continue;
    std::vector<std::string> words(argv + 2, argv + argc);
    std::vector<Option> options = c.options();
    for (const auto& w : words)
      if (w == "--help" || w == "-h") {
        std::cout << "usage: pagor " << c.name << " [options]\n"
                  << c.summary << "\n\noptions:\n"
                  << format_options(options);
        return 0;
      }
    return c.run(Args(words, options));
  }
  throw UsageError("unknown command '" + name + "' (see pagor --help)");
}

}  // namespace
}  // namespace pagor::cli

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) makes a write fail with EFBIG, which the writers report and
  // recover from, instead of killing the process in the middle of a file.
  std::signal(SIGXFSZ, SIG_IGN);
  pagor::app::keep_freed_memory();
  try {
    return pagor::cli::dispatch(argc, argv);
  } catch (const pagor::cli::UsageError& e) {
    std::cerr << "pagor: usage error: " << e.what() << "\n";
    return 2;
  } catch (const pagor::Error& e) {
    std::cerr << "pagor: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {  // inputs too large for this machine: say so plainly
    std::cerr << "pagor: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "pagor: internal error: " << e.what() << "\n";
    return 3;
  }
}
