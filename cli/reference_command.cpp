// wrenchkit reference: the reference corpus for other implementations (conformance/reference.h), written to
// --out DIR, and its summary.
#include <iostream>
#include <string>

#include "cli/common.h"
#include "conformance/reference.h"

namespace wrenchkit::cli {

int run_reference(const Options& o) {
  const Reference_options& ro = o.reference;
  const std::string& out_dir = o.out_dir;
  if (out_dir.empty()) throw Usage_error("reference needs --out DIR");
  if (const std::string why = corpus_dir_problem(out_dir); !why.empty()) throw Usage_error("--out: " + why);

  const Reference_corpus corpus = answered(build_reference(ro));
  const std::size_t bytes = write_corpus(out_dir, corpus.ids, corpus.items, reference_manifest(ro, corpus.ids.size()));

  const std::size_t certificates = corpus.certificates;
  if (o.json)
    std::cout << json_answer([&](Json_writer& w) {
      w.member("command", "reference").member("out", out_dir).member("scenes", corpus.ids.size());
      w.member("certificates_checked", certificates).member("bytes", bytes);
    }) << "\n";
  else
    std::cout << "wrote " << corpus.ids.size() << " scenes to " << out_dir << "/reference.jsonl (" << bytes
              << " bytes), scenes/, expected.csv, manifest.json\n"
              << "all " << certificates << " certificates accepted by the independent checker (exact arithmetic)\n";
  return kAnswered;
}

}  // namespace wrenchkit::cli
