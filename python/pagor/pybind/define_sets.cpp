// _pagor.bench_pairs and what run_pairs (pagor/sets.py) needs around it: the pairs of a set run
// here give the very result lines `pagor bench --out` writes (the core's pair_outcome report and
// bench_result_line), their run keys, the tool's build, and the lock of an output file.

#include <dlfcn.h>

#include <pybind11/stl.h>
#include <memory>
#include <optional>

#include "bindings.hpp"
#include "json_objects.hpp"
#include "pagor/errors.hpp"
#include "pagor/eval/file_lock.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/eval/runner.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/file_input.hpp"

namespace pagor::python {
namespace {

// The set a spec names: ("manifest", PATH) or ("kitti", ROOT, SEQUENCE, PAIRS_FILE).
PairSet open_set(const std::vector<std::string>& spec) {
  if (spec.size() == 2 && spec[0] == "manifest") return read_pair_manifest(spec[1]);
  if (spec.size() == 4 && spec[0] == "kitti") return kitti_pair_set(spec[1], spec[2], spec[3]);
  throw py::value_error("pairs: expected ('manifest', PATH) or ('kitti', ROOT, SEQUENCE, FILE)");
}

// This extension and its build, as the pagor tool names itself: the version and a fingerprint of
// the extension's file (another build gives other run keys).
std::string tool_version() {
  static const std::string tool = [] {
    std::string build = "unknown";
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&open_set), &info) != 0 && info.dli_fname) {
      try {
        build = fingerprint(file_fingerprint(info.dli_fname, "extension", kMaxCloudFileBytes));
      } catch (const InputError&) {  // unreadable: the version alone
      }
    }
    return std::string("pagor ") + PAGOR_VERSION + " (python, build " + build + ")";
  }();
  return tool;
}

// Pairs `indices` of the set, run one after the other on one runner with the GIL released; per
// pair a dict: index, pair (its name), line (the result line, or None when it failed), failed
// (why, naming its file, or None), warnings.
py::list bench_pairs(const std::vector<std::string>& spec, const std::vector<std::size_t>& indices,
                     const std::string& config_json, int threads) {
  const Config config = parse_config(config_json, "config");
  const PairSet set = open_set(spec);
  for (std::size_t i : indices)
    if (i >= set.pairs.size())
      throw py::index_error("pair index " + std::to_string(i) + " beyond the " +
                            std::to_string(set.pairs.size()) + " pairs of " + set.origin);
  struct Row {
    PairOutcome outcome;
    std::string line;
  };
  std::vector<Row> rows;
  {
    const py::gil_scoped_release release;
    SetRunner runner(set, threads);
    for (std::size_t i : indices) {
      Row row{runner.run(i, config), {}};
      if (row.outcome.loaded) {
        const PairEntry& entry = set.pairs[i];
        row.line = bench_result_line(row.outcome.report_json, entry.name,
                                     run_key(tool_version(), config, entry), tool_version());
      }
      rows.push_back(std::move(row));
    }
  }
  py::list out;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const PairOutcome& o = rows[k].outcome;
    py::dict d;
    d["index"] = indices[k];
    d["pair"] = py::bytes(o.name).attr("decode")("utf-8", "surrogateescape");
    d["line"] = o.loaded ? py::object(py::str(rows[k].line)) : py::object(py::none());
    d["failed"] = o.loaded ? py::object(py::none()) : py::object(py::str(o.load_error));
    d["warnings"] = o.load_warnings;
    out.append(d);
  }
  return out;
}

// Each pair's name and run key ("" for a pair whose files cannot be read now).
py::list pair_keys(const std::vector<std::string>& spec, const std::string& config_json) {
  const Config config = parse_config(config_json, "config");
  const PairSet set = open_set(spec);
  py::list out;
  for (const PairEntry& e : set.pairs) {
    std::string key;
    try {
      key = run_key(tool_version(), config, e);
    } catch (const InputError&) {
    }
    out.append(py::make_tuple(py::bytes(e.name).attr("decode")("utf-8", "surrogateescape"), key));
  }
  return out;
}

}  // namespace

void define_sets(py::module_& m) {
  m.def("bench_pairs", &bench_pairs, py::arg("spec"), py::arg("indices"), py::arg("config_json"),
        py::arg("threads") = 1);
  m.def("pair_keys", &pair_keys, py::arg("spec"), py::arg("config_json"));
  m.def("tool_version", &tool_version);
  m.def(
      "config_json",
      [](const py::handle& config) { return config_to_json(config_from_python(config), -1); },
      py::arg("config"));
  m.def(
      "config_file_json",
      [](const std::string& path, const std::string& base_preset) {
        return config_to_json(load_config(path, base_preset), -1);
      },
      py::arg("path"), py::arg("base_preset") = "default");
  m.def(
      "progress_text",
      [](std::size_t done, std::size_t total, std::size_t ran, std::size_t to_run,
         double elapsed_s) {
        return progress_text({done, total, ran, to_run, elapsed_s});
      },
      py::arg("done"), py::arg("total"), py::arg("ran"), py::arg("to_run"), py::arg("elapsed_s"));
  py::class_<FileLock>(m, "FileLock")
      .def(py::init<const std::string&, const std::string&>(), py::arg("path"), py::arg("purpose"))
      .def_property_readonly("lock_path", &FileLock::lock_path);
}

}  // namespace pagor::python
