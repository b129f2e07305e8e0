// File I/O and small formatting helpers of the wrenchkit command.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/common.h"
#include "cli/float_json.h"
#include "exact/io/input_error.h"
#include "exact/numbers/decimal.h"
#include "exact/numbers/vectors.h"

namespace wrenchkit::cli {

std::string read_input(const std::string& path, std::size_t limit) {
  std::istream* in = &std::cin;
  std::ifstream file;
  if (path != "-") {
    file.open(path, std::ios::binary);
    if (!file) throw Input_error(path + ": cannot open (" + std::strerror(errno) + ")");
    in = &file;
  }
  std::string data;
  char buf[1 << 16];
  while (*in) {
    in->read(buf, sizeof buf);
    data.append(buf, static_cast<std::size_t>(in->gcount()));
    if (data.size() > limit)
      throw Input_error(path + ": larger than the size limit of " + std::to_string(limit) +
                        " bytes (--max-file-size)");
  }
  if (in->bad()) throw Input_error(path + ": read error");
  return data;
}

void write_file(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp-wrenchkit";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Input_error(path + ": cannot write (" + std::strerror(errno) + ")");
    out << text;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw Input_error(path + ": write failed");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Input_error(path + ": cannot write (" + std::strerror(errno) + ")");
  }
}

std::string human_number(const Rational& q) {
  std::string t = to_string(q);
  if (t.size() <= 24) return t;
  return "~" + decimal_text(q, 12);
}

std::string number_text(const Rational& q) {
  std::string t = human_number(q);
  if (q.get_den() == 1 || t[0] == '~') return t;  // an integer, or already a decimal
  return t + " (≈ " + decimal_text(q) + ")";
}

namespace {
// " ≈ (d1, d2, …)" when an entry of v is shown as a fraction (not an integer, not already "~" and its decimal), else "".
std::string approx_suffix(const std::vector<Rational>& v) {
  bool fractions = false;
  for (const Rational& x : v) fractions = fractions || (x.get_den() != 1 && human_number(x)[0] != '~');
  if (!fractions) return "";
  std::string approx = " ≈ (";
  for (std::size_t i = 0; i < v.size(); ++i) approx += (i ? ", " : "") + decimal_text(v[i]);
  return approx + ")";
}
}  // namespace

std::string vec_text(const std::vector<Rational>& v) {
  std::string exact = "(";
  for (std::size_t i = 0; i < v.size(); ++i) exact += (i ? ", " : "") + human_number(v[i]);
  return exact + ")" + approx_suffix(v);
}
std::string vec_text(const Vec3q& v) { return vec_text(std::vector<Rational>(v.begin(), v.end())); }
std::string vec_text(const Vec2& p) { return vec_text(std::vector<Rational>{p.x, p.y}); }
std::string twist_text(const Vec3q& t) { return vec_text(primitive_vec(t)); }
std::string motion_text(const Vec3q& t) {
  const std::string words = motion_words(t);
  if (t[2] == 0) return words;  // a translation: its direction in primitive integers
  // "a … rotation about " from motion_words, the centre as vec_text writes a point.
  return words.substr(0, words.find(" about (") + 7) + vec_text(Vec2{Rational(-t[1] / t[2]), Rational(t[0] / t[2])});
}

void approx_number(Json_writer& w, const Rational& q) {
  const std::optional<double> d = nearest_double(q);
  w.raw(d ? float_number(*d) : decimal_text(q, 17));
}

void write_approx(Json_writer& w, const std::string& key, const std::vector<Rational>& v) {
  w.key(key + "_approx").array();
  for (const Rational& x : v) approx_number(w, x);
  w.end_array();
}

std::string frictionless_note(const Scene& scene) {
  std::string which;
  std::size_t n = 0;
  for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
    const Contact& c = scene.contacts[i];
    if (c.kind != Contact::Kind::point || c.mu_given) continue;
    if (++n <= 6) which += (which.empty() ? "c" : ", c") + std::to_string(i) + (c.name.empty() ? "" : " (" + c.name + ")");
  }
  if (n == 0) return "";
  if (n > 6) which += " and " + std::to_string(n - 6) + " more";
  return "note: " + which + (n == 1 ? " has" : " have") + " no \"mu\": frictionless (write \"mu\" on a contact to give "
         "it friction)\n";
}

std::string ask_support_text() {
  return "to ask: --load fx,fy,m (does the load stick, is it impending, or does it slide?), --twist vx,vy,w (the "
         "friction load of a motion and its power), --list or --svg FILE (the limit surface's polytopes), or 'wrenchkit "
         "hold' with contacts and a load\n";
}

