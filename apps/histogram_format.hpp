#pragma once
// Histograms (key -> count maps; keys are integers, e.g. face sizes, or strings, e.g.
// element names) as the CLI prints them: JSON objects and one text line.
#include <nlohmann/json.hpp>

#include <string>
#include <type_traits>

namespace dualhex::app {

template <class Key>
std::string histogram_key(const Key& k) {
    if constexpr (std::is_same_v<Key, std::string>) return k;
    else return std::to_string(k);
}

/// {"3": 60, "4": 1236} (JSON keys are strings).
template <class Map>
nlohmann::json histogram_json(const Map& h) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, v] : h) j[histogram_key(k)] = v;
    return j;
}

/// "3: 60, 4: 1236", or "-" when empty.
template <class Map>
std::string histogram_text(const Map& h) {
    std::string s;
    for (const auto& [k, v] : h) {
        if (!s.empty()) s += ", ";
        s += histogram_key(k);
        s += ": ";
        s += std::to_string(v);
    }
    return s.empty() ? "-" : s;
}

}  // namespace dualhex::app
