#include "exact/io/suggest.h"

#include <algorithm>
#include <cctype>
#include <cstddef>

namespace wrenchkit {

namespace {

std::string folded(const std::string& s) {
  std::string f;
  f.reserve(s.size());
  for (const char c : s) f += c == '-' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return f;
}

// Optimal string alignment distance (Levenshtein with adjacent transpositions), on bytes.
std::size_t distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

}  // namespace

std::string closest_word(const std::string& word, const std::vector<std::string>& known) {
  constexpr std::size_t kLongest = 64;  // a longer word is no misspelling of a key, command or option
  if (word.size() > kLongest) return "";
  const std::string w = folded(word);
  std::string best;
  std::size_t best_distance = 3;
  for (const std::string& k : known) {
    const std::size_t allowed = std::min(w.size(), k.size()) >= 5 ? 2 : 1;
    const std::size_t d = distance(w, folded(k));
    if (d <= allowed && d < best_distance) best = k, best_distance = d;
  }
  return best;
}

std::string did_you_mean(const std::string& suggestion) {
  return suggestion.empty() ? std::string() : " (did you mean \"" + suggestion + "\"?)";
}

}  // namespace wrenchkit
