#include "exact/pipeline/batch.h"

#include <new>
#include <utility>

#include "exact/io/input_error.h"
#include "exact/io/streaming_scene_reader.h"

namespace wrenchkit {

Closure_item closure_item(std::string_view scene_text, std::string_view source, const Closure_batch_options& o,
                          Scene& scratch) {
  Closure_item item;
  try {
    // Lazily: certified doubles from the digits and rationals only where an exact predicate needs them.
    // Certificates need every contact's rationals under both readings, so they read eagerly.
    const bool lazy = o.mode != Mode::exact && !o.certify;
    read_scene_into(scratch, scene_text, o.limits, source, lazy);
    item.name = scratch.name;
    item.force = decide_closure(scratch, Property::force_closure, o.mode, o.certify);
    item.form = decide_closure(scratch, Property::form_closure, o.mode, o.certify);
    if (!item.force.decided || !item.form.decided) {
      item.status = Batch_status::undecided;
      item.message = std::string("the float twin could not certify ") +
                     (!item.force.decided ? (!item.form.decided ? "force or form closure" : "force closure")
                                          : "form closure") +
                     " of this scene (a predicate is within its error bound of zero); use --mode hybrid or exact";
      return item;
    }
    if (!o.certify) return item;
    item.force_certificate = certificate_json(item.force.certificate);
    item.form_certificate = certificate_json(item.form.certificate);
    if (o.check) {
      const std::string why = o.check(scene_text, {item.force_certificate, item.form_certificate});
      if (!why.empty()) {
        item.status = Batch_status::check_failed;
        item.message = why;
      }
    }
  } catch (const Input_error& e) {
    item.status = Batch_status::bad_input;
    item.message = e.what();
  } catch (const std::bad_alloc&) {
    item.status = Batch_status::internal_error;
    item.message = "out of memory";
  } catch (const std::exception& e) {
    item.status = Batch_status::internal_error;
    item.message = e.what();
  }
  return item;
}

namespace {

struct Worker {
  Scene scene;
  std::string source;
};

}  // namespace

void batch_closure(const std::function<bool(std::string&)>& next,
                   const std::function<void(std::size_t, const Closure_item&)>& emit,
                   const Closure_batch_options& options) {
  ordered_map<std::string, Closure_item, Worker>(
      options.jobs, next,
      [&](Worker& w, const std::string& text, Closure_item& out, std::size_t index) {
        w.source = "scene " + std::to_string(index + 1);
        out = closure_item(text, w.source, options, w.scene);
      },
      emit);
}

std::vector<Closure_item> batch_closure(const std::vector<std::string>& scene_texts,
                                        const Closure_batch_options& options) {
  std::vector<Closure_item> items(scene_texts.size());
  std::size_t k = 0;
  ordered_map<std::size_t, Closure_item, Worker>(
      options.jobs, [&](std::size_t& i) { return k < scene_texts.size() ? (i = k++, true) : false; },
      [&](Worker& w, std::size_t i, Closure_item& out, std::size_t) {
        w.source = "scene " + std::to_string(i + 1);
        out = closure_item(scene_texts[i], w.source, options, w.scene);
      },
      [&](std::size_t index, Closure_item& item) { items[index] = std::move(item); });
  return items;
}

}  // namespace wrenchkit
