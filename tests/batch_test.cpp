// The C++ batch API (exact/pipeline/batch.h): answers in input order on any number of threads, each scene's
// error a value (the message read_scene gives), the same verdicts and certificates as decide_closure,
// bounded memory on a stream, and the ordered parallel map underneath.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact/certificates/certificates.h"
#include "exact/pipeline/batch.h"
#include "exact/io/input_error.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

std::vector<std::string> golden_and_bad() {
  std::vector<std::string> texts;
  for (const std::string& f : test::scene_files("tests/golden")) texts.push_back(test::read_text(f));
  for (const std::string& f : test::scene_files("tests/golden/equilibrium")) texts.push_back(test::read_text(f));
  const std::vector<std::string> bad = {
      "not json", "", R"({"wrenchkit": 1, "contacts": [{"at": [0,0], "normal": [0,0]}]})",
      R"({"wrenchkit": 1, "contacts": [{"at": [0,"1/0"], "normal": [0,1]}]})", R"({"wrenchkit": 2})"};
  for (std::size_t i = 0; i < bad.size(); ++i) texts.insert(texts.begin() + static_cast<std::ptrdiff_t>(5 * i + 2), bad[i]);
  return texts;
}

TEST(BatchClosure, AnswersEveryTextInOrderLikeDecideClosure) {
  const std::vector<std::string> texts = golden_and_bad();
  for (const Mode mode : {Mode::hybrid, Mode::exact}) {
    Batch_options o;
    o.request.mode = mode;  // certificates checked by the independent checker: the default
    o.jobs = 3;
    const std::vector<Closure_item> items = batch_closure(texts, o);
    ASSERT_EQ(items.size(), texts.size());
    int bad = 0;
    for (std::size_t i = 0; i < texts.size(); ++i) {
      SCOPED_TRACE(texts[i].substr(0, 80));
      Scene scene;
      try {
        scene = read_scene(texts[i], Input_limits{}, "scene " + std::to_string(i + 1));
      } catch (const Input_error& e) {
        ++bad;
        EXPECT_EQ(items[i].status, Status::bad_input);
        EXPECT_EQ(items[i].message, e.what());  // read_scene's message, the scene named by its position
        continue;
      }
      ASSERT_EQ(items[i].status, Status::answered) << items[i].message;
      EXPECT_EQ(items[i].name, scene.name);
      for (const Property p : {Property::force_closure, Property::form_closure}) {
        const Closure_answer want = decide_closure(scene, p, mode);
        const Closure_answer& got = p == Property::force_closure ? items[i].force : items[i].form;
        EXPECT_EQ(got.holds, want.holds);
        EXPECT_EQ(got.rank, want.rank);
        EXPECT_EQ(got.generators, want.generators);
        EXPECT_EQ(got.predicates, want.predicates);
        EXPECT_EQ(got.exact_predicates, want.exact_predicates);
        EXPECT_EQ(p == Property::force_closure ? items[i].force_certificate : items[i].form_certificate,
                  certificate_json(want.certificate));
      }
    }
    EXPECT_EQ(bad, 5);
  }
}

TEST(BatchClosure, TheSameAnswersOnOneThreadOrMany) {
  std::vector<std::string> texts;
  for (int k = 0; k < 8; ++k)
    for (const std::string& t : golden_and_bad()) texts.push_back(t);  // > 256 texts: several windows
  ASSERT_GT(texts.size(), 512u);
  Batch_options o;
  o.request.certify = false;  // verdicts only: the lazy reading
  o.jobs = 1;
  const std::vector<Closure_item> one = batch_closure(texts, o);
  for (unsigned jobs : {2u, 5u}) {
    o.jobs = jobs;
    const std::vector<Closure_item> many = batch_closure(texts, o);
    ASSERT_EQ(many.size(), one.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
      EXPECT_EQ(many[i].status, one[i].status) << i;
      EXPECT_EQ(many[i].message, one[i].message) << i;
      EXPECT_EQ(many[i].force.holds, one[i].force.holds) << i;
      EXPECT_EQ(many[i].form.holds, one[i].form.holds) << i;
      EXPECT_EQ(many[i].force.predicates, one[i].force.predicates) << i;
      EXPECT_TRUE(many[i].force_certificate.empty());
    }
  }
  // Verdicts only, the same verdicts as with certificates.
  o.request.certify = true;
  const std::vector<Closure_item> certified = batch_closure(texts, o);
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(certified[i].force.holds, one[i].force.holds);
    EXPECT_EQ(certified[i].form.holds, one[i].form.holds);
    EXPECT_EQ(certified[i].force_certificate.empty(), certified[i].status != Status::answered);
  }
}

