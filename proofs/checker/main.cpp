// proofs/checker/main.cpp - wrenchkit-check SCENE.json CERT.json [--json]
//
// Exit codes (proofs/certificate-format.md §4): 0 accepted, 1 rejected, 2 bad scene, unreadable
// file or usage error (one line on standard error, starting "wrenchkit-check: error: ").
#include <gmp.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "proofs/checker/checker.h"
#include "proofs/checker/json.h"  // escape()

namespace {

constexpr std::size_t max_file_size = 64u << 20;  // 64 MiB, as docs/scene-format.md

const char* const usage =
    "usage: wrenchkit-check SCENE.json CERT.json [--json]\n"
    "\n"
    "Checks that the certificate CERT.json (proofs/certificate-format.md, version 1) proves its claim\n"
    "for the scene SCENE.json (docs/scene-format.md). Either file may be \"-\" for standard input,\n"
    "but not both. Files are limited to 64 MiB.\n"
    "\n"
    "  --json   print {\"accepted\": true|false, \"reason\": \"...\"} instead of a line of text\n"
    "  --help   print this help\n"
    "\n"
    "Prints \"accepted\" (exit 0) or \"rejected: REASON\" (exit 1). Exit 2: the scene is not a valid\n"
    "scene, a file cannot be read, or the command line is wrong.\n";

int error(const std::string& message) {
  std::cerr << "wrenchkit-check: error: " << message << "\n";
  return 2;
}

// Reads the whole file (or standard input for "-") into `out`, refusing more than max_file_size.
bool read_file(const std::string& path, std::string& out, std::string& why) {
  const bool in = path == "-";
  std::FILE* f = in ? stdin : std::fopen(path.c_str(), "rb");
  if (!f) {
    why = "cannot open: " + std::string(std::strerror(errno));
    return false;
  }
  char buffer[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0 && out.size() <= max_file_size) out.append(buffer, n);
  const int err = std::ferror(f) ? errno : 0;
  if (!in) std::fclose(f);
  if (err)
    why = "cannot read: " + std::string(std::strerror(err));
  else if (out.size() > max_file_size)
    why = "larger than 64 MiB";
  return why.empty();
}

// GMP's allocation failures as std::bad_alloc (check() reports them), not GMP's abort.
void* allocate(std::size_t n) {
  void* p = std::malloc(n);
  if (!p) throw std::bad_alloc();
  return p;
}
void* reallocate(void* p, std::size_t, std::size_t n) {
  void* q = std::realloc(p, n);
  if (!q) throw std::bad_alloc();
  return q;
}
void release(void* p, std::size_t) { std::free(p); }

}  // namespace

int main(int argc, char** argv) {
  mp_set_memory_functions(allocate, reallocate, release);
  std::vector<std::string> files;
  bool json = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << usage;
      return 0;
    }
    if (arg == "--json")
      json = true;
    else if (arg.size() > 1 && arg[0] == '-')
      return error("unknown option " + arg + " (see --help)");
    else
      files.push_back(arg);
  }
  if (files.size() != 2) return error("expected SCENE.json and CERT.json (see --help)");
  if (files[0] == "-" && files[1] == "-") return error("SCENE and CERT cannot both be standard input");

  std::string text[2];
  for (int k = 0; k < 2; ++k) {
    std::string why;
    if (!read_file(files[k], text[k], why)) return error((files[k] == "-" ? "<stdin>" : files[k]) + ": " + why);
  }

  const wrenchkit_checker::Result result = wrenchkit_checker::check(text[0], text[1]);
  if (result.outcome == wrenchkit_checker::Outcome::bad_scene) {
    // "scene.json:3:17: invalid JSON: ..." or "scene.json: contacts[2].normal: zero vector"
    const std::string& m = result.message;
    const bool position = !m.empty() && m[0] >= '0' && m[0] <= '9';
    return error((files[0] == "-" ? "<stdin>" : files[0]) + (position ? ":" : ": ") + m);
  }
  const bool accepted = result.outcome == wrenchkit_checker::Outcome::accepted;
  if (json)
    std::cout << "{\"accepted\": " << (accepted ? "true" : "false")
              << ", \"reason\": " << wrenchkit_checker::detail::escape(result.message) << "}\n";
  else
    std::cout << (accepted ? "accepted" : "rejected: " + result.message) << "\n";
  return accepted ? 0 : 1;
}
