// wrenchkit batch COMMAND [FILE ...]: JSON lines in, one answer per line, in order, on --jobs threads. Each
// line's answer is the command's own --json answer (its Scene_answer, cli/common.h) with a "line"
// field first; the threads and the order are exact/pipeline/batch.h's ordered_map.
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "cli/common.h"
#include "exact/pipeline/ordered_map.h"
#include "exact/io/input_error.h"
#include "exact/io/json_writer.h"

namespace wrenchkit::cli {

namespace {

// The inputs (standard input, or files one after the other) read in blocks and split into lines (without the
// '\n'; a file's last line need not end with one). A line longer than `limit` bytes is flagged and its text
// dropped as it streams by, so memory stays bounded.
class Line_reader {
 public:
  Line_reader(std::vector<std::streambuf*> in, std::size_t limit) : in_(std::move(in)), limit_(limit), buf_(1 << 16) {}

  // The next line into `line`; false at the end of the last input.
  bool next(std::string& line, bool& too_long) {
    line.clear();
    too_long = false;
    bool any = false;
    for (;;) {
      if (pos_ == end_ && !fill()) {
        if (any) return true;
        if (++current_ >= in_.size()) return false;
        eof_ = false;
        continue;
      }
      any = true;
      const char* b = buf_.data() + pos_;
      const std::size_t left = end_ - pos_;
      const char* nl = static_cast<const char*>(std::memchr(b, '\n', left));
      const std::size_t n = nl ? static_cast<std::size_t>(nl - b) : left;
      if (!too_long) {
        if (line.size() + n <= limit_) {
          line.append(b, n);
        } else {
          too_long = true;
          line.clear();
        }
      }
      pos_ += n;
      if (nl) {
        ++pos_;
        return true;
      }
    }
  }

 private:
  bool fill() {
    if (eof_) return false;
    const std::streamsize got = in_[current_]->sgetn(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    pos_ = 0;
    end_ = got > 0 ? static_cast<std::size_t>(got) : 0;
    eof_ = end_ == 0;
    return !eof_;
  }

  std::vector<std::streambuf*> in_;
  std::size_t current_ = 0;
  std::size_t limit_;
  std::vector<char> buf_;
  std::size_t pos_ = 0, end_ = 0;
  bool eof_ = false;
};

struct Line {
  std::string text;
  bool too_long = false;
};

struct Worker {};

// [BATCH] Memory in flight: a window of at most 256 lines per thread and at most 64 MiB of line text (so a
// window of long lines holds fewer of them, at least one), and a line's storage beyond 1 MiB is freed
// before the next line is read into it. With the scene budget (docs/scene-format.md "Limits") bounding
// what each line's scene can cost, memory is bounded by the window plus one scene per thread.
constexpr std::size_t kWindowPerThread = 256;
constexpr std::size_t kWindowBytes = std::size_t(64) << 20;
constexpr std::size_t kKeptLineBytes = std::size_t(1) << 20;

// A line that was not answered: {"line": N, KIND: MESSAGE, "exit_code": C}, KIND "error" (bad input, or
// options that cannot apply to this scene), "undecided" or "internal_error".
void write_error_line(Json_writer& w, std::size_t line, const Ended& e) {
  const char* kind = e.status == Status::bad_input ? "error" : e.status == Status::undecided ? "undecided" : "internal_error";
  w.clear();
  w.object().member("line", line).member(kind, e.message).member("exit_code", exit_code(e.status)).end_object();
}

}  // namespace

Status batch_line(const Options& o, const Scene_answer& answer, const std::string& text, bool too_long,
                  std::size_t n, std::string& out) {
  Json_writer j(512, std::move(out));  // the line's own string again: its capacity is reused
  Status status = Status::answered;
  try {
    if (too_long)
      throw Input_error("line larger than the size limit of " + std::to_string(o.limits.max_file_bytes) +
                        " bytes (--max-file-size)");
    const std::string source = "line " + std::to_string(n);
    j.object().member("line", n);  // the command's answer with "line" first
    answer(j, text, source);
    j.end_object();
  } catch (...) {
    const Ended e = failure_of(std::current_exception());
    status = e.status;
    write_error_line(j, n, e);
  }
  out = j.take();
  return status;
}

// wrenchkit batch COMMAND [OPTIONS] [FILE ...] (the command and its options already read and prepared:
// cli/command_table.cpp): the lines of the files in their order (- or none: standard input), numbered on across
// the files. Every file is opened before any line is read.
int run_batch(const Options& o, const Scene_answer& answer) {
  std::atomic<bool> self_check_failed{false}, internal_error{false};
  std::vector<std::unique_ptr<std::filebuf>> files;
  std::vector<std::streambuf*> inputs;
  for (const std::string& path : o.positional) {
    if (path == "-") {
      inputs.push_back(std::cin.rdbuf());
      continue;
    }
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw Input_error(path + ": is a directory, not a file of scenes");
    files.push_back(std::make_unique<std::filebuf>());
    if (!files.back()->open(path, std::ios::in | std::ios::binary))
      throw Input_error(path + ": cannot open (" + std::strerror(errno) + ")");
    inputs.push_back(files.back().get());
  }
  if (inputs.empty()) inputs.push_back(std::cin.rdbuf());
  Line_reader reader(std::move(inputs), o.limits.max_file_bytes);
  ordered_map<Line, std::string, Worker>(
      o.jobs,
      [&](Line& l) {
        if (l.text.capacity() > kKeptLineBytes) std::string().swap(l.text);  // a long line's storage goes
        return reader.next(l.text, l.too_long);
      },
      [&](Worker&, const Line& l, std::string& out, std::size_t index) {
        const Status s = batch_line(o, answer, l.text, l.too_long, index + 1, out);
        if (s == Status::check_failed) self_check_failed = true;
        if (s == Status::internal_error) internal_error = true;
      },
      [&](std::size_t, const std::string& out) {
        std::cout.write(out.data(), static_cast<std::streamsize>(out.size()));
        std::cout.put('\n');
      },
      kWindowPerThread, kWindowBytes, [](const Line& l) { return l.text.size(); });
  std::cout.flush();
  return self_check_failed ? kSelfCheck : (internal_error ? kInternal : kAnswered);
}

}  // namespace wrenchkit::cli
