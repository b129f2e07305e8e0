// Options, file I/O and small formatting helpers of the wrenchkit command.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <iostream>
#include <string>
#include <vector>

#include "cli/common.h"
#include "exact/io/input_error.h"

namespace wrenchkit::cli {

namespace {

std::size_t parse_count(const std::string& opt, const std::string& v) {
  if (v.empty() || v.size() > 18 || v.find_first_not_of("0123456789") != std::string::npos)
    throw Usage_error(opt + ": \"" + v + "\" is not a non-negative integer");
  return std::stoull(v);
}

}  // namespace

Options parse_options(int argc, char** argv, int first) {
  Options o;
  for (int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Usage_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--json") o.json = true;
    else if (a == "--help" || a == "-h") o.help = true;
    else if (a == "--mode") o.mode = value();
    else if (a == "--verdict-only") o.verdict_only = true;
    else if (a == "--jobs") {
      const std::size_t j = parse_count(a, value());
      if (j < 1 || j > 1024) throw Usage_error("--jobs: must be between 1 and 1024");
      o.jobs = static_cast<unsigned>(j);
    }
    else if (a == "--certificate") o.certificate_file = value();
    else if (a == "--form-certificate") o.form_certificate_file = value();
    else if (a == "--max-digits") o.limits.max_digits = parse_count(a, value());
    else if (a == "--max-exponent") o.limits.max_exponent = static_cast<long>(parse_count(a, value()));
    else if (a == "--max-file-size") o.limits.max_file_bytes = parse_count(a, value());
    else if (a == "--max-contacts") o.limits.max_contacts = parse_count(a, value());
    else if (a == "--list") o.values[a];
    else if (a == "--resultant" || a == "--center" || a == "--sense" || a == "--direction" ||
             a == "--twist" || a == "--what" || a == "-o" || a == "--output" || a == "--sides" ||
             a == "--tolerance" || a == "--load" || a == "--off" || a == "--obj" || a == "--svg") {
      std::string& slot = o.values[a == "-o" ? "--output" : a];
      if (!slot.empty()) throw Usage_error(a + " given twice");
      slot = value();
      if (slot.empty()) throw Usage_error(a + ": empty value");
    }
    else if (a.size() > 1 && a[0] == '-' && a != "-") throw Usage_error("unknown option " + a);
    else o.positional.push_back(a);
  }
  if (o.mode != "exact" && o.mode != "hybrid" && o.mode != "float")
    throw Usage_error("--mode: \"" + o.mode + "\" is not one of exact, hybrid, float");
  return o;
}

std::vector<Rational> parse_vector(const Options& o, const std::string& option, std::size_t n) {
  const std::string& text = o.values.at(option);
  std::vector<Rational> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    std::string why;
    const std::optional<Rational> q = parse_rational(part, false, o.limits, why);
    if (!q) throw Usage_error(option + ": \"" + part + "\" " + why);
    out.push_back(*q);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (out.size() != n)
    throw Usage_error(option + ": \"" + text + "\" needs " + std::to_string(n) + " comma-separated numbers");
  return out;
}

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

wrenchkit_checker::Limits checker_limits(const Input_limits& l) {
  wrenchkit_checker::Limits c;
  c.max_digits = l.max_digits;
  c.max_exponent = l.max_exponent;
  c.max_depth = l.max_depth;
  c.max_contacts = l.max_contacts;
  return c;
}

std::string human_number(const Rational& q) {
  std::string t = to_string(q);
  if (t.size() <= 24) return t;
  char b[40];
  std::snprintf(b, sizeof b, "~%.12g", q.get_d());
  return b;
}

std::string vec_text(const std::array<Rational, 3>& v) {
  return "(" + to_string(v[0]) + ", " + to_string(v[1]) + ", " + to_string(v[2]) + ")";
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
  r.mode = mode_of(o.mode);
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
  return s == Status::undecided ? message + "; use --mode hybrid or exact" : message;
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

Mode mode_of(const std::string& m) {
  return m == "exact" ? Mode::exact : (m == "float" ? Mode::float_only : Mode::hybrid);
}

}  // namespace wrenchkit::cli
