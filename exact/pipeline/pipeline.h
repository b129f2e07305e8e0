// The pipeline: one way from a scene to a checked answer, for every front end (the CLI's commands,
// `wrenchkit batch`, the C++ batch API, the Python bindings).
//
//   request (question, mode, certify, limits)
//     → read the scene (the streaming reader: lazily — certified doubles, rationals on demand — when
//       nothing exact is needed)
//     → decide in the request's mode (core/mode.h; the mode is interpreted here and in the deciding
//       functions, never by a front end)
//     → certify (exact, in integers [FC-5]) and check every certificate with the independent checker of
//       proofs/ (Check::independent; a certificate it rejects is Status::check_failed, always a bug)
//     → an answer value: the verdicts, the certificates' JSON, decided_by and predicate counts, and how it
//       ended (Status) with the reason as data.
//
// Nothing here throws for a scene: a bad scene, an undecided float answer, a rejected certificate and an
// internal error are statuses with a message. Front ends map a status to their own channel once: the CLI to
// an exit code and a stderr line (or a batch error line), Python to an exception. Messages carry no front-end
// advice ("use --mode hybrid" is the CLI's to add). Serialisation is separate (cli/, python/).
#pragma once

#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/mode.h"
#include "exact/io/input_error.h"
#include "exact/io/scene.h"
#include "exact/io/streaming_scene_reader.h"
#include "exact/numbers/limits.h"
#include "exact/numbers/work_budget.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"
#include "exact/statics/generators.h"
#include "proofs/checker/checker.h"

namespace wrenchkit {

// How an answer ended; the CLI's exit code (docs/cli.md) in brackets.
enum class Status {
  answered,        // (0)
  bad_input,       // (2) not a valid scene, or the question does not apply to it: the reader's message
  undecided,       // (3) Mode::float_only could not decide
  check_failed,    // (4) the independent checker rejected one of our certificates: always a bug
  internal_error,  // (70) anything else (out of memory included)
};
int exit_code(Status s);

// Who re-verifies the certificates of an answer.
enum class Check {
  independent,  // the independent checker of proofs/ (the default, and what every front end uses)
  none,         // nobody: for measurements of the certificates' own cost only
};

struct Request {
  Mode mode = Mode::hybrid;
  bool certify = true;  // build the certificates (and check them); false: verdicts only (batch --verdict-only)
  Check check = Check::independent;
  Input_limits limits;
};

// Force and form closure of one scene [FC-1]–[FC-3].
struct Closure_item {
  Status status = Status::answered;
  std::string message;                               // why, unless answered (no front-end advice)
  std::string name;                                  // the scene's "name"
  Closure_answer force, form;                        // answered
  std::string force_certificate, form_certificate;  // answered and certified: certificate_json of each
  Arithmetic decided_by() const { return wrenchkit::decided_by(force.decided_by(), form.decided_by()); }
};

// Equilibrium of the scene's load [EQ-1].
struct Equilibrium_item {
  Status status = Status::answered;
  std::string message;
  std::string name;
  Equilibrium_answer answer;
  std::vector<Contact_force> forces;  // balanced: each contact's force under the certificate's weights
  std::string certificate;  // answered and certified: certificate_json
};

// Reads `text` into `scratch` (reused storage; after the call it holds the scene when it was read) and
// answers the request; `source` names the text in messages. Never throws.
Closure_item answer_closure(std::string_view text, std::string_view source, const Request& request, Scene& scratch);
Equilibrium_item answer_equilibrium(std::string_view text, std::string_view source, const Request& request,
                                    Scene& scratch);

// The same for a scene already read; `text` is a text of it for the checker (the scene's own text or
// write_scene(scene)).
Closure_item answer_closure(const Scene& scene, std::string_view text, const Request& request);
Equilibrium_item answer_equilibrium(const Scene& scene, std::string_view text, const Request& request);

// Thrown inside the engine by a float-only question that cannot decide; guarded() makes it a status.
struct Undecided_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs `decide` under the request's work budget (limits.max_work, exact/numbers/work_budget.h) and turns what it
// throws into a status and a message on `item` (Input_error → bad_input, Undecided_error and Work_exhausted →
// undecided, std::bad_alloc → internal_error "out of memory", any other exception → internal_error): the one place
// where the engine's exceptions become answers.
template <class Item, class F>
void guarded(Item& item, const Input_limits& limits, F&& decide) {
  const auto fail = [&](Status s, std::string m) {
    item.status = s;
    item.message = std::move(m);
  };
  try {
    const Work_scope budget(limits.max_work);
    decide();
  } catch (const Input_error& e) {
    fail(Status::bad_input, e.what());
  } catch (const Undecided_error& e) {
    fail(Status::undecided, e.what());
  } catch (const Work_exhausted& e) {
    fail(Status::undecided, e.what());
  } catch (const std::bad_alloc&) {
    fail(Status::internal_error, "out of memory");
  } catch (const std::exception& e) {
    fail(Status::internal_error, e.what());
  }
}

// The two entry points of a question whose item keeps its own scene (item.scene: labels, support, hold): from the
// scene's text, read eagerly into the item, or from a scene already read (copied in); then `decide(item)`, guarded.
template <class Item, class Decide>
Item answer_into_item(std::string_view text, std::string_view source, const Input_limits& limits, Decide decide) {
  Item item;
  guarded(item, limits, [&] {
    read_scene_into(item.scene, text, limits, source, false);
    decide(item);
  });
  return item;
}
template <class Item, class Decide>
Item answer_into_item(const Scene& scene, const Input_limits& limits, Decide decide) {
  Item item;
  guarded(item, limits, [&] {
    item.scene = scene;
    decide(item);
  });
  return item;
}
// The same, the scene moved in (the array API moves each row's scene in and back out of the item: no copy).
template <class Item, class Decide>
Item answer_into_item(Scene&& scene, const Input_limits& limits, Decide decide) {
  Item item;
  guarded(item, limits, [&] {
    item.scene = std::move(scene);
    decide(item);
  });
  return item;
}

// The independent checker's limits for the request's limits: the same scenes are valid to both.
wrenchkit_checker::Limits checker_limits(const Input_limits& limits);

// The independent checker's verdict on our own certificates of one scene: "" when every one is accepted,
// else the reason (with the rejected certificate). Check::none accepts without looking. The environment
// variable WRENCHKIT_FAULT_INJECTION=corrupt-certificate corrupts the first certificate first (the tests use
// it to prove that a rejection reaches the user as exit 4).
std::string check_certificates(std::string_view scene_text, const std::vector<std::string_view>& certificates,
                               const Request& request);
// The same on an item: a rejection makes it check_failed with the reason (every answer's last step).
// A certificate longer than limits.max_certificate_bytes makes the item undecided instead (the answer's size is
// bounded by default, docs/scene-format.md "Limits"), unchecked.
template <class Item>
void check_into(Item& item, std::string_view scene_text, const std::vector<std::string_view>& certificates,
                const Request& request) {
  for (const std::string_view c : certificates)
    if (c.size() > request.limits.max_certificate_bytes) {
      item.status = Status::undecided;
      item.message = "the answer's certificate would be " + std::to_string(c.size()) +
                     " bytes, more than the limit of " + std::to_string(request.limits.max_certificate_bytes) +
                     " (--max-certificate-size; raise it to have the answer)";
      return;
    }
  std::string why = check_certificates(scene_text, certificates, request);
  if (!why.empty()) item.status = Status::check_failed, item.message = std::move(why);
}

}  // namespace wrenchkit
