// The rules for comments in src/: a comment says why in the present tense, so it cites no issue
// number ("issue 15", "issues 11 and 21", "Issue #4"), never the architecture guide outside the
// repository ("ARCHITECTURE §4.7", "../shared/ARCHITECTURE.md"), and carries no dated timing
// history (an arrow between two durations, "87 -> 24.5 ms" or "21.7 → 19.4 ms"; "was 30 ms";
// "from 55 ms to 39 ms"). A number that justifies a design choice points to where it is
// measured: "(measured: docs/decisions.md)". Papers are cited with their section and equation
// ("paper 003 §V Eq. 7"), which no rule here touches.
//
// Only comment text is read — // and /* */ comments — never code, string literals (raw ones
// included) or character literals, so `issue_count - 1` or "issue 5" in a string passes. The lines
// of consecutive comments are read as one text, so a citation broken across two lines ("(issue" at
// the end of one, "15)" at the start of the next) is still found, at the line where it starts.
// Header-only, so that it builds with the layering test alone.
#pragma once

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace relight::comment_rules {

// The text of one comment on one source line (without its // or the * that opens a line of a
// block comment), `line` counted from 1.
struct CommentLine {
  std::size_t line = 0;
  std::string text;
};

namespace detail {

inline bool is_identifier_char(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

// Whether the ' at `at` separates digits of a number (32'768, 0xFF'FF) rather than opening a
// character literal (L'x', u8'x'): the token it ends starts with a digit.
inline bool is_digit_separator(std::string_view s, std::size_t at) {
  std::size_t start = at;
  while (start > 0 &&
         (is_identifier_char(s[start - 1]) || s[start - 1] == '\'' || s[start - 1] == '.')) {
    --start;
  }
  return start < at && s[start] >= '0' && s[start] <= '9';
}

// Whether a raw string literal R"delim( starts at `at` (the R), with or without an encoding
// prefix (u8R, uR, UR, LR) before it.
inline bool is_raw_string_start(std::string_view s, std::size_t at) {
  if (s[at] != 'R' || at + 1 >= s.size() || s[at + 1] != '"') return false;
  std::size_t start = at;
  while (start > 0 && is_identifier_char(s[start - 1])) --start;
  const std::string_view prefix = s.substr(start, at - start);
  return prefix.empty() || prefix == "u8" || prefix == "u" || prefix == "U" || prefix == "L";
}

// A comment fragment's text with its leading slashes or asterisks and the space after them gone.
inline std::string strip_marker(std::string_view text) {
  std::size_t at = 0;
  while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
  while (at < text.size() && (text[at] == '/' || text[at] == '*' || text[at] == '!')) ++at;
  while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
  std::size_t end = text.size();
  if (end >= at + 2 && text.substr(end - 2, 2) == "*/") end -= 2;
  while (end > at && (text[end - 1] == ' ' || text[end - 1] == '\t' || text[end - 1] == '\r')) {
    --end;
  }
  return std::string(text.substr(at, end - at));
}

}  // namespace detail

// Every comment of C++ source text, one entry per source line it covers (a line holding two
// comments gives two entries), in order.
inline std::vector<CommentLine> comment_lines(std::string_view s) {
  std::vector<CommentLine> out;
  std::size_t line = 1;
  std::size_t i = 0;
  const std::size_t n = s.size();
  while (i < n) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (c == '/' && i + 1 < n && s[i + 1] == '/') {
      std::size_t end = s.find('\n', i);
      if (end == std::string_view::npos) end = n;
      out.push_back({line, detail::strip_marker(s.substr(i, end - i))});
      i = end;
    } else if (c == '/' && i + 1 < n && s[i + 1] == '*') {
      std::size_t end = s.find("*/", i + 2);
      end = end == std::string_view::npos ? n : end + 2;
      std::size_t from = i;
      while (from < end) {
        std::size_t eol = s.find('\n', from);
        if (eol == std::string_view::npos || eol > end) eol = end;
        out.push_back({line, detail::strip_marker(s.substr(from, eol - from))});
        if (eol < end) ++line;
        from = eol + 1;
      }
      i = end;
    } else if (detail::is_raw_string_start(s, i)) {
      const std::size_t open = s.find('(', i + 2);
      if (open == std::string_view::npos) return out;
      std::string close(1, ')');
      close.append(s.substr(i + 2, open - i - 2));
      close.push_back('"');
      std::size_t end = s.find(close, open + 1);
      end = end == std::string_view::npos ? n : end + close.size();
      line += static_cast<std::size_t>(std::count(s.begin() + i, s.begin() + end, '\n'));
      i = end;
    } else if (c == '"' || (c == '\'' && !detail::is_digit_separator(s, i))) {
      ++i;
      while (i < n && s[i] != c && s[i] != '\n') {
        if (s[i] == '\\' && i + 1 < n) {
          if (s[i + 1] == '\n') ++line;
          ++i;
        }
        ++i;
      }
      if (i < n && s[i] == c) ++i;
    } else {
      ++i;
    }
  }
  return out;
}

// What is wrong with comment text, one "LINE: reason" each: `comments` as comment_lines gives
// them. Comments on consecutive lines are read as one text.
inline std::vector<std::string> comment_breaches(const std::vector<CommentLine>& comments) {
  struct Rule {
    std::regex pattern;
    const char* reason;
    bool (*worth_a_look)(const std::string&);
  };
  static const std::string kDuration =
      R"([0-9]+(?:\.[0-9]+)?(?:\s*(?:-|–)\s*[0-9]+(?:\.[0-9]+)?)?)";
  static const std::string kUnit = R"((?:ms|µs|us|ns|s|min)\b)";
  static const std::vector<Rule> rules = [] {
    std::vector<Rule> r;
    r.push_back({std::regex(R"(\bissues?\s*#?\s*[0-9]+)", std::regex::icase),
                 "cites an issue number", [](const std::string& t) {
                   return t.find("ssue") != std::string::npos ||
                          t.find("SSUE") != std::string::npos;
                 }});
    r.push_back({std::regex("ARCHITECTURE"),
                 "cites ARCHITECTURE, a document outside the repository",
                 [](const std::string& t) { return t.find("ARCHITECTURE") != std::string::npos; }});
    r.push_back({std::regex(kDuration + R"(\s*)" + "(?:" + kUnit + R"(\s*)?(?:->|→)\s*)" +
                            kDuration + R"(\s*)" + kUnit),
                 "carries a dated timing (a duration then another)", [](const std::string& t) {
                   return t.find("->") != std::string::npos || t.find("→") != std::string::npos;
                 }});
    r.push_back({std::regex(R"(\bwas\s+)" + kDuration + R"(\s*)" + kUnit),
                 "carries a dated timing (what a duration was)",
                 [](const std::string& t) { return t.find("was") != std::string::npos; }});
    r.push_back({std::regex(R"(\bfrom\s+)" + kDuration + R"(\s*)" + kUnit + R"(\s+to\s+)" +
                            kDuration + R"(\s*)" + kUnit),
                 "carries a dated timing (a duration then another)",
                 [](const std::string& t) { return t.find("from") != std::string::npos; }});
    return r;
  }();

  std::vector<std::string> out;
  std::size_t first = 0;
  while (first < comments.size()) {
    // A run of comments on consecutive lines, joined with spaces; starts[k] is where the k-th
    // comment of the run begins in the joined text.
    std::size_t last = first;
    while (last + 1 < comments.size() && comments[last + 1].line <= comments[last].line + 1) {
      ++last;
    }
    std::string text;
    std::vector<std::size_t> starts;
    for (std::size_t k = first; k <= last; ++k) {
      starts.push_back(text.size());
      text += comments[k].text;
      text += ' ';
    }
    for (const Rule& rule : rules) {
      if (!rule.worth_a_look(text)) continue;
      for (auto m = std::sregex_iterator(text.begin(), text.end(), rule.pattern);
           m != std::sregex_iterator(); ++m) {
        const auto at = static_cast<std::size_t>(m->position(0));
        const std::size_t k =
            static_cast<std::size_t>(std::upper_bound(starts.begin(), starts.end(), at) -
                                     starts.begin()) -
            1;
        out.push_back(std::to_string(comments[first + k].line) + ": " + rule.reason + " (\"" +
                      m->str(0) + "\"): " + comments[first + k].text);
      }
    }
    first = last + 1;
  }
  std::stable_sort(out.begin(), out.end(), [](const std::string& a, const std::string& b) {
    return std::stoul(a) < std::stoul(b);
  });
  return out;
}

// Every breach of the rules in the .h and .cpp files under `src_root`, in path order, one line
// each: "src/FILE:LINE: reason (\"what\"): the comment's line", FILE relative to `src_root`.
inline std::vector<std::string> comment_rule_violations(const std::filesystem::path& src_root) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(src_root)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".h" || ext == ".cpp")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<std::string> out;
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const std::string name = "src/" + file.lexically_relative(src_root).generic_string();
    for (const std::string& breach : comment_breaches(comment_lines(text.str()))) {
      out.push_back(name + ":" + breach);
    }
  }
  return out;
}

}  // namespace relight::comment_rules
