#pragma once
// CanonicalSummary as JSON and back (the distributed executable's output, the tests'
// comparison). Hashes are 16-digit hex strings: JSON numbers above 2^53 lose digits.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "dualhex/distributed/canonical.hpp"

namespace dualhex {

inline std::string hash_hex(std::uint64_t h) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

inline nlohmann::json to_json(const CanonicalSummary& s) {
    nlohmann::json faces = nlohmann::json::object(), elements = nlohmann::json::object();
    for (const auto& [k, n] : s.face_sizes) faces[std::to_string(k)] = n;
    for (const auto& [k, n] : s.elements) elements[k] = n;
    return {{"leaves", s.leaves},       {"cells", s.cells},   {"non_hex_cells", s.non_hex_cells},
            {"vertices", s.vertices},   {"hexes", s.hexes},   {"non_cube_vertices", s.non_cube_vertices},
            {"face_sizes", faces},      {"elements", elements}, {"cell_hash", hash_hex(s.cell_hash)},
            {"hex_hash", hash_hex(s.hex_hash)}};
}

inline CanonicalSummary summary_from_json(const nlohmann::json& j) {
    CanonicalSummary s;
    s.leaves = j.at("leaves");
    s.cells = j.at("cells");
    s.non_hex_cells = j.at("non_hex_cells");
    s.vertices = j.at("vertices");
    s.hexes = j.at("hexes");
    s.non_cube_vertices = j.at("non_cube_vertices");
    for (const auto& [k, n] : j.at("face_sizes").items()) s.face_sizes[std::stoi(k)] = n;
    for (const auto& [k, n] : j.at("elements").items()) s.elements[k] = n;
    s.cell_hash = std::stoull(j.at("cell_hash").get<std::string>(), nullptr, 16);
    s.hex_hash = std::stoull(j.at("hex_hash").get<std::string>(), nullptr, 16);
    return s;
}

}  // namespace dualhex
