// [BATCH] Many scenes at once through the pipeline (exact/pipeline/pipeline.h): answers in input order,
// computed on `jobs` threads (exact/pipeline/ordered_map.h), each scene's failure a status and never an
// exception, memory bounded whatever the number of scenes. The C++ batch API of closure; the CLI's
// `wrenchkit batch COMMAND` runs every command through the same map and pipeline.
//
// Exactness: every verdict is the exact verdict of the scene as written; the speed comes from the
// streaming scene reader (one pass, storage reused per thread, rationals only on demand) and from reusing
// each thread's scratch storage.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "exact/pipeline/ordered_map.h"
#include "exact/pipeline/pipeline.h"

namespace wrenchkit {

struct Batch_options {
  Request request;   // mode, certify, check, limits: as for one scene
  unsigned jobs = 0;  // threads; 0: all cores
};

// answer_closure of every text, in order, on options.jobs threads. Scene i is named "scene i+1" in
// messages (as `batch` names lines).
std::vector<Closure_item> batch_closure(const std::vector<std::string>& scene_texts, const Batch_options& options = {});

// The same on a stream: next(text) fills the next scene text until it returns false; emit(index, item)
// receives the answers in input order on the calling thread. Memory is bounded by a window of 256 scenes
// per thread, whatever the number of scenes.
void batch_closure(const std::function<bool(std::string& text)>& next,
                   const std::function<void(std::size_t index, const Closure_item& item)>& emit,
                   const Batch_options& options = {});

}  // namespace wrenchkit
