#include "exact/pipeline/batch.h"

#include <utility>

namespace wrenchkit {

namespace {

struct Worker {
  Scene scene;
  std::string source;
};

}  // namespace

void batch_closure(const std::function<bool(std::string&)>& next,
                   const std::function<void(std::size_t, const Closure_item&)>& emit, const Batch_options& options) {
  ordered_map<std::string, Closure_item, Worker>(
      options.jobs, next,
      [&](Worker& w, const std::string& text, Closure_item& out, std::size_t index) {
        w.source = "scene " + std::to_string(index + 1);
        out = answer_closure(text, w.source, options.request, w.scene);
      },
      emit);
}

std::vector<Closure_item> batch_closure(const std::vector<std::string>& scene_texts, const Batch_options& options) {
  std::vector<Closure_item> items(scene_texts.size());
  std::size_t k = 0;
  ordered_map<std::size_t, Closure_item, Worker>(
      options.jobs, [&](std::size_t& i) { return k < scene_texts.size() ? (i = k++, true) : false; },
      [&](Worker& w, std::size_t i, Closure_item& out, std::size_t) {
        w.source = "scene " + std::to_string(i + 1);
        out = answer_closure(scene_texts[i], w.source, options.request, w.scene);
      },
      [&](std::size_t index, Closure_item& item) { items[index] = std::move(item); });
  return items;
}

}  // namespace wrenchkit
