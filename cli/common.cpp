// File I/O and small formatting helpers of the wrenchkit command.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cli/common.h"
#include "exact/io/input_error.h"

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

}  // namespace wrenchkit::cli
