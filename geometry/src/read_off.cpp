// Strict OFF reader: "OFF" (vertex lines exactly "x y z"; COFF/NOFF/CNOFF and the ST
// variants add colour, normal or texture numbers after x y z, checked and ignored; 4OFF,
// nOFF and binary OFF are refused), the counts "V F E", V vertex lines, F face lines
// "n i1 .. in [colour numbers]". '#' comments and blank lines anywhere. Counts are checked
// against the bytes left before anything is reserved; nothing but comments may follow.
#include "surface_parse.hpp"

namespace dualhex::geometry::detail {

namespace {

bool is_off_keyword(std::string_view word) {
    return word == "OFF" || word == "COFF" || word == "NOFF" || word == "CNOFF" || word == "STOFF" ||
           word == "STCOFF" || word == "STNOFF" || word == "STCNOFF";
}

// Reads "V F E" from `fields` (the rest of the header line, or the next content line).
void read_counts(const std::vector<std::string_view>& f, const LineCursor& cur, std::int64_t& nv, std::int64_t& nf) {
    if (f.size() < 2 || f.size() > 3)
        cur.fail("expected the counts 'vertices faces edges', found " + std::to_string(f.size()) + " fields");
    nv = parse_integer(f[0], cur, "vertex count");
    nf = parse_integer(f[1], cur, "face count");
    if (f.size() == 3) (void)parse_integer(f[2], cur, "edge count");
    if (nv < 0 || nf < 0) cur.fail("negative count, " + quoted(nv < 0 ? f[0] : f[1]));
    // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line at least 8 ("3 0 1 2\n").
    const auto left = static_cast<std::int64_t>(cur.remaining());
    if (nv > left / 6) cur.fail("vertex count " + std::to_string(nv) + " exceeds what the file can hold");
    if (nf > (left - 6 * nv) / 8) cur.fail("face count " + std::to_string(nf) + " exceeds what the file can hold");
}

}  // namespace

PolygonSoup read_off(std::string_view bytes, const std::string& source) {
    LineCursor cur(bytes, source);
    std::string_view line;
    if (!cur.next_content(line)) cur.fail("empty file (expected 'OFF')");
    auto fields = split_fields(line);
    if (!is_off_keyword(fields[0])) cur.fail("expected 'OFF', found " + quoted(fields[0]));
    if (fields.size() > 1 && fields[1] == "BINARY") cur.fail("binary OFF is not supported");
    const bool extra_vertex_values = fields[0] != "OFF";
    fields.erase(fields.begin());
    if (fields.empty()) {
        if (!cur.next_content(line)) cur.fail("missing the counts 'vertices faces edges'");
        fields = split_fields(line);
    }
    std::int64_t nv = 0, nf = 0;
    read_counts(fields, cur, nv, nf);

    PolygonSoup soup;
    soup.points.reserve(static_cast<std::size_t>(nv));
    for (std::int64_t v = 0; v < nv; ++v) {
        if (!cur.next_content(line))
            cur.fail("file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
        fields = split_fields(line);
        if (fields.size() < 3 || (!extra_vertex_values && fields.size() > 3))
            cur.fail("vertex " + std::to_string(v) + ": expected 'x y z', found " + quoted(line));
        Eigen::Vector3d p;
        for (int c = 0; c < 3; ++c) p[c] = parse_coordinate(fields[static_cast<std::size_t>(c)], cur, "coordinate");
        for (std::size_t c = 3; c < fields.size(); ++c) check_number(fields[c], cur, "extra vertex value");
        soup.points.push_back(p);
    }
    std::vector<std::int64_t> ids;
    for (std::int64_t f = 0; f < nf; ++f) {
        if (!cur.next_content(line))
            cur.fail("file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
        fields = split_fields(line);
        const std::int64_t n = parse_integer(fields[0], cur, "face size");
        if (n < 3 || n > static_cast<std::int64_t>(fields.size()) - 1)
            cur.fail("face " + std::to_string(f) + ": size " + std::to_string(n) + " does not match the line " +
                     quoted(line));
        ids.assign(static_cast<std::size_t>(n), 0);
        for (std::int64_t c = 0; c < n; ++c)
            ids[static_cast<std::size_t>(c)] = parse_integer(fields[static_cast<std::size_t>(c + 1)], cur, "vertex index");
        for (std::size_t c = static_cast<std::size_t>(n) + 1; c < fields.size(); ++c)
            check_number(fields[c], cur, "face colour");
        add_polygon(soup, ids, [&](const std::string& m) { cur.fail("face " + std::to_string(f) + ": " + m); });
    }
    if (cur.next_content(line)) cur.fail("unexpected content after the last face, " + quoted(line));
    return soup;
}

}  // namespace dualhex::geometry::detail
