// wrenchkit batch COMMAND: JSON lines in, one answer per line, in order, on --jobs threads.
#include <algorithm>
#include <atomic>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "cli/common.h"
#include "exact/input_error.h"
#include "exact/json.h"

namespace wrenchkit::cli {

namespace {

bool read_line(std::istream& in, std::string& line, std::size_t limit, bool& too_long) {
  line.clear();
  too_long = false;
  std::streambuf* sb = in.rdbuf();
  bool any = false;
  for (;;) {
    const int c = sb->sbumpc();
    if (c == std::char_traits<char>::eof()) return any;
    any = true;
    if (c == '\n') return true;
    if (line.size() < limit) line.push_back(static_cast<char>(c));
    else too_long = true;
  }
}

std::string error_line(std::size_t line, const char* kind, int code, const std::string& message) {
  return "{\"line\": " + std::to_string(line) + ", \"" + kind + "\": " + json::quote(message) +
         ", \"exit_code\": " + std::to_string(code) + "}";
}

}  // namespace

// wrenchkit batch closure: one scene per input line, one JSON answer per output line, in order.
int run_batch(const Options& o) {
  if (o.positional.size() != 1 || o.positional[0] != "closure")
    throw Usage_error("batch needs a command: wrenchkit batch closure [OPTIONS] < scenes.jsonl");
  if (!o.certificate_file.empty() || !o.form_certificate_file.empty())
    throw Usage_error("batch writes certificates in its output lines, not to files");
  unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t chunk = 256 * std::size_t(jobs);
  std::vector<std::string> lines, out;
  std::vector<char> too_long;
  std::atomic<bool> self_check_failed{false}, internal_error{false};
  std::size_t first_line = 1;
  std::string line;
  bool eof = false;
  while (!eof) {
    lines.clear();
    too_long.clear();
    while (lines.size() < chunk) {
      bool longer = false;
      if (!read_line(std::cin, line, o.limits.max_file_bytes, longer)) {
        eof = true;
        break;
      }
      lines.push_back(line);
      too_long.push_back(longer);
    }
    if (lines.empty()) break;
    out.assign(lines.size(), std::string());
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t i; (i = next++) < lines.size();) {
        const std::size_t n = first_line + i;
        try {
          if (too_long[i])
            throw Input_error("line larger than the size limit of " + std::to_string(o.limits.max_file_bytes) +
                              " bytes (--max-file-size)");
          out[i] = closure_json(o, compute_closure(o, lines[i], "line " + std::to_string(n), true), "closure", n);
        } catch (const Input_error& e) {
          out[i] = error_line(n, "error", kBadInput, e.what());
        } catch (const Undecided& e) {
          out[i] = error_line(n, "undecided", kUndecided, e.what());
        } catch (const Self_check_failure& e) {
          self_check_failed = true;
          out[i] = error_line(n, "internal_error", kSelfCheck, e.what());
        } catch (const std::exception& e) {
          internal_error = true;
          out[i] = error_line(n, "internal_error", kInternal, e.what());
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < jobs && t < lines.size(); ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    for (const std::string& s : out) std::cout << s << '\n';
    first_line += lines.size();
  }
  std::cout.flush();
  return self_check_failed ? kSelfCheck : (internal_error ? kInternal : kAnswered);
}

}  // namespace wrenchkit::cli
