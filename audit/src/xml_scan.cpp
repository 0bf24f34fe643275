#include "xml_scan.hpp"

#include <algorithm>
#include <cctype>

#include "dualhex/grid/input_error.hpp"

namespace dualhex::audit::detail {

int XmlScanner::line_of(std::size_t pos) const {
    pos = std::min(pos, text_.size());
    return 1 + static_cast<int>(std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
}

void XmlScanner::fail(std::size_t pos, const std::string& message) const {
    throw InputError(path_, line_of(pos), message);
}

bool XmlScanner::next(XmlTag& tag) {
    for (;;) {
        const std::size_t lt = text_.find('<', pos_);
        if (lt == std::string_view::npos) return false;
        if (text_.compare(lt, 4, "<!--") == 0) {
            const std::size_t e = text_.find("-->", lt + 4);
            if (e == std::string_view::npos) fail(lt, "unterminated comment");
            pos_ = e + 3;
            continue;
        }
        if (text_.compare(lt, 2, "<?") == 0) {
            const std::size_t e = text_.find("?>", lt + 2);
            if (e == std::string_view::npos) fail(lt, "unterminated <?");
            pos_ = e + 2;
            continue;
        }
        const std::size_t gt = text_.find('>', lt);
        if (gt == std::string_view::npos) fail(lt, "unterminated tag");
        tag = XmlTag{};
        tag.begin = lt;
        tag.end = gt + 1;
        std::string_view body = text_.substr(lt + 1, gt - lt - 1);
        if (!body.empty() && body.front() == '/') {
            tag.closing = true;
            body.remove_prefix(1);
        }
        if (!body.empty() && body.back() == '/') {
            tag.self_closing = true;
            body.remove_suffix(1);
        }
        std::size_t i = 0;
        while (i < body.size() && !std::isspace(static_cast<unsigned char>(body[i]))) ++i;
        tag.name = std::string(body.substr(0, i));
        if (tag.name.empty()) fail(lt, "empty tag name");
        while (i < body.size()) {
            while (i < body.size() && std::isspace(static_cast<unsigned char>(body[i]))) ++i;
            if (i >= body.size()) break;
            const std::size_t eq = body.find('=', i);
            if (eq == std::string_view::npos || eq + 1 >= body.size() || (body[eq + 1] != '"' && body[eq + 1] != '\''))
                fail(lt, "malformed attribute in <" + tag.name + ">");
            const char q = body[eq + 1];
            const std::size_t close = body.find(q, eq + 2);
            if (close == std::string_view::npos) fail(lt, "unterminated attribute value in <" + tag.name + ">");
            std::string key(body.substr(i, eq - i));
            while (!key.empty() && std::isspace(static_cast<unsigned char>(key.back()))) key.pop_back();
            tag.attrs[key] = std::string(body.substr(eq + 2, close - eq - 2));
            i = close + 1;
        }
        pos_ = tag.end;
        return true;
    }
}

std::string_view XmlScanner::content(const XmlTag& open) {
    if (open.self_closing) return {};
    const std::string closing = "</" + open.name;
    const std::size_t e = text_.find(closing, open.end);
    if (e == std::string_view::npos) fail(open.begin, "<" + open.name + "> is never closed (truncated file?)");
    const std::size_t gt = text_.find('>', e);
    if (gt == std::string_view::npos) fail(e, "unterminated closing tag");
    pos_ = gt + 1;
    return text_.substr(open.end, e - open.end);
}

}  // namespace dualhex::audit::detail
