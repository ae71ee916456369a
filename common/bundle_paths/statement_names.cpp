#include "bundle_paths/statement_names.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <utility>

#include "bundle_paths/name_index.h"
#include "text/trim.h"

namespace toond::bundle_paths {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bool is_escaped_blank(std::string_view line, std::size_t i) {
  return line[i] == '\\' && i + 1 < line.size() && (line[i + 1] == ' ' || line[i + 1] == '\t');
}

struct Word {
  std::string text;   // with `\ ` already turned into a blank
  std::size_t begin;  // offsets into the line, for rebuilding a name with blanks
  std::size_t end;
};

// Splits on unescaped blanks. Any backslash but `\ ` is kept, to be read
// later as a Windows path separator.
std::vector<Word> words(std::string_view line) {
  std::vector<Word> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    if (i >= line.size()) break;
    Word w{{}, i, i};
    while (i < line.size() && !is_blank(line[i])) {
      if (is_escaped_blank(line, i)) ++i;
      w.text += line[i++];
    }
    w.end = i;
    out.push_back(std::move(w));
  }
  return out;
}

std::string unescape_blanks(std::string_view raw) {
  std::string out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (!is_escaped_blank(raw, i)) out += raw[i];
  }
  return out;
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// How many arguments a texture option takes (the MTL spec's list plus the
// -colorspace and -texres extensions seen in the wild); -1 for -o/-s/-t,
// which take one to three numbers; 0 when `word` is no option at all.
int option_arity(std::string_view word) {
  static constexpr std::pair<std::string_view, int> kOptions[] = {
      {"-blendu", 1}, {"-blendv", 1}, {"-bm", 1},         {"-boost", 1}, {"-cc", 1}, {"-clamp", 1}, {"-imfchan", 1},
      {"-texres", 1}, {"-type", 1},   {"-colorspace", 1}, {"-mm", 2},    {"-o", -1}, {"-s", -1},    {"-t", -1}};
  for (const auto& [name, arity] : kOptions) {
    if (same_ignoring_case(word, name)) return arity;
  }
  return 0;
}

bool is_quoted(std::string_view s) {
  return s.size() >= 2 && (s.front() == '"' || s.front() == '\'') && s.back() == s.front();
}

// The part after the last '/' or '\'.
std::string file_name_of(std::string_view path) {
  const auto slash = path.find_last_of("/\\");
  return std::string(slash == std::string_view::npos ? path : path.substr(slash + 1));
}

}  // namespace

std::vector<std::string> mtllib_names(std::string_view rest_of_line,
                                      const std::function<bool(const std::string&)>& exists) {
  std::vector<std::string> names;
  for (Word& w : words(rest_of_line)) names.push_back(std::move(w.text));
  if (names.size() > 1) {
    std::string whole = unescape_blanks(text::trim(rest_of_line));
    if (exists(whole)) return {std::move(whole)};
  }
  return names;
}

std::vector<TextureName> texture_names(std::string_view rest_of_line) {
  const std::vector<Word> all = words(rest_of_line);
  std::vector<std::size_t> named;  // indices of words that are not options or their arguments
  for (std::size_t i = 0; i < all.size(); ++i) {
    const int arity = option_arity(all[i].text);
    if (arity > 0) {
      i += static_cast<std::size_t>(arity);
    } else if (arity < 0) {
      for (int n = 0; n < 3 && i + 1 < all.size() && is_number(all[i + 1].text); ++n) ++i;
    } else {
      named.push_back(i);
    }
  }
  if (named.empty()) return {};

  std::vector<TextureName> out;
  const Word& last = all[named.back()];
  const bool contiguous = named.back() - named.front() + 1 == named.size();
  if (named.size() > 1 && contiguous) {
    const Word& first = all[named.front()];
    std::string whole = unescape_blanks(rest_of_line.substr(first.begin, last.end - first.begin));
    if (is_quoted(whole)) {
      out.push_back({whole.substr(1, whole.size() - 2)});
    } else {
      out.push_back({std::move(whole)});
      out.push_back({last.text});
    }
  } else {
    out.push_back({is_quoted(last.text) ? last.text.substr(1, last.text.size() - 2) : last.text});
  }

  if (out.front().name.empty()) return {};  // a pair of quotes and nothing in them
  std::string file_name = file_name_of(out.front().name);
  const bool known = std::any_of(out.begin(), out.end(), [&](const TextureName& t) { return t.name == file_name; });
  if (!file_name.empty() && !known) out.push_back({std::move(file_name), true});
  return out;
}

std::vector<TextureName> path_names(std::string_view path) {
  if (path.empty()) return {};
  std::vector<TextureName> names = {{std::string(path), false}};
  std::string file_name = file_name_of(path);
  if (!file_name.empty() && file_name != path) names.push_back({std::move(file_name), true});
  return names;
}

}  // namespace toond::bundle_paths
