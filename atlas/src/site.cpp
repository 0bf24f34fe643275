// The atlas as a static site: pages, index, assets.
#include "dualhex/atlas/site.hpp"

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace dualhex::atlas {
namespace fs = std::filesystem;
namespace {

std::string read_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SiteError("cannot read " + file.string());
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

void write_text(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw SiteError("cannot write " + file.string());
}

fs::path executable_directory() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe.parent_path();
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
    return s;
}

std::string html_escape(const std::string& s) {
    return replace_all(replace_all(replace_all(s, "&", "&amp;"), "<", "&lt;"), ">", "&gt;");
}

/// JSON safe inside <script>: "</" becomes "<\/" (the same string to a JSON parser).
std::string embeddable(const nlohmann::json& j) { return replace_all(j.dump(), "</", "<\\/"); }

void add_link(Page& page, const std::string& href, const std::string& text) {
    page.data["links"].push_back({{"href", href}, {"text", text}});
}

std::string index_html(const std::vector<Page>& pages, const std::string& page_template) {
    const std::map<std::string, std::string> headings = {{"element", "Elements"}, {"transition", "Strong transitions"},
                                                         {"weak", "Weak classes (three levels)"}, {"variant", "Crossing variants"}};
    std::ostringstream body;
    for (const auto* kind : {"element", "transition", "weak", "variant"}) {
        std::size_t n = 0;
        for (const auto& p : pages) n += p.data["kind"] == kind;
        body << "<h2>" << headings.at(kind) << " (<span data-count=\"" << kind << "\">" << n << "</span>)</h2>\n<ul>\n";
        for (const auto& p : pages)
            if (p.data["kind"] == kind)
                body << "<li><a href=\"" << p.id << ".html\">" << html_escape(p.data["title"]) << "</a> — "
                     << html_escape(p.data["summary"]) << "</li>\n";
        body << "</ul>\n";
    }
    std::string html = replace_all(page_template, "{{TITLE}}", "dualhex atlas");
    html = replace_all(html, "{{DATA}}", "null");
    return replace_all(html, "{{BODY}}", body.str());
}

}  // namespace

std::vector<Page> all_pages(const ElementLibrary& library) {
    std::vector<Page> pages = element_pages(library);
    for (auto* more : {&transition_pages, &weak_pages, &variant_pages})
        for (auto& p : (*more)(library)) pages.push_back(std::move(p));
    std::map<std::string, Page*> by_id;
    for (auto& p : pages) by_id[p.id] = &p;
    for (auto& p : pages) {  // back links: an element page lists the pages placing it
        if (p.data["kind"] == "element") continue;
        for (const auto& link : p.data["links"]) {
            const std::string href = link["href"];
            const std::string target = href.substr(0, href.size() - 5);  // minus ".html"
            if (by_id.count(target) && by_id[target]->data["kind"] == "element")
                add_link(*by_id[target], p.id + ".html", p.data["title"]);
        }
    }
    return pages;
}

void check_output_directory(const fs::path& dir, bool force) {
    std::error_code ec;
    if (!fs::exists(dir, ec)) return;
    if (!fs::is_directory(dir, ec)) throw SiteError(dir.string() + " exists and is not a directory");
    if (!force && !fs::is_empty(dir, ec))
        throw SiteError(dir.string() + " exists and is not empty (use --force to write into it)");
}

fs::path site_template_directory() {
    if (const char* env = std::getenv("DUALHEX_ATLAS_SITE"); env && *env) return env;
    const fs::path installed = executable_directory() / ".." / "share" / "dualhex" / "atlas";
    if (fs::exists(installed / "page.html")) return installed;
    return DUALHEX_ATLAS_SITE_DIR;
}

fs::path three_js_file() {
    if (const char* env = std::getenv("DUALHEX_THREE_JS"); env && *env) return env;
    return DUALHEX_ATLAS_THREE_JS;
}

nlohmann::json write_site(const std::vector<Page>& pages, const fs::path& dir, bool force) {
    check_output_directory(dir, force);
    const fs::path site = site_template_directory(), three = three_js_file();
    if (!fs::exists(three)) throw SiteError("three.js not found at " + three.string() + " (install Debian libjs-three)");
    const std::string page_template = read_text(site / "page.html");  // read all before writing anything
    const std::string js = read_text(site / "atlas.js"), css = read_text(site / "atlas.css"), three_js = read_text(three);
    fs::create_directories(dir / "assets");
    write_text(dir / "assets" / "atlas.js", js);
    write_text(dir / "assets" / "atlas.css", css);
    write_text(dir / "assets" / "three.min.js", three_js);
    nlohmann::json summary = {{"pages", nlohmann::json::array()}};
    for (const auto& p : pages) {
        std::string html = replace_all(page_template, "{{TITLE}}", html_escape(p.data["title"]));
        html = replace_all(html, "{{BODY}}", "");
        write_text(dir / (p.id + ".html"), replace_all(html, "{{DATA}}", embeddable(p.data)));
        summary["pages"].push_back({{"id", p.id}, {"kind", p.data["kind"]}, {"title", p.data["title"]},
                                    {"tables", p.data["tables"]}, {"cells", p.data["scene"]["cells"].size()},
                                    {"dual_hexes", p.data["scene"]["dual"]["hexes"].size()}});
    }
    write_text(dir / "index.html", index_html(pages, page_template));
    write_text(dir / "atlas.json", summary.dump(1));
    return summary;
}

}  // namespace dualhex::atlas