std::string contact_forces_text(const std::vector<Contact_force>& forces) {
  std::string s;
  for (const Contact_force& f : forces) {
    if (!s.empty()) s += "; ";
    s += "c" + std::to_string(f.contact) + (f.name.empty() ? "" : " (" + f.name + ")") + " " +
         (f.point ? vec_text(std::vector<Rational>{f.wrench[0], f.wrench[1]}) : "the wrench " + vec_text(f.wrench));
  }
  return s;
}

void write_forces(Json_writer& w, const std::vector<Contact_force>& forces) {
  w.key("forces").array();
  for (const Contact_force& f : forces) {
    w.object().member("contact", f.contact).member("name", f.name);
    w.key("force").array().rational(f.wrench[0]).rational(f.wrench[1]).end_array();
    write_approx(w, "force", {f.wrench[0], f.wrench[1]});
    w.end_object();
  }
  w.end_array();
}

int write_answer(const Options& o, const std::function<void(Json_writer&)>& json,
                 const std::function<std::string()>& text, bool undecided) {
  if (o.json) std::cout << json_answer(json, 4096) << "\n";
  else std::cout << text();
  return undecided ? kUndecided : kAnswered;
}

std::string undecided_advice(Mode mode) { return mode == Mode::float_only ? "; use --mode hybrid or exact" : ""; }

std::string scene_line(const Scene& scene, const std::string& source) {
  std::string s = "scene: " + (scene.name.empty() ? source : scene.name) + "\n";
  for (const std::string& w : scene.warnings) s += "warning: " + w.substr(0, w.find("; or pass --lenient")) + " (kept: --lenient)\n";
  return s;
}

std::string region_sentence(const std::string& shape, const std::vector<std::string>& v,
                            const std::vector<std::string>& d) {
  const auto list = [](const std::vector<std::string>& x) {
    std::string s;
    for (std::size_t i = 0; i < x.size(); ++i) s += (i ? ", " : "") + x[i];
    return s;
  };
  if (shape == "empty") return "empty";
  if (shape == "point") return "the single point " + v[0];
  if (shape == "segment") return "the segment " + list(v);
  if (shape == "polygon") return "the polygon " + list(v) + " (counter-clockwise)";
  if (shape == "ray") return "the ray from " + v[0] + " toward " + d[0];
  if (shape == "wedge") return "the wedge at " + v[0] + " between directions " + d[0] + " and " + d[1];
  if (shape == "unbounded polygon")
    return "the unbounded polygon with corners " + list(v) + ", running off toward " + list(d);
  if (shape == "line") return "the line through " + v[0] + " along " + d[0];
  if (shape == "strip") return "the strip between the lines through " + v[0] + " and " + v[1] + " along " + d[0];
  if (shape == "half-plane")
    return "the half-plane bounded by the line through " + v[0] + " along " + d[0] + ", on the side of " + d[1];
  if (shape == "plane") return "the whole plane";
  return "?";
}

Request request_of(const Options& o) {
  Request r;
  r.mode = o.mode;
  r.certify = !o.verdict_only;
  r.limits = o.limits;
  return r;
}

Ended failure_of(std::exception_ptr e) {
  try {
    std::rethrow_exception(e);
  } catch (const Failure& f) {
    return {f.status, f.what()};
  } catch (const Usage_error& f) {
    return {Status::bad_input, f.what(), true};
  } catch (const Input_error& f) {
    return {Status::bad_input, f.what()};
  } catch (const Undecided& f) {
    return {Status::undecided, f.what()};
  } catch (const Self_check_failure& f) {
    return {Status::check_failed, f.what()};
  } catch (const std::bad_alloc&) {
    return {Status::internal_error, "out of memory"};
  } catch (const std::exception& f) {
    return {Status::internal_error, f.what()};
  }
}

std::string cli_message(Status s, const std::string& message) {
  // An undecided status is the float mode's, or a budget's (the work, the certificate's size: it names its option).
  return s == Status::undecided && message.find("(--max-") == std::string::npos
             ? message + undecided_advice(Mode::float_only)
             : message;
}

int report(const Ended& e) {
  const char* prefix = "wrenchkit: internal error (please report): ";
  switch (e.status) {
    case Status::answered: return kAnswered;
    case Status::bad_input: prefix = e.usage ? "wrenchkit: usage error: " : "wrenchkit: error: "; break;
    case Status::undecided: prefix = "wrenchkit: undecided: "; break;
    case Status::check_failed: break;
    case Status::internal_error:
      if (e.message == "out of memory") prefix = "wrenchkit: internal error: ";
      break;
  }
  std::cerr << prefix << e.message << "\n";
  return exit_code(e.status);
}

}  // namespace wrenchkit::cli
