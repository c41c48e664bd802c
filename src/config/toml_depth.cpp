#include "toml_depth.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <vector>

namespace capsubot::detail {
namespace {

// The scan of RequireTomlDepth: keys' dots, headers' dots and the brackets and braces of values,
// outside strings and comments. Tracks only what nests; the parser checks the rest of the
// syntax.
class TomlDepthScan {
 public:
  TomlDepthScan(const std::string& text, const std::string& path) : text_(text), path_(path) {}

  // Throws at the first place nested deeper than kMaxTomlDepth. Every step moves i_ forward.
  void Run() {
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '#') {
        while (i_ < text_.size() && text_[i_] != '\n') ++i_;
      } else if (c == '"' || c == '\'') {
        SkipString();
      } else if (c == '\n') {
        NewLine();
      } else if (at_key_ && open_.empty() && c == '[') {  // a [table] or [[array]] header
        Header();
      } else if (at_key_ && c == '}' && !open_.empty() && open_.back() == '{') {  // {} or {a=1,}
        Close();
        at_key_ = false;
        ++i_;
      } else if (at_key_) {
        KeyChar(c);
      } else {
        ValueChar(c);
      }
    }
  }

 private:
  void Check(int d) const {
    if (d > kMaxTomlDepth) {
      throw std::invalid_argument(fmt::format(
          "config file {} line {} is invalid: keys and values nested more than {} deep: "
          "expected at most {} levels (parts of dotted keys and table headers, nested arrays "
          "and inline tables)",
          path_, line_, kMaxTomlDepth, kMaxTomlDepth));
    }
  }

  int Context() const { return depth_.empty() ? header_ : depth_.back(); }

  // Moves past the string that starts at i_ (basic or literal, one line or several).
  void SkipString() {
    const std::size_t n = text_.size();
    const char quote = text_[i_];
    const bool multi = text_.compare(i_, 3, std::string(3, quote)) == 0;
    i_ += multi ? 3 : 1;
    while (i_ < n) {
      if (text_[i_] == '\n') ++line_;
      if (quote == '"' && text_[i_] == '\\') {
        i_ += 2;
        continue;
      }
      if (text_[i_] == quote && (!multi || text_.compare(i_, 3, std::string(3, quote)) == 0)) {
        i_ += multi ? 3 : 1;
        return;
      }
      if (text_[i_] == '\n' && !multi) return;
      ++i_;
    }
  }

  void NewLine() {
    ++line_;
    ++i_;
    if (open_.empty()) {
      at_key_ = true;
      parts_ = 1;
    }
  }

  // A [table] or [[array]] header: its dotted parts give the depth of the keys below it.
  void Header() {
    int header_parts = 1;
    for (++i_; i_ < text_.size() && text_[i_] != ']' && text_[i_] != '\n';) {
      if (text_[i_] == '"' || text_[i_] == '\'') {
        SkipString();
        continue;
      }
      if (text_[i_] == '.') Check(++header_parts);
      ++i_;
    }
    header_ = header_parts;
    while (i_ < text_.size() && text_[i_] == ']') ++i_;
  }

  void Close() {
    depth_.pop_back();
    open_.pop_back();
  }

  void KeyChar(char c) {
    if (c == '.') Check(Context() + ++parts_);
    if (c == '=') {
      at_key_ = false;
      value_depth_ = Context() + parts_;
      Check(value_depth_);
    }
    ++i_;
  }

  void ValueChar(char c) {
    if (c == '[' || c == '{') {
      const int d = (!open_.empty() && open_.back() == '[' ? depth_.back() : value_depth_) + 1;
      Check(d);
      depth_.push_back(d);
      open_.push_back(c);
      if (c == '{') {
        at_key_ = true;
        parts_ = 1;
      }
    } else if ((c == ']' || c == '}') && !open_.empty()) {
      Close();
    } else if (c == ',' && !open_.empty() && open_.back() == '{') {
      at_key_ = true;
      parts_ = 1;
    }
    ++i_;
  }

  const std::string& text_;
  const std::string& path_;
  std::size_t i_ = 0;
  int line_ = 1;
  int header_ = 0;          // parts of the last [table] header: the depth of the keys below it
  std::vector<int> depth_;  // depth of the elements of each open array or inline table
  std::vector<char> open_;  // '[' or '{' of each
  int value_depth_ = 0;     // depth of the value after the last '='
  bool at_key_ = true;      // reading a key: its dots separate its parts
  int parts_ = 1;
};

}  // namespace

void RequireTomlDepth(const std::string& text, const std::string& path) {
  TomlDepthScan(text, path).Run();
}

}  // namespace capsubot::detail