TEST(BatchClosure, ErrorsAreValues) {
  Batch_options o;
  o.jobs = 2;
  // --mode float on exactly concurrent normals written with inexact decimals: undecided.
  const std::string tenths = R"({"wrenchkit": 1, "contacts": [
      {"at": [0.1, 0], "normal": [0, 0.1]}, {"at": [0, 0.1], "normal": [0.1, 0]}, {"at": [0.3, 0.3], "normal": [-0.1, -0.1]}]})";
  o.request.mode = Mode::float_only;
  std::vector<Closure_item> items = batch_closure({tenths, "{"}, o);
  EXPECT_EQ(items[0].status, Status::undecided);
  EXPECT_NE(items[0].message.find("could not certify"), std::string::npos);
  EXPECT_EQ(items[1].status, Status::bad_input);
  EXPECT_EQ(items[1].message, "scene 2:1:2: invalid JSON: expected a string key");
  EXPECT_EQ(items[0].message.find("use --mode"), std::string::npos);  // no front end's advice in the engine
  // A certificate the independent checker rejects (corrupted on purpose): check_failed, with its reason;
  // the same scene unharmed: answered.
  o.request.mode = Mode::hybrid;
  setenv("WRENCHKIT_FAULT_INJECTION", "corrupt-certificate", 1);
  items = batch_closure({tenths}, o);
  unsetenv("WRENCHKIT_FAULT_INJECTION");
  EXPECT_EQ(items[0].status, Status::check_failed);
  EXPECT_EQ(items[0].message.rfind("the independent checker rejected our own certificate: ", 0), 0u) << items[0].message;
  EXPECT_NE(items[0].message.find("injected_fault"), std::string::npos);
  o.request.check = Check::none;  // nobody checks: the corruption would pass (measurements only)
  setenv("WRENCHKIT_FAULT_INJECTION", "corrupt-certificate", 1);
  items = batch_closure({tenths}, o);
  unsetenv("WRENCHKIT_FAULT_INJECTION");
  EXPECT_EQ(items[0].status, Status::answered);
  o.request.check = Check::independent;
  items = batch_closure({tenths}, o);
  EXPECT_EQ(items[0].status, Status::answered) << items[0].message;
  EXPECT_FALSE(items[0].force.holds);
  EXPECT_GT(items[0].force.exact_predicates, 0u);  // hybrid went exact where the twin could not decide
}

TEST(BatchClosure, StreamsInOrderWithBoundedMemory) {
  const std::vector<std::string> texts = golden_and_bad();
  const std::size_t n = 3000;
  for (unsigned jobs : {1u, 3u}) {
    Batch_options o;
    o.request.certify = false;
    o.jobs = jobs;
    std::size_t pulled = 0, emitted = 0, most_pending = 0;
    batch_closure(
        [&](std::string& text) {
          if (pulled == n) return false;
          text = texts[pulled++ % texts.size()];
          most_pending = std::max(most_pending, pulled - emitted);
          return true;
        },
        [&](std::size_t index, const Closure_item& item) {
          EXPECT_EQ(index, emitted);
          if (item.message.find("invalid JSON") != std::string::npos) {  // the scene named by its position
            EXPECT_EQ(item.message.rfind("scene " + std::to_string(index + 1) + ":", 0), 0u) << item.message;
          }
          ++emitted;
        },
        o);
    EXPECT_EQ(emitted, n);
    EXPECT_LE(most_pending, 256u * jobs);  // one window: memory does not grow with the stream
  }
}

TEST(OrderedMap, KeepsOrderAndPropagatesTheCallersExceptions) {
  struct Worker {
    int seen = 0;
  };
  for (unsigned jobs : {1u, 2u, 7u}) {
    int next = 0;
    std::vector<long> out;
    std::atomic<int> per_worker_total{0};
    ordered_map<int, long, Worker>(
        jobs, [&](int& x) { return next < 5000 ? (x = next++, true) : false; },
        [&](Worker& w, int x, long& y, std::size_t index) {
          ++w.seen;
          ++per_worker_total;
          y = static_cast<long>(x) * x + static_cast<long>(index);
        },
        [&](std::size_t index, long y) {
          EXPECT_EQ(static_cast<std::size_t>(out.size()), index);
          out.push_back(y);
        },
        16);
    ASSERT_EQ(out.size(), 5000u);
    for (long i = 0; i < 5000; ++i) EXPECT_EQ(out[static_cast<std::size_t>(i)], i * i + i);
    EXPECT_EQ(per_worker_total.load(), 5000);
    // An exception from emit (the caller's side) stops the map and reaches the caller.
    int k = 0;
    EXPECT_THROW((ordered_map<int, int, Worker>(
                     jobs, [&](int& x) { return k < 1000 ? (x = k++, true) : false; },
                     [](Worker&, int x, int& y, std::size_t) { y = x; },
                     [](std::size_t index, int) {
                       if (index == 100) throw std::runtime_error("stop");
                     },
                     8)),
                 std::runtime_error);
  }
}

// [BATCH] A window also closes once its inputs weigh window_bytes: long inputs make it shorter, down to one,
// and the outputs stay in order.
TEST(OrderedMap, AWindowClosesAtItsBytes) {
  struct Worker {};
  for (const std::size_t len : {std::size_t(10), std::size_t(100)}) {
    std::vector<std::string> inputs(20, std::string(len, 'x'));
    inputs[7] = std::string(1000, 'y');  // one long input: a window of its own at most
    std::size_t k = 0;
    std::string trace;  // n: an input read, e: an output emitted
    std::vector<std::size_t> sizes;
    ordered_map<std::string, std::size_t, Worker>(
        1, [&](std::string& x) { return k < inputs.size() ? (x = inputs[k++], trace += 'n', true) : false; },
        [](Worker&, const std::string& x, std::size_t& y, std::size_t) { y = x.size(); },
        [&](std::size_t index, std::size_t y) {
          trace += 'e';
          EXPECT_EQ(index, sizes.size());
          sizes.push_back(y);
        },
        256, 35, [](const std::string& x) { return x.size(); });
    ASSERT_EQ(sizes.size(), inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) EXPECT_EQ(sizes[i], inputs[i].size());
    // len 10: windows of 4 (40 bytes ≥ 35), the long one closing its window; len 100: one input a window.
    if (len == 10) EXPECT_EQ(trace, "nnnneeeennnneeeennnneeee" "nnnneeeennnneeee");
    else
      for (std::size_t i = 0; i + 1 < trace.size(); i += 2) EXPECT_EQ(trace.substr(i, 2), "ne") << trace;
  }
}

}  // namespace
}  // namespace wrenchkit
