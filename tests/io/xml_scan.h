// A tiny, strict XML reader for tests: elements, attributes, character data, comments, CDATA, the
// five predefined entities and numeric character references. No namespaces or DTD processing (a
// DOCTYPE is skipped). Enough to check the XDMF files PoroSPH writes without an XML library.
#pragma once

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace porosph::test {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;  ///< character data directly inside this element, concatenated
  std::vector<XmlElement> children;

  /// The attribute's value, or `fallback` if absent.
  std::string attribute(const std::string& key, const std::string& fallback = "") const {
    auto it = attributes.find(key);
    return it == attributes.end() ? fallback : it->second;
  }
  bool has_attribute(const std::string& key) const { return attributes.count(key) > 0; }
  /// Direct children named `child_name`.
  std::vector<const XmlElement*> children_named(const std::string& child_name) const {
    std::vector<const XmlElement*> found;
    for (const XmlElement& child : children) {
      if (child.name == child_name) found.push_back(&child);
    }
    return found;
  }
};

namespace xml_detail {

class Scanner {
 public:
  explicit Scanner(const std::string& text) : text_(text) {}

  XmlElement document() {
    skip_misc();
    if (!starts_with("<")) fail("expected the root element");
    XmlElement root = element();
    skip_misc();
    if (pos_ != text_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML error at byte " + std::to_string(pos_) + ": " + what);
  }
  bool starts_with(const char* prefix) const {
    return text_.compare(pos_, std::strlen(prefix), prefix) == 0;
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  void skip_past(const char* terminator) {
    const std::size_t end = text_.find(terminator, pos_);
    if (end == std::string::npos) fail(std::string("missing '") + terminator + "'");
    pos_ = end + std::strlen(terminator);
  }
  /// Skips whitespace, the XML declaration, processing instructions, comments and a DOCTYPE.
  void skip_misc() {
    for (;;) {
      skip_space();
      if (starts_with("<?")) {
        skip_past("?>");
      } else if (starts_with("<!--")) {
        skip_past("-->");
      } else if (starts_with("<!DOCTYPE")) {
        const std::size_t bracket = text_.find('[', pos_);
        const std::size_t close = text_.find('>', pos_);
        if (bracket != std::string::npos && bracket < close) {
          pos_ = bracket;
          skip_past("]");
        }
        skip_past(">");
      } else {
        return;
      }
    }
  }
  std::string name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-' ||
            c == '.')) {
        break;
      }
      ++pos_;
    }
    if (pos_ == start) fail("expected a name");
    return text_.substr(start, pos_ - start);
  }
  std::string unescape(const std::string& raw) const {
    std::string out;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] != '&') {
        out += raw[i];
        continue;
      }
      const std::size_t semicolon = raw.find(';', i);
      if (semicolon == std::string::npos) fail("unterminated entity");
      const std::string entity = raw.substr(i + 1, semicolon - i - 1);
      if (entity == "amp")
        out += '&';
      else if (entity == "lt")
        out += '<';
      else if (entity == "gt")
        out += '>';
      else if (entity == "quot")
        out += '"';
      else if (entity == "apos")
        out += '\'';
      else if (entity.size() > 1 && entity[0] == '#') {
        const bool hex = entity[1] == 'x';
        const long code = std::strtol(entity.c_str() + (hex ? 2 : 1), nullptr, hex ? 16 : 10);
        if (code <= 0 || code > 127) fail("non-ASCII character reference &" + entity + ";");
        out += static_cast<char>(code);
      } else {
        fail("unknown entity &" + entity + ";");
      }
      i = semicolon;
    }
    return out;
  }
  XmlElement element() {
    ++pos_;  // '<'
    XmlElement node;
    node.name = name();
    for (;;) {
      skip_space();
      if (starts_with("/>")) {
        pos_ += 2;
        return node;
      }
      if (starts_with(">")) {
        ++pos_;
        break;
      }
      const std::string key = name();
      skip_space();
      if (!starts_with("=")) fail("expected '=' after attribute " + key);
      ++pos_;
      skip_space();
      if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\'')) {
        fail("expected a quoted value for attribute " + key);
      }
      const char quote = text_[pos_++];
      const std::size_t end = text_.find(quote, pos_);
      if (end == std::string::npos) fail("unterminated value of attribute " + key);
      const std::string raw = text_.substr(pos_, end - pos_);
      if (raw.find('<') != std::string::npos) fail("'<' in attribute " + key);
      if (!node.attributes.emplace(key, unescape(raw)).second) fail("duplicate attribute " + key);
      pos_ = end + 1;
    }
    for (;;) {  // content
      if (pos_ >= text_.size()) fail("unclosed element <" + node.name + ">");
      if (starts_with("</")) {
        pos_ += 2;
        const std::string closing = name();
        if (closing != node.name) fail("</" + closing + "> closes <" + node.name + ">");
        skip_space();
        if (!starts_with(">")) fail("expected '>'");
        ++pos_;
        return node;
      }
      if (starts_with("<!--")) {
        skip_past("-->");
      } else if (starts_with("<![CDATA[")) {
        const std::size_t start = pos_ + 9;
        skip_past("]]>");
        node.text += text_.substr(start, pos_ - 3 - start);
      } else if (starts_with("<")) {
        node.children.push_back(element());
      } else {
        const std::size_t end = text_.find('<', pos_);
        const std::size_t stop = end == std::string::npos ? text_.size() : end;
        node.text += unescape(text_.substr(pos_, stop - pos_));
        pos_ = stop;
      }
    }
  }

  const std::string& text_;
  std::size_t pos_ = 0;
};

}  // namespace xml_detail

/// Parses a whole XML document and returns its root element. Throws std::runtime_error (with the
/// byte offset) if the document is not well formed.
inline XmlElement parse_xml(const std::string& text) {
  return xml_detail::Scanner(text).document();
}

}  // namespace porosph::test
