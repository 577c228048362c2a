// JSON for summary.json and the check records: quoting of strings and a strict validator
// (RFC 8259) that every JSON file passes before it is published. FreeFEM prints a non-finite real
// as inf, -inf or nan, which is not JSON: the validator names the key whose value it is, so a run
// whose figures overflowed fails instead of leaving a file no reader can parse.
#pragma once
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace sma::json {

// `text` as a JSON string literal: quotes, backslashes and control characters escaped; other
// bytes (UTF-8 included) as they are.
inline std::string quote(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += (char)c;
        }
    }
  }
  return out + "\"";
}

// A recursive-descent check of one JSON document. error() is empty when the text is valid, else
// it says where (line, the enclosing key) and what.
class Validator {
 public:
  explicit Validator(const std::string& text) : s_(text) {
    skip();
    if (value(0)) {
      skip();
      if (i_ != s_.size()) fail("text after the end of the document");
    }
  }
  const std::string& error() const { return error_; }

 private:
  const std::string& s_;
  std::size_t i_ = 0;
  std::string key_ = "(top level)";
  std::string error_;

  bool fail(const std::string& what) {
    if (error_.empty()) {
      std::size_t line = 1;
      for (std::size_t k = 0; k < i_ && k < s_.size(); ++k) line += s_[k] == '\n';
      error_ = "line " + std::to_string(line) + ", at key \"" + key_ + "\": " + what;
    }
    return false;
  }
  void skip() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\t')) ++i_;
  }
  bool literal(const char* word) {
    const std::string w(word);
    if (s_.compare(i_, w.size(), w) != 0) return false;
    i_ += w.size();
    return true;
  }
  // The token at i_ (up to a delimiter), for messages.
  std::string token() const {
    std::size_t j = i_;
    while (j < s_.size() && j - i_ < 24 && std::string(",]}\n\r\t ").find(s_[j]) == std::string::npos) ++j;
    return s_.substr(i_, j - i_);
  }
  bool value(int depth) {
    if (depth > 64) return fail("nested too deep");
    if (i_ >= s_.size()) return fail("unexpected end of the text");
    const char c = s_[i_];
    if (c == '{') return object(depth);
    if (c == '[') return array(depth);
    if (c == '"') {
      std::string ignored;
      return string(ignored);
    }
    const std::string t = token();
    if (t == "inf" || t == "-inf" || t == "nan" || t == "-nan" || t == "Infinity" || t == "-Infinity" || t == "NaN")
      return fail("the value is not a finite number (" + t + ")");
    if (c == '-' || (c >= '0' && c <= '9')) return number();
    if (literal("true") || literal("false") || literal("null")) return true;
    return fail("not a JSON value: '" + t + "'");
  }
  bool object(int depth) {
    ++i_;
    skip();
    if (i_ < s_.size() && s_[i_] == '}') return ++i_, true;
    const std::string outer = key_;
    for (;;) {
      skip();
      if (i_ >= s_.size() || s_[i_] != '"') return fail("expected a key in quotes, found '" + token() + "'");
      std::string k;
      if (!string(k)) return false;
      key_ = k;
      skip();
      if (i_ >= s_.size() || s_[i_] != ':') return fail("expected ':' after the key");
      ++i_;
      skip();
      if (!value(depth + 1)) return false;
      skip();
      if (i_ < s_.size() && s_[i_] == ',') { ++i_; continue; }
      if (i_ < s_.size() && s_[i_] == '}') { ++i_; key_ = outer; return true; }
      return fail("expected ',' or '}' after the value, found '" + token() + "'");
    }
  }
  bool array(int depth) {
    ++i_;
    skip();
    if (i_ < s_.size() && s_[i_] == ']') return ++i_, true;
    for (;;) {
      skip();
      if (!value(depth + 1)) return false;
      skip();
      if (i_ < s_.size() && s_[i_] == ',') { ++i_; continue; }
      if (i_ < s_.size() && s_[i_] == ']') return ++i_, true;
      return fail("expected ',' or ']' in the array, found '" + token() + "'");
    }
  }
  bool string(std::string& out) {
    ++i_;
    while (i_ < s_.size()) {
      const unsigned char c = s_[i_];
      if (c == '"') return ++i_, true;
      if (c < 0x20) return fail("a control character inside a string (an unescaped quote or newline?)");
      if (c == '\\') {
        if (i_ + 1 >= s_.size()) break;
        const char e = s_[i_ + 1];
        if (e == 'u') {
          for (int k = 2; k < 6; ++k)
            if (i_ + k >= s_.size() || !std::isxdigit((unsigned char)s_[i_ + k])) return fail("a bad \\u escape");
          i_ += 6;
          continue;
        }
        if (std::string("\"\\/bfnrt").find(e) == std::string::npos) return fail(std::string("a bad escape \\") + e);
        out += e;
        i_ += 2;
        continue;
      }
      out += (char)c;
      ++i_;
    }
    return fail("a string that does not end");
  }
  bool digits() {
    const std::size_t start = i_;
    while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
    return i_ > start;
  }
  bool number() {
    const std::size_t start = i_;
    if (s_[i_] == '-') ++i_;
    if (i_ < s_.size() && s_[i_] == '0') ++i_;
    else if (!digits()) return i_ = start, fail("not a number: '" + token() + "'");
    if (i_ < s_.size() && s_[i_] == '.') {
      ++i_;
      if (!digits()) return i_ = start, fail("not a number: '" + token() + "'");
    }
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      ++i_;
      if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
      if (!digits()) return i_ = start, fail("not a number: '" + token() + "'");
    }
    const double v = std::strtod(s_.substr(start, i_ - start).c_str(), nullptr);
    if (!std::isfinite(v)) {
      const std::size_t end = i_;
      i_ = start;
      const std::string t = s_.substr(start, end - start);
      return fail("the value is not a finite number (" + t + " overflows a double)");
    }
    return true;
  }
};

// Empty when `text` is one valid JSON document with finite numbers, else what is wrong and where.
inline std::string validate(const std::string& text) { return Validator(text).error(); }

}  // namespace sma::json
