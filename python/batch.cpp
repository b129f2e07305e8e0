// wrenchkit.batch's native part (_core.Batch): the lines of `wrenchkit batch COMMAND [OPTIONS]` for a chunk of
// scene texts, made by the command line's own parts — its option table (prepare_batch: the same parsing,
// validation and usage errors) and its batch line (batch_line: the command's --json answer with "line" first,
// or the error line) — on the batch's ordered map (exact/pipeline/ordered_map.h) with the GIL released. So a
// line here is byte for byte the command line's. The package (python/wrenchkit/__init__.py) streams an
// iterable through it chunk by chunk, numbering lines from where the previous chunk ended.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "cli/command_table.h"
#include "cli/common.h"
#include "exact/pipeline/ordered_map.h"
#include "python/convert.h"

namespace wrenchkit::python {

namespace {

struct Batch {
  cli::Batch_job job;

  // The lines (bytes, no newline) of texts[0..], numbered from first_line, and the exit code the command
  // line would end with for them (0; 4 when a certificate was rejected; 70 after an internal error).
  py::tuple run(const std::vector<std::string>& texts, std::size_t first_line, unsigned jobs) const {
    std::vector<std::string> out(texts.size());
    bool self_check = false, internal = false;
    {
      py::gil_scoped_release release;
      std::size_t next = 0;
      struct Worker {};
      ordered_map<std::size_t, Status, Worker>(
          jobs ? jobs : job.options.jobs, [&](std::size_t& i) { return next < texts.size() ? (i = next++, true) : false; },
          [&](Worker&, std::size_t i, Status& s, std::size_t) {
            const std::string& t = texts[i];
            s = cli::batch_line(job.options, job.answer, t, t.size() > job.options.limits.max_file_bytes,
                                first_line + i, out[i]);
          },
          [&](std::size_t, Status s) {
            self_check |= s == Status::check_failed;
            internal |= s == Status::internal_error;
          });
    }
    py::list lines;
    for (const std::string& l : out) lines.append(py::bytes(l));
    return py::make_tuple(lines, static_cast<int>(self_check ? cli::kSelfCheck : internal ? cli::kInternal : cli::kAnswered));
  }
};

}  // namespace

void register_batch(py::module_& m) {
  py::class_<Batch>(m, "Batch")
      .def(py::init([](const std::vector<std::string>& args) {
        try {
          return Batch{cli::prepare_batch(args)};
        } catch (const cli::Usage_error& e) {
          throw std::invalid_argument(e.what());
        }
      }))
      .def("run", &Batch::run);
}

}  // namespace wrenchkit::python
