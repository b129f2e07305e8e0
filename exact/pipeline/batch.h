// [BATCH] Many scenes at once (interface.md §2 `batch`, docs/design.md): answers in input order,
// computed on `jobs` threads, each scene's error a value and never an exception, memory bounded
// whatever the number of scenes.
//
//   ordered_map     the ordered parallel map under every batch: the CLI's `wrenchkit batch COMMAND`
//                   and batch_closure below;
//   closure_item    one scene text → force and form closure [FC-1]–[FC-3], certified and checked as
//                   the options say (the `closure` command and `batch closure` use it too);
//   batch_closure   the C++ batch API: a vector of scene texts, or a stream with a callback.
//
// Exactness: every verdict is the exact verdict of the scene as written (decide_closure); the speed
// comes from the streaming scene reader (exact/io/streaming_scene_reader.h: one pass, storage reused per
// thread, rationals only on demand) and from reusing each thread's scratch storage.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "exact/statics/closure.h"
#include "exact/numbers/limits.h"
#include "exact/io/scene.h"

namespace wrenchkit {

// The number of threads for `jobs` (0: every core the system reports, at least 1).
inline unsigned batch_threads(unsigned jobs) { return jobs ? jobs : std::max(1u, std::thread::hardware_concurrency()); }

// The ordered parallel map. On the calling thread, next(Input&) fills the next input until it returns
// false; work(Worker&, Input&, Output&, index) maps each input (index counts from 0) on `jobs`
// threads (0: all cores), each thread with its own Worker (scratch storage reused from one input to the
// next); on the calling thread again, emit(index, Output&) receives the outputs in input order.
// Inputs are taken in windows of `window_per_thread`·jobs, so memory stays bounded whatever the
// number of inputs; Input and Output objects are reused from window to window (assign into them).
// `work` must not throw (turn a per-input error into an Output); next/emit may, and the map then
// stops and rethrows on the calling thread once its threads are idle.
template <class Input, class Output, class Worker, class Next, class Work, class Emit>
void ordered_map(unsigned jobs, Next&& next, Work&& work, Emit&& emit, std::size_t window_per_thread = 256) {
  const unsigned threads = batch_threads(jobs);
  const std::size_t window = std::max<std::size_t>(1, window_per_thread * threads);
  std::vector<Input> in(window);
  std::vector<Output> out(window);
  std::vector<Worker> workers(threads);
  std::size_t count = 0, first = 0;  // inputs in the current window, index of its first
  std::atomic<std::size_t> cursor{0};
  const auto run = [&](unsigned t) {
    for (std::size_t k; (k = cursor++) < count;) work(workers[t], in[k], out[k], first + k);
  };
  // Helper threads wait for a new generation, run it, and report when they are done.
  std::mutex m;
  std::condition_variable start, done;
  std::size_t generation = 0;
  unsigned busy = 0;
  bool stop = false;
  std::vector<std::thread> pool;
  const auto helper = [&](unsigned t, std::size_t seen) {  // seen: the generation before its first
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(m);
        start.wait(lock, [&] { return stop || generation != seen; });
        if (stop) return;
        seen = generation;
      }
      run(t);
      std::lock_guard<std::mutex> lock(m);
      if (--busy == 0) done.notify_one();
    }
  };
  const auto finish = [&] {
    {
      std::lock_guard<std::mutex> lock(m);
      stop = true;
    }
    start.notify_all();
    for (std::thread& th : pool) th.join();
  };
  try {
    for (bool more = true; more;) {
      count = 0;
      while (count < window && (more = next(in[count]))) ++count;
      if (count == 0) break;
      cursor = 0;
      const unsigned helpers = static_cast<unsigned>(std::min<std::size_t>(threads, count)) - 1;
      while (pool.size() < helpers) pool.emplace_back(helper, static_cast<unsigned>(pool.size() + 1), generation);
      if (!pool.empty()) {
        {
          std::lock_guard<std::mutex> lock(m);
          busy = static_cast<unsigned>(pool.size());
          ++generation;
        }
        start.notify_all();
      }
      run(0);
      if (!pool.empty()) {
        std::unique_lock<std::mutex> lock(m);
        done.wait(lock, [&] { return busy == 0; });
      }
      for (std::size_t k = 0; k < count; ++k) emit(first + k, out[k]);
      first += count;
    }
  } catch (...) {
    finish();
    throw;
  }
  finish();
}

// How one scene of a batch ended (the CLI's exit code in brackets).
enum class Batch_status {
  answered,        // (0)
  bad_input,       // (2) the scene text is not a valid scene: message is read_scene's Input_error
  undecided,       // (3) Mode::float_only could not decide
  check_failed,    // (4) a certificate was rejected by `check`: always a bug
  internal_error,  // (70) anything else (message: what())
};

struct Closure_batch_options {
  Mode mode = Mode::hybrid;
  bool certify = true;  // build both certificates (and their JSON); false: verdicts only
  Input_limits limits;
  unsigned jobs = 0;    // threads; 0: all cores
  // Re-verifies the certificates of one scene (certificate_json of force then form closure) against its
  // text; returns "" if every one is accepted, else the reason. The CLI passes the independent checker
  // of proofs/ (wrenchkit_checker::check_all); empty: not checked. Called from worker threads.
  std::function<std::string(std::string_view scene_text, const std::vector<std::string_view>& certificates)> check;
};

// One scene's force and form closure, or why not.
struct Closure_item {
  Batch_status status = Batch_status::answered;
  std::string message;                               // why, unless answered
  std::string name;                                  // the scene's "name"
  Closure_answer force, form;                        // answered
  std::string force_certificate, form_certificate;  // answered and certify: certificate_json of each
};

// Reads one scene text into `scratch` (the streaming reader; lazily — rationals only on demand —
// unless the mode is exact or certificates are built) and decides force and form closure; `source`
// names the text in messages. Never throws: every failure is a status. After the call `scratch`
// holds the scene when it was read.
Closure_item closure_item(std::string_view scene_text, std::string_view source, const Closure_batch_options& options,
                          Scene& scratch);

// The C++ batch API: closure_item of every text, in order, on options.jobs threads. Scene i is named
// "scene i+1" in messages (as `batch` names lines).
std::vector<Closure_item> batch_closure(const std::vector<std::string>& scene_texts,
                                        const Closure_batch_options& options = {});

// The same on a stream: next(text) fills the next scene text until it returns false; emit(index,
// item) receives the answers in input order on the calling thread. Memory is bounded by a window of
// 256 scenes per thread, whatever the number of scenes.
void batch_closure(const std::function<bool(std::string& text)>& next,
                   const std::function<void(std::size_t index, const Closure_item& item)>& emit,
                   const Closure_batch_options& options = {});

}  // namespace wrenchkit
