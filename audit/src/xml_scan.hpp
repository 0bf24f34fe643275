#pragma once
// Just enough XML for VTK's .vtu files: tags with attributes, in document order, and the
// text between a tag and its closing tag. No entities, no namespaces, no DTD.
#include <map>
#include <string>
#include <string_view>

namespace dualhex::audit::detail {

struct XmlTag {
    std::string name;                          ///< without '/'
    std::map<std::string, std::string> attrs;
    bool closing = false;                      ///< </name>
    bool self_closing = false;                 ///< <name ... />
    std::size_t begin = 0, end = 0;            ///< '<' and one past '>'
};

class XmlScanner {
public:
    XmlScanner(std::string path, std::string_view text) : path_(std::move(path)), text_(text) {}
    /// The next tag (skipping <?..?>, <!--..-->, text); false at the end of the text.
    bool next(XmlTag& tag);
    /// The text from `open.end` to the matching "</name>" (no nesting of the same name);
    /// moves past the closing tag. InputError if there is none.
    std::string_view content(const XmlTag& open);
    /// 1-based line of a position.
    [[nodiscard]] int line_of(std::size_t pos) const;
    [[noreturn]] void fail(std::size_t pos, const std::string& message) const;
    [[nodiscard]] const std::string& path() const { return path_; }

private:
    std::string path_;
    std::string_view text_;
    std::size_t pos_ = 0;
};

}  // namespace dualhex::audit::detail
