// [BATCH] The ordered parallel map under every batch (the CLI's `wrenchkit batch COMMAND`, the C++ batch
// API of exact/pipeline/batch.h, the Python bindings' batch): inputs read on the calling thread, mapped on
// `jobs` threads, outputs emitted in input order; memory bounded by a window, whatever the input's length.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace wrenchkit {

// The number of threads for `jobs` (0: every core the system reports, at least 1).
inline unsigned batch_threads(unsigned jobs) { return jobs ? jobs : std::max(1u, std::thread::hardware_concurrency()); }

// The ordered parallel map. On the calling thread, next(Input&) fills the next input until it returns
// false; work(Worker&, Input&, Output&, index) maps each input (index counts from 0) on `jobs`
// threads (0: all cores), each thread with its own Worker (scratch storage reused from one input to the
// next); on the calling thread again, emit(index, Output&) receives the outputs in input order.
// Inputs are taken in windows of `window_per_thread`·jobs, and a window also closes once the inputs in it
// weigh `window_bytes` or more (weigh(Input&): their bytes; a long input shrinks the window, down to one
// input), so memory stays bounded whatever the number and the size of the inputs; Input and Output objects
// are reused from window to window (assign into them).
// `work` must not throw (turn a per-input error into an Output); next/emit may, and the map then
// stops and rethrows on the calling thread once its threads are idle.
struct Weightless {
  template <class Input>
  std::size_t operator()(const Input&) const {
    return 0;
  }
};

template <class Input, class Output, class Worker, class Next, class Work, class Emit, class Weigh = Weightless>
void ordered_map(unsigned jobs, Next&& next, Work&& work, Emit&& emit, std::size_t window_per_thread = 256,
                 std::size_t window_bytes = static_cast<std::size_t>(-1), Weigh weigh = {}) {
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
      for (std::size_t bytes = 0; count < window && bytes < window_bytes && (more = next(in[count]));)
        bytes += weigh(in[count++]);
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

}  // namespace wrenchkit
