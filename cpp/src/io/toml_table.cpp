#include "io/toml_table.hpp"

#include <sstream>

namespace hinf::detail {

namespace {

// toml++ makes a table of each part of a dotted key (a.b.c = 1, [a.b.c]), and builds and frees
// them recursively: a key of some hundred thousand parts overflows the stack. Scenario keys
// have at most four parts; more than kMaxKeyParts are refused before parsing. (Arrays and
// inline tables are nested at most TOML_MAX_NESTED_VALUES deep: toml++ refuses more.)
constexpr int kMaxKeyParts = 16;

bool bare_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

// The index just past the TOML string that starts at text[i] (basic or literal, single- or
// multi-line), counting the line breaks inside it. An unterminated string ends at the end of
// its line (single-line) or of the text (multi-line); toml++ reports it.
std::size_t skip_string(const std::string& text, std::size_t i, long& line) {
  const char quote = text[i];
  const std::string triple(3, quote);
  const bool multiline = text.compare(i, 3, triple) == 0;
  i += multiline ? 3 : 1;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\\' && quote == '"') {
      if (i + 1 < text.size() && text[i + 1] == '\n') ++line;
      i += 2;
    } else if (multiline && text.compare(i, 3, triple) == 0) {
      i += 3;
      while (i < text.size() && text[i] == quote) ++i;  // up to two quotes may end the content
      return i;
    } else if (!multiline && c == quote) {
      return i + 1;
    } else if (c == '\n') {
      if (!multiline) return i;
      ++line;
      ++i;
    } else {
      ++i;
    }
  }
  return i;
}

// Refuses a run of more than kMaxKeyParts parts joined by dots (bare words or strings), outside
// strings and comments. Numbers and dates have at most two such parts ("1.5").
void check_key_parts(const std::string& text, const std::string& source) {
  long line = 1;
  int parts = 0;  // parts of the dotted run being read: "a.b.c" has 3
  bool after_dot = false;
  std::size_t i = 0, run_start = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (bare_key_char(c) || c == '"' || c == '\'') {
      if (!after_dot) run_start = i;
      if (bare_key_char(c)) {
        while (i < text.size() && bare_key_char(text[i])) ++i;
      } else {
        i = skip_string(text, i, line);
      }
      parts = after_dot ? parts + 1 : 1;
      after_dot = false;
      if (parts > kMaxKeyParts)
        throw InputError(str_cat(source, ":", line, ": invalid TOML: the key '", text.substr(run_start, 40),
                                 "...' has more than ", kMaxKeyParts,
                                 " dotted parts (tables nested too deeply for a scenario)"));
    } else if (c == ' ' || c == '\t') {
      ++i;
    } else if (c == '.' && parts > 0 && !after_dot) {
      after_dot = true;
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else {
      if (c == '\n') ++line;
      parts = 0;
      after_dot = false;
      ++i;
    }
  }
}

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// For messages: the key whose value holds the byte at `offset` ("[measurement] seed"), or ""
// when `offset` is not inside a value. The value of the last '=' before `offset` holds it
// unless a line break comes after that value's arrays and inline tables have all closed.
// Strings and comments are not told apart: this only names, it decides nothing.
std::string key_at(const std::string& text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const std::size_t equals = offset == 0 ? std::string::npos : text.rfind('=', offset - 1);
  if (equals == std::string::npos) return "";
  int open = 0;
  for (std::size_t i = equals + 1; i < offset; ++i) {
    if (text[i] == '[' || text[i] == '{') ++open;
    if (text[i] == ']' || text[i] == '}') --open;
    if (text[i] == '\n' && open <= 0) return "";
  }
  // The key: from the start of its line, or of its place in an inline table, to the '='.
  const std::size_t before = equals == 0 ? std::string::npos : text.find_last_of("\n{,", equals - 1);
  const std::size_t key_start = before == std::string::npos ? 0 : before + 1;
  const std::string key = trim(text.substr(key_start, equals - key_start));
  if (key.empty()) return "";
  // The table: the last header line ("[name]" or "[[name]]") above the key.
  for (std::size_t end = key_start; end > 0;) {
    const std::size_t newline = text.rfind('\n', end - 1);
    const std::size_t start = newline == std::string::npos ? 0 : newline + 1;
    const std::string line = trim(text.substr(start, end - start));
    if (!line.empty() && line[0] == '[') {
      const std::size_t close = line.rfind(']');
      return (close == std::string::npos ? line : line.substr(0, close + 1)) + " " + key;
    }
    if (newline == std::string::npos) break;
    end = newline;
  }
  return "top level " + key;
}

// The byte offset of a 1-based line and column (toml++ counts columns in code points: on a line
// with non-ASCII text before the position the offset is a little early).
std::size_t offset_of(const std::string& text, long line, long column) {
  std::size_t offset = 0;
  for (long l = 1; l < line; ++l) {
    const std::size_t next = text.find('\n', offset);
    if (next == std::string::npos) return text.size();
    offset = next + 1;
  }
  return std::min(text.size(), offset + static_cast<std::size_t>(std::max(0L, column - 1)));
}

}  // namespace

toml::table parse_toml(const std::string& text, const std::string& source) {
  check_key_parts(text, source);
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const long line = static_cast<long>(e.source().begin.line);
    const long column = static_cast<long>(e.source().begin.column);
    const std::string key = key_at(text, offset_of(text, line, column));
    throw InputError(str_cat(source, ":", line, ":", column, ": invalid TOML", key.empty() ? "" : " in " + key,
                             ": ", e.description()));
  }
}

toml::array vector_toml(const Vec& v) {
  toml::array a;
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

toml::array matrix_toml(const Mat& M) {
  toml::array rows;
  for (Eigen::Index i = 0; i < M.rows(); ++i) rows.push_back(vector_toml(M.row(i).transpose()));
  return rows;
}

// The TOML form of a signal: a number for a constant, a table otherwise.
void insert_signal(toml::table& table, const std::string& key, const Signal& signal) {
  if (signal.is_constant()) {
    table.insert(key, signal.offset());
    return;
  }
  toml::table spec;
  if (signal.is_table()) {
    toml::array t, value;
    for (double x : signal.table_t()) t.push_back(x);
    for (double x : signal.table_values()) value.push_back(x);
    spec.insert("table", toml::table{{"t", std::move(t)},
                                     {"value", std::move(value)},
                                     {"interpolation", to_string(signal.interpolation())}});
  } else {
    spec.insert("offset", signal.offset());
    toml::array harmonics;
    for (const Harmonic& h : signal.harmonics())
      harmonics.push_back(toml::table{{"amplitude", h.amplitude},
                                      {"omega", h.omega},
                                      {"phase", h.phase},
                                      {"shape", h.cosine ? "cos" : "sin"}});
    spec.insert("harmonics", std::move(harmonics));
  }
  table.insert(key, std::move(spec));
}

std::string toml_text(const toml::table& root) {
  std::ostringstream os;
  os << toml::toml_formatter(root, toml::toml_formatter::default_flags & ~toml::format_flags::allow_literal_strings);
  return os.str() + "\n";
}

}  // namespace hinf::detail
